"""A section per experiment of data/experiments/: its report into docs/results.md."""
from __future__ import annotations

import re
import shutil
from pathlib import Path

from .project import ACOBENCH, IMAGES, RESULTS, ROOT
from .run import Run
from .sections import section


# The report's plots that go beside an experiment's tables (file names in build/results/NAME/plots/).
def chosen_plots(name: str, plots: list[str]) -> list[str]:
    def first(prefix: str, count: int) -> list[str]:
        return [p for p in plots if p.startswith(prefix)][:count]
    if name in ("movingai", "generated", "terrain", "anytime"):
        return first("ecdf-", 2)  # hundreds of problems: the fixed-target ECDFs over all of them
    if name == "dwa":
        return first("box-", 2) + first("ablation", 1)
    if name == "ablation":
        return first("box-", 1) + first("convergence-", 1) + first("ablation", 1)
    return first("box-", 3) + first("convergence-", 1)


def experiment(name: str):
    def make(run: Run):
        db = Path("build/results") / f"{name}.db"
        out = Path("build/results") / name
        db.parent.mkdir(parents=True, exist_ok=True)
        ran = run.tool(ACOBENCH, "run", f"data/experiments/{name}.yaml", "--db", db)
        # A resumed database keeps the trials an earlier run measured, on its machine and load.
        resumed = re.search(r"(\d+) trials, (\d+) already in", ran)
        if resumed and int(resumed[2]) > 0:
            run.note = (f" ({resumed[2]} of the {resumed[1]} trials were stored by an earlier run of the section; "
                        f"delete {db} to measure them all again)")
        if (out / "plots").exists():
            shutil.rmtree(out / "plots")
        run.tool(ACOBENCH, "report", db, "--out", out)
        report = (ROOT / out / "report.md").read_text()
        keep = {"movingai": ("Summary by problem set", "Gap by difficulty bucket"),
                "terrain": ("Summary by problem set", "Gap by difficulty bucket"),
                "generated": ("Summary by problem set", "Gap by difficulty bucket"),
                "dwa": ("Simulations", "Ablation path"),
                "anytime": ("Summary by problem set", "Does the pheromone matter?")}.get(name)
        parts = re.split(r"^(?=## )", report, flags=re.M)[1:]
        if keep:
            parts = [p for p in parts if p.removeprefix("## ").startswith(keep)]
        ours = re.sub(r"^## ", "#### ", "".join(parts), flags=re.M)
        images = ROOT / IMAGES / "results" / name
        if images.exists():
            shutil.rmtree(images)
        images.mkdir(parents=True)
        plots = sorted(p.name for p in (ROOT / out / "plots").glob("*.svg"))
        pictures = []
        for plot in chosen_plots(name, plots):
            shutil.copy(ROOT / out / "plots" / plot, images / plot)
            title = re.search(r"<text class=\"title\"[^>]*>([^<]*)<", (images / plot).read_text())
            alt = title[1] if title else plot
            pictures.append(f"![{alt}](images/results/{name}/{plot})")
        text = ((ROOT / f"data/experiments/{name}.md").read_text().strip() + "\n\n"
                + f"Ours (`acobench run data/experiments/{name}.yaml`):\n\n" + run.stamp() + "\n\n"
                + ("\n".join(pictures) + "\n\n" if pictures else "") + ours)
        return {(RESULTS, name): text}
    return make


EXPERIMENTS = {  # on the shared 2-core machine, with a fresh database
    "paper000": "30 s", "paper001": "10 s", "paper002": "10 s", "paper003": "30 s", "paper004": "15 s",
    "ablation": "3.5 min", "movingai": "15-30 min", "terrain": "1-2 min", "generated": "2-4 min", "dwa": "6 min",
    "anytime": "10-15 min",
}
for _name, _estimate in EXPERIMENTS.items():
    section(_name, _estimate, f"data/experiments/{_name}.yaml into docs/results.md, with its report's plots",
            [(RESULTS, _name)])(experiment(_name))

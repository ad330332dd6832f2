"""tools/figures.sh's command line: `python3 -m figures [SECTION ...] | --list | --help`."""
from __future__ import annotations

import os
import sys
import time

import figures
from .project import ROOT, FiguresError
from .regions import find_region, replace_regions
from .run import Run, load_average
from .sections import SECTIONS, Section


def run_section(s: Section) -> None:
    run = Run(s.name, load_start=load_average(), started=time.monotonic())
    bodies = s.make(run)
    stamp = run.short_stamp()  # before any file changes, which would read as uncommitted changes
    for (file, region), body in bodies.items():
        path = ROOT / file
        path.write_text(replace_regions(path.read_text(), {region: body}, s.name, str(file), stamp))
    print(f"[{s.name}] done in {run.elapsed()}: {', '.join(sorted({str(f) for f, _ in bodies}))}", file=sys.stderr)


def main(argv: list[str]) -> int:
    if argv[:1] in (["-h"], ["--help"]):
        print(figures.__doc__.strip() + "\n\nUsage: tools/figures.sh [SECTION ...] | --list   (no section: every one)")
        return 0
    if argv[:1] == ["--list"]:
        for s in SECTIONS.values():
            print(f"{s.name:17} {s.estimate:>13}  {s.summary}")
        return 0
    names = argv or list(SECTIONS)
    unknown = [n for n in names if n not in SECTIONS]
    if unknown:
        raise FiguresError(f"unknown section {', '.join(unknown)} (sections: {', '.join(SECTIONS)}; --list says more)")
    # Every region must be there before anything runs: an hour of experiments should not end in a
    # missing marker.
    for n in names:
        for file, region in SECTIONS[n].regions:
            find_region((ROOT / file).read_text(), region, n, str(file))
    for n in names:
        run_section(SECTIONS[n])
    return 0


if __name__ == "__main__":
    os.chdir(ROOT)
    try:
        sys.exit(main(sys.argv[1:]))
    except FiguresError as e:
        print(f"figures: error: {e}", file=sys.stderr)
        sys.exit(1)

"""The example notebook, examples/python/planning.ipynb, runs (Debian's python3-nbclient) and shows
what it says; its stored outputs, there for readers on GitHub, are a fresh run's.

After changing the notebook, store its outputs again:
    PYTHONPATH=build/release/python /usr/bin/python3 python/tests/test_notebook.py
"""
import base64
import copy
import pathlib
import sys

import nbformat
from nbclient import NotebookClient

NOTEBOOK = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "planning.ipynb"


def executed(notebook):
    """The notebook run from its own folder, as Jupyter runs it."""
    notebook = copy.deepcopy(notebook)
    NotebookClient(notebook, timeout=300, kernel_name="python3", record_timing=False,
                   resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()
    return notebook


def by_tag(notebook):
    return {tag: cell for cell in notebook.cells for tag in cell.metadata.get("tags", [])}


def printed(cell):
    """What the cell printed (not stderr, where a fresh machine's matplotlib says it builds its font cache)."""
    return "".join(output.text for output in cell.outputs if output.output_type == "stream" and output.name == "stdout")


def picture(cell, kind):
    pictures = [output.data[kind] for output in cell.outputs if kind in output.get("data", {})]
    assert len(pictures) == 1, f"cell {cell.metadata.tags}: {len(pictures)} {kind} outputs"
    return pictures[0]


def test_the_notebook_runs_and_shows_its_runs():
    import aco

    stored = nbformat.read(NOTEBOOK, as_version=4)
    cells = by_tag(executed(stored))
    assert picture(cells["map"], "image/svg+xml").startswith("<svg")
    run = picture(cells["run"], "image/svg+xml")
    assert 'id="grid-path"' in run and 'class="best-so-far"' in run
    assert base64.b64decode(picture(cells["plot"], "image/png"))[:8] == b"\x89PNG\r\n\x1a\n"
    assert 'id="unknown"' in picture(cells["simulation"], "image/svg+xml")

    # The printed numbers are those of the same runs made here.
    grid = aco.Map.load(NOTEBOOK.parent / "../../data/maps/classic20/map1.txt")
    result = aco.plan(grid, (0, 0), (19, 19), seed=1)
    length, segments = printed(cells["length"]).splitlines()
    assert length == f"length {result.length:.4f}, optimum {result.optimal_length:.4f}"
    assert segments == f"segments {result.length:.4f}"
    terrain = aco.Map.load(NOTEBOOK.parent / "../../data/terrain/epf20.asc")
    goal_x = aco.plan(terrain, (0, 10), (19, 8), seed=1).path[-1, 0]
    assert printed(cells["plot"]) == f"cell size 10.0, goal at x = {goal_x:.1f}\n"
    assert goal_x == 19 * 10.0  # world units, not cells
    table = [line.split() for line in printed(cells["comparison"]).splitlines()]
    assert [row[0] for row in table] == ["ant_system", "max_min", "acs"] and all(len(row) == 4 for row in table)
    first = aco.plan(grid, (0, 0), (19, 19), preset="paper001", update="ant_system", iterations=10, seed=1)
    assert table[0][1] == f"{first.gap_percent:.2f}"

    # What GitHub shows is what the notebook prints now, pictures included.
    stored_cells = by_tag(stored)
    for tag, cell in cells.items():
        assert printed(stored_cells[tag]) == printed(cell), f"cell {tag}: stored outputs are stale ({__doc__})"
    for tag, kind in (("map", "image/svg+xml"), ("run", "image/svg+xml"), ("plot", "image/png")):
        picture(stored_cells[tag], kind)


if __name__ == "__main__":
    nbformat.write(executed(nbformat.read(NOTEBOOK, as_version=4)), NOTEBOOK)
    print(f"stored the outputs of {NOTEBOOK}", file=sys.stderr)

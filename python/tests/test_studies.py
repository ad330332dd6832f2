"""aco.run_experiment(), aco.read_database() and aco.stats against acobench's own run and report."""
import csv
import math
import sqlite3
import subprocess

import numpy as np
import pytest

import aco
from conftest import MAP1

EXPERIMENT = f"""name: python
seed: 3
repetitions: 6
problems:
  - {{name: down, map: {MAP1}, start: [0, 0], goal: [19, 19]}}
  - {{name: up, map: {MAP1}, start: [0, 19], goal: [19, 0]}}
settings: {{preset: ant-system, ants: 10, iterations: 15}}
baseline: {{name: ant system}}
configurations:
  - {{name: max-min, update: max_min}}
"""


@pytest.fixture(scope="module")
def database(tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    (folder / "python.yaml").write_text(EXPERIMENT)
    seen = []
    summary = aco.run_experiment(folder / "python.yaml", folder / "python.db", threads=2,
                                 progress=lambda done, total: seen.append((done, total)))
    assert summary["trials"] == summary["ran"] == 24 and not summary["failures"]
    assert summary["failures_by_reason"] == {} and summary["same_runs"] == []
    assert seen[-1] == (24, 24) and {done for done, _ in seen} >= set(range(1, 25))  # after every stored trial
    return folder / "python.db"


def test_running_again_continues_the_database(database):
    again = aco.run_experiment(database.parent / "python.yaml", database, progress=False)
    assert again["skipped"] == 24 and again["ran"] == 0


def test_the_dataframe_is_the_reports_csv_row_for_row(database, build):
    out = database.parent / "report"
    subprocess.run([str(build / "hosts" / "acobench" / "acobench"), "report", str(database), "--out", str(out)],
                   check=True, capture_output=True)
    with open(out / "runs.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    frame = aco.read_database(database)
    assert len(frame) == len(rows) == 24
    assert (frame["peak_memory_mib"] > 0).all()  # this process's peak so far: the trials ran in it
    assert list(frame.columns[:len(rows[0])]) == list(rows[0])
    for (_, mine), theirs in zip(frame.iterrows(), rows):
        for column, text in theirs.items():
            value = mine[column]
            if text == "":
                assert isinstance(value, float) and math.isnan(value), column
            elif column in ("problem", "configuration", "stopped_by"):
                assert value == text, column
            elif column == "solved":
                assert bool(value) == (text == "1")
            else:  # the CSV's numbers are rounded (10 or 6 significant digits)
                assert float(value) == pytest.approx(float(text), rel=1e-5, abs=1e-6), column


def test_every_trial_field_python_shows_is_a_column(database):
    with sqlite3.connect(database) as db:
        runs_columns = {row[1] for row in db.execute("PRAGMA table_info(runs)")}
    frame = aco.read_database(database)
    for field in aco._aco.trial_fields():
        assert (field["column"] in frame.columns) == field["in_python"], field
        # A column added when used is there once a trial has a value for it: this planning study on
        # flat grids, where no trial failed, has optimal_corridor, not failure or the simulation measures.
        stored = field["stored_as"] in runs_columns
        if field["when_used"]:
            assert stored == (field["stored_as"] == "optimal_corridor"), field
        else:
            assert stored == field["in_runs_table"], field


def test_configuration_columns_group_the_runs(database):
    frame = aco.read_database(database)
    assert set(frame["config.update"]) == {"ant_system", "max_min"}
    assert (frame.groupby("configuration")["config.update"].nunique() == 1).all()
    assert frame["optimal_length"].notna().all()


def test_the_reports_statistics_on_dataframes(database):
    frame = aco.read_database(database)
    table = aco.stats.summary(frame, "length")
    assert len(table) == 4 and (table["runs"] == 6).all()
    group = frame[(frame["configuration"] == "max-min") & (frame["problem"] == frame["problem"].iloc[0]) & frame["solved"]]
    row = table.loc[(frame["problem"].iloc[0], "max-min")]
    assert row["mean"] == pytest.approx(group["length"].mean())
    assert row["sd"] == pytest.approx(group["length"].std(ddof=1))
    compared = aco.stats.compare(frame, baseline="ant system")
    assert len(compared) == 2 and set(compared["configuration"]) == {"max-min"}
    assert ((compared["p_holm"] >= compared["p"]) & (compared["p_holm"] <= 1)).all()


def test_the_statistics_on_samples():
    # Exact Mann-Whitney (no ties, n <= 8): U = 0 for fully separated samples of 3 and 3: p = 2/20.
    test = aco.stats.mann_whitney_u([1, 2, 3], [4, 5, 6])
    assert test["u"] == 0 and test["exact"] and test["p"] == pytest.approx(0.1)
    assert aco.stats.vargha_delaney_a12([1, 2, 3], [4, 5, 6]) == 0.0
    assert aco.stats.effect_size(0.5) == "negligible" and aco.stats.effect_size(0.9) == "large"
    assert aco.stats.holm_adjust([0.01, 0.04, 0.03]) == pytest.approx([0.03, 0.06, 0.06])
    assert aco.stats.average_ranks([[1, 1], [2, 3]]) == [1.0, 2.0]
    assert aco.stats.ecdf([1.0, 3.0, math.inf], [0.0, 2.0, 5.0]) == pytest.approx([0, 1 / 3, 2 / 3])
    summary = aco.stats.summarize(np.arange(10.0))
    assert summary["n"] == 10 and summary["median"] == 4.5 and summary["sd"] == pytest.approx(np.std(np.arange(10.0), ddof=1))


def test_a_bad_experiment_raises_with_acobenchs_message(tmp_path):
    (tmp_path / "bad.yaml").write_text("name: bad\nproblems: []\n")
    with pytest.raises(aco.Error):
        aco.run_experiment(tmp_path / "bad.yaml", tmp_path / "bad.db", progress=False)
    with pytest.raises(aco.Error, match="no such results database"):
        aco.read_database(tmp_path / "none.db")

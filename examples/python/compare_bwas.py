"""Runs bwas_study.yaml (the Python Best-Worst Ant System against MAX-MIN) and analyses the
database in pandas: mean length and success per map and configuration, then the report's test.

    PYTHONPATH=build/release/python python3 examples/python/compare_bwas.py bwas.db
"""
import pathlib
import sys

import aco

here = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(here))  # the study's update.class imports bwas from this folder
database = sys.argv[1] if len(sys.argv) > 1 else "bwas.db"

summary = aco.run_experiment(here / "bwas_study.yaml", database)
print(f"ran {summary['ran']} trials, {len(summary['failures'])} failed")

runs = aco.read_database(database)
table = runs.groupby(["problem", "configuration"]).agg(success=("solved", "mean"), mean_length=("length", "mean"),
                                                       mean_gap_percent=("gap_percent", "mean"))
print(table.round(3).to_string())
print(aco.stats.compare(runs, baseline="max-min").round(4).to_string(index=False))

"""The report's statistics (acobench report) as functions: on samples, and on the DataFrames of
aco.read_database().

The tests are the report's own code (C++, aco/studies/statistics.hpp): Mann-Whitney U as SciPy's
mannwhitneyu(method="auto"), Holm-Bonferroni, Vargha-Delaney A12 with its effect labels,
Friedman average ranks, and the anytime measures (ECDF of hitting times, expected running time).
"""
from __future__ import annotations

from typing import Iterable, Sequence

from . import _aco


def summarize(sample: Iterable[float]) -> dict:
    """n, mean, sd (n - 1), median, q1, q3, iqr (type 7 quantiles), 95 % CI of the mean, min, max."""
    return _aco.summarize([float(v) for v in sample])


def mann_whitney_u(first: Iterable[float], second: Iterable[float]) -> dict:
    """Two-sided Mann-Whitney U test: {"u": U of the first sample, "p": p value, "exact": bool}."""
    return _aco.mann_whitney_u([float(v) for v in first], [float(v) for v in second])


def holm_adjust(p_values: Iterable[float]) -> list:
    """Holm-Bonferroni adjusted p values, in the input order."""
    return _aco.holm_adjust([float(p) for p in p_values])


def vargha_delaney_a12(first: Iterable[float], second: Iterable[float]) -> float:
    """P(a value of first > one of second), ties half; < 0.5: first tends to be smaller (shorter)."""
    return _aco.vargha_delaney_a12([float(v) for v in first], [float(v) for v in second])


def effect_size(a12: float) -> str:
    """Vargha and Delaney's label of an A12: negligible, small, medium or large."""
    return _aco.effect_size(float(a12))


def average_ranks(scores: Sequence[Sequence[float]]) -> list:
    """Friedman average ranks: scores[c][p] of configuration c on problem p, lower is better."""
    return _aco.average_ranks([[float(v) for v in row] for row in scores])


def ecdf(hitting_times: Iterable[float], at: Iterable[float]) -> list:
    """For each t of ``at``: the share of all runs whose hitting time is <= t."""
    return _aco.ecdf([float(v) for v in hitting_times], [float(v) for v in at])


def expected_running_time(hitting_times: Iterable[float], run_efforts: Iterable[float]) -> float:
    """Total effort of all runs (until they hit or ended) over the number that hit; inf if none."""
    return _aco.expected_running_time([float(v) for v in hitting_times], [float(v) for v in run_efforts])


def summary(frame, value: str = "length", by: Sequence[str] = ("problem", "configuration")):
    """summarize() of ``value`` over the solved trials of each group, plus the success rate, as a
    DataFrame indexed by ``by``."""
    import pandas as pd

    rows = []
    for key, group in frame.groupby(list(by), sort=False):
        solved = group[group["solved"]]
        row = dict(zip(by, key if isinstance(key, tuple) else (key,)))
        row["runs"] = len(group)
        row["success"] = len(solved) / len(group)
        row.update(summarize(solved[value].dropna()))
        rows.append(row)
    return pd.DataFrame(rows).set_index(list(by))


def compare(frame, baseline: str, value: str = "length", by: str = "problem"):
    """Each configuration against ``baseline`` on each problem, over the solved trials, as the
    report's table does: Mann-Whitney p, Holm-adjusted p over all the comparisons, A12 (< 0.5: the
    configuration's values tend to be smaller than the baseline's) and its label. A baseline that
    is no configuration of the frame raises aco.Error naming those it has."""
    import pandas as pd

    configurations = list(frame["configuration"].unique())
    if baseline not in configurations:
        raise _aco.Error(f"baseline {baseline!r} is not a configuration of the frame; "
                         f"its configurations: {', '.join(map(repr, configurations))}")
    rows = []
    for problem, group in frame.groupby(by, sort=False):
        solved = group[group["solved"]]
        base = solved[solved["configuration"] == baseline][value].dropna()
        for configuration, runs in solved.groupby("configuration", sort=False):
            if configuration == baseline or base.empty or runs[value].dropna().empty:
                continue
            sample = runs[value].dropna()
            test = mann_whitney_u(sample, base)
            a12 = vargha_delaney_a12(sample, base)
            rows.append({by: problem, "configuration": configuration, "p": test["p"], "a12": a12, "effect": effect_size(a12)})
    table = pd.DataFrame(rows, columns=[by, "configuration", "p", "a12", "effect"])
    table.insert(3, "p_holm", holm_adjust(table["p"]) if len(table) else [])
    return table

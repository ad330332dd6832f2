"""Figures as the pages write them."""
from __future__ import annotations


def table(header: list[str], rows: list[list]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def span(values: list[float], digits: int = 2) -> str:
    """'1.23' or '1.20-1.35': the range over repeated measurements."""
    low, high = f"{min(values):.{digits}f}", f"{max(values):.{digits}f}"
    return low if low == high else f"{low}-{high}"


def about(seconds: float) -> str:
    """A duration as the prose says it: 'about 2 s', 'about 3 min'."""
    return f"about {seconds:.0f} s" if seconds < 100 else f"about {seconds / 60:.0f} min"

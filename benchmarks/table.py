"""The one table every benchmark adds its rows to, and how it is printed.

Kept apart from the measuring so each section module only says what it measured.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass


@dataclass
class Row:
    section: str
    what: str
    measured: str
    baseline: str = ""
    ratio: float | None = None
    target: str = ""
    ok: bool | None = None  # None: reported only (no target), or not measured
    #: The ratio of the row's floor (the same work done by the fastest bare loop), when its
    #: target was measured against one: a failed row whose floor is over the target says so.
    floor: float | None = None

    @property
    def below_floor(self) -> bool:
        """Is the target below the floor measured in the same run, so that no loop of the
        engine could meet it?"""
        return self.ok is False and self.floor is not None and self.floor > _limit(self.target)

    @property
    def verdict(self) -> str:
        if self.target == "baseline":
            return "-"
        if self.ok is None:
            return "n/a" if self.measured in ("not installed", "skipped") else "report"
        if self.below_floor:
            return f"FAIL, target below the floor ({fmt_ratio(self.floor)})"
        return "pass" if self.ok else "FAIL"


def _limit(target: str) -> float:
    """The number of a ``≤ N`` target (infinity for any other)."""
    try:
        return float(target.removeprefix("≤").split()[0])
    except (ValueError, IndexError):
        return float("inf")


#: Every row added so far, in order: the table ``bench.py`` prints at the end.
ROWS: list[Row] = []


def add(row: Row) -> Row:
    ROWS.append(row)
    print(f"  [{row.section}] {row.what}: {row.measured} | {row.baseline} | "
          f"{fmt_ratio(row.ratio)} {row.target} {row.verdict}", file=sys.stderr, flush=True)
    return row


def fmt_ratio(r: float | None) -> str:
    if r is None:
        return "-"
    return f"{r:.3f}" if r < 0.1 else f"{r:.2f}"


def print_table(rows: list[Row]) -> None:
    head = ("section", "what", "measured", "baseline", "ratio", "target", "result")
    cells = [head] + [
        (r.section, r.what, r.measured, r.baseline, fmt_ratio(r.ratio), r.target, r.verdict)
        for r in rows
    ]
    widths = [max(len(c[i]) for c in cells) for i in range(len(head))]
    line = "  ".join("-" * w for w in widths)
    print(line)
    for i, c in enumerate(cells):
        print("  ".join(s.ljust(w) for s, w in zip(c, widths, strict=True)).rstrip())
        if i == 0:
            print(line)
    print(line)
    passed = sum(r.ok is True for r in rows)
    failed = [r for r in rows if r.ok is False]
    below = sum(r.below_floor for r in failed)
    print(f"{passed} pass, {len(failed)} fail"
          f"{f' ({below} with the target below its floor)' if below else ''}, "
          f"{sum(r.ok is None for r in rows)} reported only")
    for r in failed:
        floor = f", floor {fmt_ratio(r.floor)}" if r.below_floor else ""
        print(f"  FAIL: [{r.section}] {r.what} ({fmt_ratio(r.ratio)}, target {r.target}{floor})")

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

    @property
    def verdict(self) -> str:
        if self.target == "baseline":
            return "-"
        if self.ok is None:
            return "n/a" if self.measured in ("not installed", "skipped") else "report"
        return "pass" if self.ok else "FAIL"


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
        print("  ".join(s.ljust(w) for s, w in zip(c, widths)).rstrip())
        if i == 0:
            print(line)
    print(line)
    passed = sum(r.ok is True for r in rows)
    failed = [r for r in rows if r.ok is False]
    print(f"{passed} pass, {len(failed)} fail, {sum(r.ok is None for r in rows)} reported only")
    for r in failed:
        print(f"  FAIL: [{r.section}] {r.what} ({fmt_ratio(r.ratio)}, target {r.target})")

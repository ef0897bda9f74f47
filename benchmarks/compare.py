"""Section "compare" (issue 11): compare mode's lockstep step against a single pane's, and
``end`` in compare mode, on maze512.  (Its start-up row is in the startup section.)"""

from __future__ import annotations

import asyncio
import sys

from benchmarks.apps import search_app_class
from benchmarks.harness import fmt_time, med, paired, series
from benchmarks.jump import _jump_once
from benchmarks.maps import maze_grid
from benchmarks.step import _presses, step_keys
from benchmarks.table import Row, add

COMPARED = "bfs,dfs"


def bench_compare(quick: bool) -> None:
    print("compare ...", file=sys.stderr, flush=True)
    app_cls, why = search_app_class()
    maze = maze_grid()
    if app_cls is None or maze is None:
        add(Row("compare", "compare mode on maze512", "skipped", why or "maze512 missing"))
        return
    n = 100 if quick else 200
    reps = 3 if quick else 5
    single, pair = [], []
    for _ in range(reps):  # interleaved
        single.append(asyncio.run(_presses(app_cls(maze.copy()), step_keys(n))))
        pair.append(asyncio.run(_presses(app_cls(maze.copy(), compare=COMPARED),
                                         step_keys(n))))
    one = series("compare single cpu", [c - i for _, c, i, _ in single])
    two = series("compare pair cpu", [c - i for _, c, i, _ in pair])
    r = paired(two, one)
    add(Row("compare", f"n/p on maze512: two panes ({COMPARED}) vs one (CPU per press, net of "
            "Pilot)", fmt_time(two), f"one pane {fmt_time(one)}", r, "≤ 2.2", r <= 2.2))
    lines = (med([d for *_, d in single]), med([d for *_, d in pair]))
    add(Row("compare", "lines drawn afresh per press: one pane / two panes",
            f"{lines[0]:.1f} / {lines[1]:.1f}", "", None, "report"))
    times, singles, ks = [], [], []
    for _ in range(3 if quick else 5):  # interleaved with the single runs' end, the floor
        dt, ks = asyncio.run(_jump_once(app_cls, maze, compare=COMPARED))
        times.append(dt)
        singles.append(sum(asyncio.run(_jump_once(app_cls, maze, algo))[0]
                           for algo in COMPARED.split(",")))
    series("compare end", times)
    series("compare end, single runs", singles)
    steps = " and ".join(f"{k:,}" for k in ks)
    add(Row("compare", f"maze512 {COMPARED}: press end → final screen ({steps} steps)",
            fmt_time(times), "limit 0.6 s", med(times) / 0.6, "≤ 0.6 s", med(times) <= 0.6))
    add(Row("compare", f"maze512 {COMPARED}: end in compare mode vs end in each single run, "
            "summed", fmt_time(times), f"summed {fmt_time(singles)}", paired(times, singles),
            "report"))

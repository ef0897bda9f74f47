"""Section "jump": ``end`` on a big map, from the key to the final screen."""

from __future__ import annotations

import asyncio
import gc
import sys
import time

from benchmarks.apps import TERMINAL, fast_press, search_app_class, settle
from benchmarks.harness import fmt_time, med, series
from benchmarks.maps import OPEN_SIZE, maze_grid, open_grid
from benchmarks.table import Row, add
from tui_search.engine.grid import Grid


async def _jump_once(app_cls, grid: Grid, algorithm: str = "bfs",
                     compare: str | None = None) -> tuple[float, list[int]]:
    """``end`` from the key to the final screen: of one run, or with ``compare`` of every
    run of compare mode.  The seconds, and the step each run ends at."""
    app = app_cls(grid.copy(), algorithm=algorithm, compare=compare)
    async with app.run_test(size=TERMINAL) as pilot:
        await pilot.pause()
        gc.collect()
        t0 = time.perf_counter()
        await fast_press(pilot, "end")
        # Poll without forcing repaints (pilot.pause() would repaint every poll, which the
        # app's own screen-update timer does not): the app paints as it would in a terminal.
        while app.session.seeking or not app.session.runs or not all(r.at_end for r in app.session.runs):
            await asyncio.sleep(0.01)
            if time.perf_counter() - t0 > 120:
                raise TimeoutError("end did not reach the end in 120 s")
        await settle(pilot)  # the final screen, painted
        return time.perf_counter() - t0, [r.k for r in app.session.runs]


def bench_jump(quick: bool) -> None:
    print("jump ...", file=sys.stderr, flush=True)
    app_cls, why = search_app_class()
    if app_cls is None:
        add(Row("jump", "end on maze512 / 1024²", "skipped", why))
        return
    cases = []
    maze = maze_grid()
    if maze is not None:
        cases.append(("maze512", maze, 0.5))
    cases.append((f"open {OPEN_SIZE}²", open_grid(), 2.0))
    for name, grid, limit in cases:
        times, k = [], 0
        for _ in range(2 if quick else 3):
            dt, (k,) = asyncio.run(_jump_once(app_cls, grid))
            times.append(dt)
        series(f"jump {name}", times)
        add(Row("jump", f"{name} BFS: press end → final screen ({k:,} steps)", fmt_time(times),
                f"limit {limit} s", med(times) / limit, f"≤ {limit} s", med(times) <= limit))

"""Section "jump": ``end`` on a big map, from the key to the final screen: maze512 and open
1024² on the wall clock, and open 4096² (issue 26) on the CPU clock too (a shared machine's
wall clock counts the waits for a CPU)."""

from __future__ import annotations

import asyncio
import gc
import sys
import time

from benchmarks.apps import TERMINAL, fast_press, search_app_class, settle
from benchmarks.harness import CPU, fmt_time, med, series
from benchmarks.maps import OPEN_SIZE, maze_grid, open_grid
from benchmarks.table import Row, add
from tui_search.engine.maps.grid import Grid


async def _jump_once(app_cls, grid: Grid, algorithm: str = "bfs",
                     compare: str | None = None) -> tuple[float, list[int]]:
    """``end`` from the key to the final screen: of one run, or with ``compare`` of every
    run of compare mode.  The seconds, and the step each run ends at."""
    wall, _, steps = await _jump_times(app_cls, grid, algorithm, compare)
    return wall, steps


async def _jump_times(app_cls, grid: Grid, algorithm: str = "bfs",
                      compare: str | None = None) -> tuple[float, float, list[int]]:
    """:func:`_jump_once`'s wall seconds, its CPU seconds beside, and the steps."""
    app = app_cls(grid.copy(), algorithm=algorithm, compare=compare)
    async with app.run_test(size=TERMINAL) as pilot:
        await pilot.pause()
        gc.collect()
        t0, c0 = time.perf_counter(), CPU()
        await fast_press(pilot, "end")
        # Poll without forcing repaints (pilot.pause() would repaint every poll, which the
        # app's own screen-update timer does not): the app paints as it would in a terminal.
        session = app.session
        while session.seeking or not session.runs or not all(r.at_end for r in session.runs):
            await asyncio.sleep(0.01)
            if time.perf_counter() - t0 > 120:
                raise TimeoutError("end did not reach the end in 120 s")
        await settle(pilot)  # the final screen, painted
        return time.perf_counter() - t0, CPU() - c0, [r.k for r in app.session.runs]


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
    bench_jump_4096(app_cls, 2 if quick else 3)


def bench_jump_4096(app_cls, repeats: int) -> None:
    """Issue 26's row: ``end`` on open 4096² in the app, CPU seconds from the key to the
    final screen (the wall clock's beside it), within 1.5 s."""
    grid, limit = open_grid(4096), 1.5
    cpu, wall, k = [], [], 0
    for _ in range(repeats):
        dt, used, (k,) = asyncio.run(_jump_times(app_cls, grid))
        wall.append(dt)
        cpu.append(used)
    series("jump open 4096² (CPU)", cpu)
    series("jump open 4096² (wall)", wall)
    add(Row("jump", f"open 4096² BFS: press end → final screen ({k:,} steps), CPU time",
            fmt_time(cpu), f"limit {limit} s; wall {fmt_time(wall)}", med(cpu) / limit,
            f"≤ {limit} s", med(cpu) <= limit))

"""Section "core" (issue 26): the compiled search core against the C floor.

The floor (``benchmarks/floor.c``, built here with the core's flags and called through
ctypes) runs the same searches with the least record that lets the app move to any step.  A
row times, in CPU seconds, a recorded run to its end (``Run(...)`` and ``advance()``: the
set-up included) under the compiled core against the floor: BFS, DFS (a full traversal, the
goal walled in), A* and UCS on maze512 (its ``.scen`` row 3, corners never) and open 1024²,
and BFS on open 4096².  Then re-running BFS to its end after an edit on open 1024², and the
record's bytes an expansion under both cores.
"""

from __future__ import annotations

import ctypes
import os
import subprocess
import sys
import sysconfig
import tempfile
from collections.abc import Callable
from functools import cache
from pathlib import Path

from benchmarks.baselines import walled_in
from benchmarks.harness import CPU, fmt_time, interleaved, med, paired, series
from benchmarks.maps import MAPS, MAZE, MAZE_SCEN, open_grid
from benchmarks.table import Row, add
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.heuristics import DIAGONAL_EXTRA
from tui_search.engine.search.loops import compiled
from tui_search.engine.search.loops.best_first import _costed_moves
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.registry import get_algorithm

FLOOR_SOURCE = Path(__file__).with_name("floor.c")
MAZE_ROW = 3
NEVER = Semantics(corners="never")


@cache
def floor_library() -> ctypes.CDLL:
    """``floor.c`` built into a temporary folder (once a process)."""
    out = Path(tempfile.mkdtemp(prefix="tui-search-floor-")) / "floor.so"
    cc = (sysconfig.get_config_var("CC") or "cc").split()
    subprocess.run([*cc, "-O2", "-ffp-contract=off", "-shared", "-fPIC", str(FLOOR_SOURCE),
                    "-o", str(out)], check=True)
    lib = ctypes.CDLL(str(out))
    lib.floor_queue.restype = lib.floor_best.restype = ctypes.c_long
    return lib


def floor_search(grid: Grid, key: str, sem: Semantics) -> Callable[[], int]:
    """The floor's search of ``grid`` (a call returns its steps); the map's padded walls,
    terrain (a map with costs: UCS and A* weigh them) and moves are made before, outside the
    time."""
    lib = floor_library()
    algo = get_algorithm(key)
    if sem.corners == "one":
        raise ValueError("the floor knows the corner rules always and never")
    problem = Problem(grid, sem, sem.goal_test_for(algo))
    walls = (ctypes.c_ubyte * len(problem.walls)).from_buffer_copy(problem.walls)
    moves = _costed_moves(problem)
    n = len(moves)
    off, side_a, side_b = ((ctypes.c_int * n)(*(m[i] for m in moves)) for i in (0, 2, 3))
    cost = (ctypes.c_double * n)(*(m[1] for m in moves))
    terrain = None if problem.terrain is None else (
        (ctypes.c_double * len(problem.terrain)).from_buffer_copy(problem.terrain))
    if algo.priority is None:
        return lambda: lib.floor_queue(walls, ctypes.c_long(len(walls)), problem.start,
                                       problem.goal, off, side_a, side_b, n, int(key == "dfs"))
    return lambda: lib.floor_best(walls, ctypes.c_long(len(walls)), problem.stride,
                                  problem.start, problem.goal, off, side_a, side_b, cost, n,
                                  int(algo.priority == "g+h"), ctypes.c_double(DIAGONAL_EXTRA),
                                  terrain, ctypes.c_double(problem.lowest))


def recorded(grid: Grid, key: str, sem: Semantics) -> Run:
    run = Run(grid, key, sem)
    run.advance()
    return run


def maze_row() -> Grid | None:
    m, s = MAPS / MAZE, MAPS / MAZE_SCEN
    if not m.exists() or not s.exists():
        return None
    from tui_search.engine.maps.load import load_map
    from tui_search.engine.maps.scenarios import load_scenario

    scen = load_scenario(s, MAZE_ROW)
    return load_map(m, start=scen.start, goal=scen.goal)


def _cases() -> list[tuple[str, Grid, str, Semantics]]:
    maze, open_map = maze_row(), open_grid()
    out = []
    for name, grid, sem in (("maze512 row 3, corners never", maze, NEVER),
                            ("open 1024²", open_map, Semantics())):
        if grid is None:
            add(Row("core", MAZE, "skipped", f"not found in {MAPS}"))
            continue
        out += [(name, grid, "bfs", sem), (name, walled_in(grid), "dfs", sem),
                (name, grid, "astar", sem), (name, grid, "ucs", sem)]
    return [*out, ("open 4096²", open_grid(4096), "bfs", Semantics())]


def bench_core(quick: bool) -> None:
    print("core ...", file=sys.stderr, flush=True)
    os.environ.pop(compiled.CORE_ENV, None)
    compiled.selected.cache_clear()
    if compiled.selected()[0] is None:
        add(Row("core", "the compiled search core", "not built", compiled.core_name()))
        return
    repeats = 3 if quick else 7
    for name, grid, key, sem in _cases():
        floor = floor_search(grid, key, sem)
        steps = recorded(grid, key, sem).recorded  # warm-up, and the steps
        t = interleaved({"floor": floor, "run": lambda g=grid, k=key, s=sem: recorded(g, k, s)},
                        repeats if len(grid.blocked) < 1 << 21 else min(repeats, 3), CPU)
        for what, xs in t.items():
            series(f"{name} {key} {what}", xs)
        full = " (full traversal)" if key == "dfs" else ""
        r = paired(t["run"], t["floor"])
        add(Row("core", f"{name} {key.upper()}{full} recorded run ({steps:,} steps) vs C floor",
                fmt_time(t["run"]), f"C floor {fmt_time(t['floor'])}", r, "≤ 2", r <= 2))
    bench_edit(repeats)
    bench_record_memory()


def bench_edit(repeats: int) -> None:
    """A wall toggled on open 1024², then BFS recorded to its end and the run moved there
    (what the app shows after an edit)."""
    grid = open_grid()
    cell = (grid.width // 2, grid.height // 2)

    def rerun() -> None:
        grid.set_blocked(cell, not grid.is_blocked(cell))
        run = recorded(grid, "bfs", Semantics())
        run.goto(run.total)

    xs = series("edit rerun", interleaved({"rerun": rerun}, repeats, CPU)["rerun"])
    add(Row("core", "open 1024² re-run after an edit: BFS recorded and moved to its end",
            fmt_time(xs), "-", None, "≤ 50 ms", med(xs) <= 0.05))


def bench_record_memory() -> None:
    """The record's bytes an expansion, under each core: the same arrays."""
    grid = open_grid()
    for key, g in (("bfs", grid), ("dfs", walled_in(grid))):
        per_step = {}
        for core in ("python", "compiled"):
            os.environ[compiled.CORE_ENV] = core
            compiled.selected.cache_clear()
            rec = recording_of(recorded(g, key, Semantics())).rec
            per_step[core] = rec.nbytes() / rec.steps
        os.environ.pop(compiled.CORE_ENV, None)
        compiled.selected.cache_clear()
        add(Row("core", f"open 1024² {key.upper()} record, bytes an expansion (compiled core)",
                f"{per_step['compiled']:.2f} B", f"Python core {per_step['python']:.2f} B",
                per_step["compiled"] / per_step["python"], "≤ 1", per_step["compiled"]
                <= per_step["python"]))

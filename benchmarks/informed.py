"""Section "informed" (issue 10): the recorded A* and uniform-cost runs against a bare heapq
A* / Dijkstra of the same map and against the ``pathfinding`` package's A*, and the cost of a
step with a priority queue of 100,000 entries.

The bare searches are the floor: plain Python, the padded flat grid the engine uses, a binary
heap of ``(priority, counter, cell)`` with lazy deletion (a cell popped a second time is
skipped), no recording.  They find the same costs (checked before timing).
"""

from __future__ import annotations

import heapq
import itertools
import sys
import time
from collections.abc import Callable

from benchmarks.baselines import pad
from benchmarks.engine import bench_memory
from benchmarks.harness import CPU, fmt_time, interleaved, med, paired, series, timed
from benchmarks.maps import MAPS, MAZE, MAZE_SCEN, open_grid
from benchmarks.table import Row, add
from tui_search.engine.maps.grid import DEFAULT_ORDER, DELTAS, SQRT2, Grid
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import Semantics

NEVER = Semantics(corners="never")
#: maze512's problem: row 3 of its .scen, as the issue says.
MAZE_ROW = 3


def bare_best_first(grid: Grid, astar: bool) -> float:
    """The cheapest path's cost under no corner cutting: A* with octile (``astar``) or
    Dijkstra.  A diagonal needs both side cells free; a cell is closed when first popped."""
    walls, stride, start, goal, offs = pad(grid)
    moves = []  # (offset, cost, the two side cells' offsets for a diagonal)
    for off, name in zip(offs, DEFAULT_ORDER, strict=True):
        dx, dy = DELTAS[name]
        sides = (dx, dy * stride) if dx and dy else None
        moves.append((off, SQRT2 if sides else 1.0, sides))
    gy, gx = divmod(goal, stride)
    extra = SQRT2 - 1
    best = [float("inf")] * len(walls)
    closed = bytearray(walls)
    best[start] = 0.0
    heap = [(0.0, 0, start)]
    pop, push = heapq.heappop, heapq.heappush
    count = 1
    while heap:
        _, _, n = pop(heap)
        if closed[n]:
            continue
        if n == goal:
            return best[n]
        closed[n] = 1
        g = best[n]
        for off, cost, sides in moves:
            m = n + off
            if closed[m] or (sides and (walls[n + sides[0]] or walls[n + sides[1]])):
                continue
            ng = g + cost
            if ng < best[m]:
                best[m] = ng
                if astar:
                    y, x = divmod(m, stride)
                    dx, dy = abs(x - gx), abs(y - gy)
                    f = ng + (dx + extra * dy if dx >= dy else dy + extra * dx)
                else:
                    f = ng
                push(heap, (f, count, m))
                count += 1
    return float("inf")


def pathfinding_astar(grid: Grid) -> Callable[[], float] | None:
    """The ``pathfinding`` package's A* (octile, no corner cutting), its grid built in the
    call (it keeps the search's state on its nodes, so a grid serves one search)."""
    try:
        from pathfinding.core.diagonal_movement import DiagonalMovement
        from pathfinding.core.grid import Grid as PFGrid
        from pathfinding.core.heuristic import octile
        from pathfinding.finder.a_star import AStarFinder
    except ImportError:
        return None
    w = grid.width
    matrix = [[0 if grid.blocked[y * w + x] else 1 for x in range(w)] for y in range(grid.height)]

    def solve() -> float:
        pf = PFGrid(matrix=matrix)
        finder = AStarFinder(heuristic=octile,
                             diagonal_movement=DiagonalMovement.only_when_no_obstacle)
        path, _ = finder.find_path(pf.node(*grid.start), pf.node(*grid.goal), pf)
        return sum(SQRT2 if a.x != b.x and a.y != b.y else 1.0 for a, b in itertools.pairwise(path))

    return solve


def informed_maps() -> list[tuple[str, Grid]]:
    maps = [("open 1024²", open_grid())]
    m, s = MAPS / MAZE, MAPS / MAZE_SCEN
    if m.exists() and s.exists():
        from tui_search.engine.maps.load import load_map
        from tui_search.engine.maps.scenarios import load_scenario

        scen = load_scenario(s, MAZE_ROW)
        maps.append((f"maze512 row {MAZE_ROW}", load_map(m, start=scen.start, goal=scen.goal)))
    else:
        add(Row("informed", MAZE, "skipped", f"not found in {MAPS}"))
    return maps


def recorded(grid: Grid, algorithm: str) -> Run:
    run = Run(grid, algorithm, NEVER)
    run.advance()
    return run


def bench_informed(quick: bool) -> None:
    print("informed ...", file=sys.stderr, flush=True)
    repeats = 3 if quick else 5
    for name, grid in informed_maps():
        for key, astar in (("astar", True), ("ucs", False)):
            run = recorded(grid, key)
            want = bare_best_first(grid, astar)
            got = run.outcome().cost
            if got is None or abs(got - want) > 1e-6 * want:
                print(f"WARNING: {name} {key}: engine cost {got}, bare {want}", file=sys.stderr)
            label = "A*" if astar else "UCS"
            t = interleaved({
                "bare": lambda g=grid, a=astar: bare_best_first(g, a),
                "run": lambda g=grid, k=key: recorded(g, k),
            }, repeats, CPU)
            series(f"{name} bare {label}", t["bare"])
            series(f"{name} run {label}", t["run"])
            r = paired(t["run"], t["bare"])
            add(Row("informed", f"{name} {label} recorded run vs bare heapq "
                    f"({run.recorded:,} steps, {len(recording_of(run).discarded_steps()):,} stale)",
                    fmt_time(t["run"]), f"bare {fmt_time(t['bare'])}", r, "≤ 1.30", r <= 1.30))
            if astar:
                pf = pathfinding_astar(grid)
                if pf is None:
                    add(Row("informed", f"{name} pathfinding A*", "not installed"))
                else:
                    pf_t = series(f"{name} pathfinding A*",
                                  [timed(pf, CPU)[0] for _ in range(1 if quick else 3)])
                    r = med(t["run"]) / med(pf_t)  # not interleaved: pathfinding takes seconds
                    # The floor: the bare heapq A* itself against pathfinding.
                    add(Row("informed", f"{name} A* recorded run vs pathfinding 1.0.23 A* "
                            "(+grid)", fmt_time(t["run"]), f"pathfinding {fmt_time(pf_t)}", r,
                            "≤ 0.125 (8× less)", r <= 0.125,
                            floor=med(t["bare"]) / med(pf_t)))
            bench_memory(name, grid, key, run, "informed",
                         lambda g, a=astar: bare_best_first(g, a))
            del run
    bench_big_queue(quick)


def bench_big_queue(quick: bool) -> None:
    """A step's cost does not grow with the queue: uniform-cost tree search on an open map
    (no best g: every successor pushed) holds ~100,000 entries after ~20,000 steps; one step
    forwards and back there against the same at step 1 (7 entries, the issue's "10")."""
    grid = Grid(400, 400, start=(200, 200), goal=(0, 0))
    sem = Semantics(tree_search=True)
    runs = {}
    for name, k in (("small", 1), ("big", 20_000)):  # 7 entries / ~102,000
        runs[name] = Run(grid, "ucs", sem, max_steps=30_000)
        runs[name].goto(k)
    small_n, big_n = runs["small"].now.frontier_len(), runs["big"].now.frontier_len()

    def step_at(name: str) -> Callable[[], None]:
        run = runs[name]

        def go() -> None:  # 50 steps forwards and back, reading what the panel reads
            for _ in range(50):
                run.forward()
                run.now.frontier(0, 30)
                run.backward()
                run.now.frontier(0, 30)
        return go

    t = interleaved({"small": step_at("small"), "big": step_at("big")}, 3 if quick else 7, CPU)
    per = {k: [x / 100 for x in xs] for k, xs in t.items()}
    r = paired(per["big"], per["small"])
    add(Row("informed", f"priority queue step (n/p) with {big_n:,} entries vs {small_n:,}",
            fmt_time(per["big"]), f"{small_n:,} entries {fmt_time(per['small'])}", r,
            "≤ 1.5", r <= 1.5))


if __name__ == "__main__":  # the section alone: python -m benchmarks.informed
    from benchmarks.table import ROWS, print_table

    t0 = time.perf_counter()
    bench_informed("--quick" in sys.argv)
    print_table(ROWS)
    print(f"took {time.perf_counter() - t0:.0f} s")

"""Section "diagnose": ``--check-trace`` without ``-a`` (issue 36), which tries every search
under the choices that tell them apart, and the choices of published code where a candidate
parts for their reason.

The issue's budgets are absolute: ≤ 2 s for a 6x6 map, ≤ 10 s for a 10,000-step trace.  Each
row prints the CPU time of one diagnosis (the median of a few, this process's CPU: the
diagnosis is single-threaded and CPU-bound), its ratio to the budget (target ≤ 1), and, beside
it as a report, its ratio to its floor: the one check of the search the trace is, the least any
diagnosis must do.  The traces are the app's own (``--trace``) under the choices students'
code makes, and one of expansions only (a course's autograder's: no successors, so 24 orders of
the moves are tried).
"""

from __future__ import annotations

import io
import json
from pathlib import Path

from benchmarks.harness import CPU, fmt_time, med, series, timed
from benchmarks.table import Row, add
from tui_search.cli.headless import search_headless
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.engine.maps.scenarios import load_scenario
from tui_search.engine.search.choices import Semantics
from tui_search.engine.traces.check import check_trace
from tui_search.engine.traces.meeting import check_bidirectional, diagnose_trace
from tui_search.engine.traces.read import Trace, read_trace

#: The diagnosis tests' 6x6 map (tests/engine/test_trace_diagnose.py).
ROWS = ["S.....", ".##.#.", "...#..", ".#...#", "...#.G", "......"]
NESW = ("N", "E", "S", "W")
#: The 6x6 traces: (name, algorithm, choices, expansions only?).
SMALL = [
    ("BFS", "bfs", Semantics(order=NESW), False),
    ("recursive DFS, a line lists the calls", "dfs", Semantics(order=NESW, recursive="calls"),
     False),
    ("A*, heapq's ties, no re-opening", "astar",
     Semantics(order=NESW, heuristic="manhattan", ties="node", reopen=False), False),
    ("BFS marking cells visited when taken off", "bfs",
     Semantics(order=NESW, visit="expand-again", goal_test="expand"), False),
    ("DFS, expansions only (an autograder's)", "dfs",
     Semantics(order=("N", "S", "E", "W"), visit="expand", goal_test="expand"), True),
]
#: lak303d's problem whose BFS takes 10,187 steps, in the clone's trimmed copy of its .scen
#: (tests/engine/test_trace_diagnose.py's).
BIG_MAP, BIG_SCEN, BIG_ROW = "lak303d.map", "lak303d.map.scen", 4
COPIED = Path(__file__).resolve().parents[1] / "tests" / "data" / "movingai"


def app_trace(grid: Grid, key: str, sem: Semantics, nodes_only: bool) -> Trace:
    out = io.StringIO()
    search_headless(grid, key, sem, 1_000_000, out)
    text = out.getvalue()
    if nodes_only:
        text = "".join(json.dumps({"node": json.loads(line)["node"]}) + "\n"
                       for line in text.splitlines())
    return read_trace(text, grid, "trace", both_ways=None)  # as --check-trace reads it


def _row(what: str, trace: Trace, grid: Grid, key: str, sem: Semantics, budget: float,
         repeats: int) -> None:
    times, floors, tried = [], [], 0
    for _ in range(repeats):
        t, diagnosis = timed(lambda: diagnose_trace(trace, grid), CPU)
        times.append(t)
        tried = diagnosis.tried  # type: ignore[attr-defined]
        assert diagnosis.matches  # type: ignore[attr-defined]
        if trace.bidirectional:
            f, _ = timed(lambda: check_bidirectional(trace, grid, key, sem, 10**9), CPU)
        else:
            f, _ = timed(lambda: check_trace(trace, grid, key, sem, look_ahead=0), CPU)
        floors.append(f)
    t = med(series(f"diagnose {what}", times))
    add(Row("diagnose", f"{what}: {len(trace.steps):,} steps, {tried:,} searches and choices "
            f"tried (floor: its one check, {fmt_time(floors)}, {t / med(floors):.0f}x)",
            fmt_time(times), f"the issue's budget {budget:g} s", t / budget, "≤ 1.00",
            t <= budget))


def bench_diagnose(quick: bool) -> None:
    repeats = 3 if quick else 5
    grid = parse_map_text("\n".join(ROWS) + "\n", "6x6")
    for what, key, sem, nodes_only in SMALL:
        _row(f"6x6, {what}", app_trace(grid, key, sem, nodes_only), grid, key, sem, 2.0,
             repeats)
    trap = load_map(Path(__file__).resolve().parents[1] / "maps" / "pathfinding-js-28.txt")
    for key, stop in (("bibfs", "first-meeting"), ("biastar", "proven")):
        sem = Semantics(stop=stop)
        _row(f"pathfinding-js-28, {key} {stop} (bidirectional)",
             app_trace(trap, key, sem, False), trap, key, sem, 2.0, repeats)
    scen = COPIED / BIG_SCEN
    if not scen.exists():
        add(Row("diagnose", BIG_MAP, "skipped", f"not found in {COPIED}"))
        return
    problem = load_scenario(str(scen), BIG_ROW)
    big = load_map(COPIED / BIG_MAP, start=problem.start, goal=problem.goal)
    for what, key, sem, nodes_only in (
            ("BFS", "bfs", Semantics(), False),
            ("A*, heapq's ties, exact costs", "astar",
             Semantics(ties="node", cost_tolerance=0.0), False),
            ("DFS, expansions only (an autograder's)", "dfs",
             Semantics(order=("N", "S", "E", "W"), visit="expand", goal_test="expand"), True),
            ("bibfs (bidirectional)", "bibfs", Semantics(), False)):
        trace = app_trace(big, key, sem, nodes_only)
        _row(f"{BIG_MAP} row {BIG_ROW}, {what}", trace, big, key, sem, 10.0,
             max(1, repeats // 2))


__all__ = ["bench_diagnose"]

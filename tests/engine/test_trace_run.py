"""A trace replayed as a run (:mod:`tui_search.engine.traces.as_run`): the app's own ``--trace``
of any search and choices, replayed, is a run with the same steps; its frontier is what the
trace added and has not expanded, in the order added, either way and after a long jump."""

from __future__ import annotations

from collections import Counter

from tests.engine.test_trace import GRID, app_case, lines, over_app_searches
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import DEFAULT_SEMANTICS, Semantics
from tui_search.engine.search.registry import Frontier
from tui_search.engine.traces.as_run import TRACE_ALGORITHM, trace_run
from tui_search.engine.traces.read import read_trace


def steps_of(run: Run) -> list[tuple[object, ...]]:
    run.advance()
    return [(s.node, [c for _, c in s.successors], s.discarded) for s in run.steps.all()]


@over_app_searches
def test_the_apps_own_trace_replayed_has_the_runs_steps(
        grid: Grid, key: str, sem: Semantics, visit: str) -> None:
    limit = 300
    sem, text = app_case(grid, key, sem, visit, limit)
    real = Run(grid, key, sem, limit)
    replayed = trace_run(read_trace(text, grid, "t"), grid, key, sem, limit)
    assert steps_of(replayed) == steps_of(real)
    if real.done and not real.gave_up:
        assert replayed.found == real.found
        if real.found:
            assert replayed.path() == real.path()
    # every step either way: the frontier is what was added and not taken off, oldest first
    # (a multiset of cells: each step's successors, less each step's node); a long jump,
    # rebuilt in bulk, gives the same
    trace = read_trace(text, grid, "t")
    if real.algo.iterative:
        return  # restarts: a new frontier an iteration
    shown = []
    for k in range(replayed.recorded + 1):
        replayed.goto(k)
        events = replayed.now.frontier()
        assert events == sorted(events) and len(events) == replayed.now.frontier_len()
        shown.append(events)
        left = Counter([grid.start]) + Counter(c for t in trace.steps[:k] for c in t.successors)
        left.subtract(t.node for t in trace.steps[:k])
        assert Counter(replayed.nodes.cell(g) for g in events) == +left
    for k in range(replayed.recorded, -1, -1):
        replayed.goto(k)
        assert replayed.now.frontier() == shown[k]
    replayed.REBUILD_AFTER = 0  # every jump rebuilds
    for k in (replayed.recorded, 0, replayed.recorded // 2):
        replayed.goto(k)
        assert replayed.now.frontier() == shown[k]


def test_the_trace_run_is_no_registry_search_and_says_its_frontier_is_as_added() -> None:
    text = lines({"node": [0, 0], "successors": [[0, 1]]},
                 {"node": [0, 1], "successors": [[0, 2], [1, 2]]})
    run = trace_run(read_trace(text, GRID, "t"), GRID, "bfs", DEFAULT_SEMANTICS)
    assert run.algo is TRACE_ALGORITHM and run.algo.frontier is Frontier.ADDED
    from tui_search.engine.search.registry import ALGORITHMS

    assert TRACE_ALGORITHM.key not in ALGORITHMS
    run.goto(2)
    assert [run.nodes.cell(g) for g in run.now.frontier()] == [(0, 2), (1, 2)]
    assert run.steps.at(2).node == (0, 1)
    run.goto(1)
    assert [run.nodes.cell(g) for g in run.now.frontier()] == [(0, 1)]


def test_a_stack_trace_takes_the_newest_entry_of_a_cell_a_queue_the_oldest() -> None:
    # (0,2) is added twice, events 2 and 4: the queue takes the older, the stack the newer
    text = lines({"node": [0, 0], "successors": [[0, 1]]},
                 {"node": [0, 1], "successors": [[0, 2], [1, 2]]},
                 {"node": [1, 2], "successors": [[0, 2]]},
                 {"node": [0, 2], "successors": []})
    trace = read_trace(text, GRID, "t")
    for key, left in (("bfs", 4), ("dfs", 2)):
        run = trace_run(trace, GRID, key, DEFAULT_SEMANTICS.replace(visit="expand"))
        run.goto(4)
        assert run.now.frontier() == [left]
        assert run.steps.at(4).node == (0, 2) and not run.steps.at(4).discarded

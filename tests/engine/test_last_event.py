"""The latest event of each cell at a run's position (the map's arrows, depths and readout):
what scanning the record says, wherever the position went and however it got there."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from tests.engine.test_search import random_grids
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import Semantics


def scanned(run: Run) -> dict:
    """The latest event of each cell among the iteration's events generated so far."""
    out: dict = {}
    for g in range(run.now.tree_root(), run.now.generated):
        out[run.nodes.cell(g)] = g
    return out


def kept(run: Run) -> dict:
    g = run.grid
    cells = ((x, y) for y in range(g.height) for x in range(g.width))
    return {c: e for c in cells if (e := run.now.last_event(c)) is not None}


@settings(max_examples=150, deadline=None)
@given(random_grids(max_side=6), st.sampled_from(["bfs", "dfs", "iddfs", "ucs", "astar"]),
       st.booleans(), st.lists(st.integers(-3, 400), min_size=1, max_size=8),
       st.sampled_from([0, 3, 10**9]))
def test_the_last_event_of_each_cell_is_the_latest_generated(grid, algo, tree, moves,
                                                              rebuild) -> None:
    """Steps forwards and backwards (small moves), jumps (rebuilt in bulk or stepped), tree
    search (a cell generated many times) and iterative deepening's iterations."""
    semantics = Semantics(tree_search=True) if tree and algo != "iddfs" else Semantics()
    run = Run(grid, algo, semantics, max_steps=3000)
    run.REBUILD_AFTER = rebuild
    run.advance()
    assert kept(run) == scanned(run)
    for move in moves:
        if move < 0:
            for _ in range(-move):
                run.backward()
        else:
            run.goto(move % (run.recorded + 1))
        assert kept(run) == scanned(run)
    run.reset()
    assert kept(run) == scanned(run) == {grid.start: 0}


def test_the_depth_of_a_stack_search_event_is_its_chain_walked_once() -> None:
    """DFS records no depth: gen_depth walks the chain, and asking again (or for a child)
    answers what the walk found."""
    from tests.helpers import TUTORIAL_ROWS, grid_from_rows

    run = Run(grid_from_rows(TUTORIAL_ROWS), "dfs")
    run.advance()
    for g in range(len(recording_of(run).rec.gen_node)):
        assert run.nodes.depth(g) == len(run.nodes.ancestors(g)) - 1

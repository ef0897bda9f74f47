"""A bidirectional search as a run (engine/run/bidirectional.py): each half's steps, costs
and frontier, at every position either way, are the reference's
(:class:`~tui_search.engine.search.bidirectional.loop.BidirectionalSearch`), on random maps
with terrain and any moves, and on random graphs with one-way roads; its answer is the
headless run's."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.engine.test_bidirectional import bidirectional, grid_choices
from tests.engine.test_graph_search import app_graph, graphs
from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.bidirectional import BiRun, app_refusal
from tui_search.engine.search.bidirectional.loop import (
    BidirectionalSearch,
    stream_bidirectional,
)
from tui_search.engine.search.choices import STOP_RULES, Semantics
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.rules import PriorityQueue

KEYS = ("bibfs", "biucs", "biastar")


Entries = list[tuple[object, float]]


def reference_frontiers(board: Grid | Graph, key: str, sem: Semantics
                        ) -> list[tuple[str, Entries, Entries]]:
    """After each step of the reference: its direction and each half's frontier, as
    (cell, g) in the order it comes out."""
    search = BidirectionalSearch(board, get_algorithm(key), sem)

    def out(queue: object) -> Entries:
        if isinstance(queue, PriorityQueue):
            nodes = [entry[3] for entry in sorted(queue.heap)]
        else:
            nodes = list(queue.entries)  # type: ignore[attr-defined]
        return [(n.cell, round(n.g, 9)) for n in nodes]

    return [(step.direction, out(search.forward.queue), out(search.backward.queue))
            for step in search]


def run_frontier(run: BiRun, back: int) -> Entries:
    half = run.halves[back]
    weighted = run.algo.weighted
    return [(half.nodes.cell(e), round(half.nodes.costs(e)[0], 9) if weighted else 0.0)
            for e in half.now.frontier()]


def assert_follows(board: Grid | Graph, key: str, sem: Semantics) -> None:
    expected = reference_frontiers(board, key, sem)
    run = BiRun(board, key, sem)
    weighted = get_algorithm(key).weighted
    for k, (direction, ahead, behind) in enumerate(expected, 1):
        assert run.forward()
        assert run.k == k and run.direction(k) == direction
        for back, want in ((0, ahead), (1, behind)):
            if not weighted:
                want = [(cell, 0.0) for cell, _ in want]
            assert run_frontier(run, back) == want, (k, back)
    assert not run.forward() and run.at_end
    # and back again: each position the same as on the way there
    for k in range(len(expected) - 1, 0, -1):
        assert run.backward()
        _, ahead, behind = expected[k - 1]
        if weighted:
            assert run_frontier(run, 0) == ahead and run_frontier(run, 1) == behind
    outcome = stream_bidirectional(board, get_algorithm(key), sem, 10**6)
    mine = run.outcome()
    assert (mine.path, mine.cost, mine.expanded, mine.stopped, mine.meeting) == (
        outcome.path, outcome.cost, outcome.expanded, outcome.stopped, outcome.meeting)


@bidirectional
@given(random_grids(max_side=8, costs=True), grid_choices(), st.sampled_from(KEYS),
       st.sampled_from(STOP_RULES))
def test_each_half_is_the_references_on_random_maps(grid: Grid, sem: Semantics, key: str,
                                                   stop: str) -> None:
    assert_follows(grid, key, sem.replace(stop=stop))


@bidirectional
@given(graphs(), st.sampled_from(KEYS), st.sampled_from(STOP_RULES),
       st.sampled_from(("zero", "euclidean")))
def test_each_half_is_the_references_on_random_graphs(g: dict, key: str, stop: str,
                                                      heuristic: str) -> None:
    """Roads one way are taken against their way backward."""
    assert_follows(app_graph(g), key, Semantics(order=("file",), stop=stop,
                                                heuristic=heuristic))


@pytest.mark.parametrize("stop", STOP_RULES)
def test_the_trap_map_s_two_answers(stop: str) -> None:
    from tui_search.engine.maps.load import load_board

    run = BiRun(load_board("maps/pathfinding-js-28.txt"), "biastar", Semantics(stop=stop))
    run.goto(10**6)
    assert run.at_end and run.found
    cost, cell = (13.66, (8, 3)) if stop == "proven" else (14.24, (7, 3))
    assert round(run.path_cost(), 2) == cost and run.meeting() == cell
    assert run.why().startswith("the best meeting" if stop == "proven" else "both searches")
    run.goto(3)
    assert run.half_steps(3) == (2, 1) and run.meeting() is None


def test_a_jump_is_the_same_as_stepping() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    stepped, jumped = BiRun(grid, "biastar"), BiRun(grid, "biastar")
    while stepped.forward():
        jumped.goto(stepped.k)
        for back in (0, 1):
            assert run_frontier(jumped, back) == run_frontier(stepped, back)
            assert jumped.halves[back].k == stepped.halves[back].k


def test_a_run_that_gives_up_finds_nothing() -> None:
    run = BiRun(grid_from_rows(TUTORIAL_ROWS), "bibfs", max_steps=2)
    run.goto(10)
    assert run.k == 2 and run.at_end and run.gave_up and not run.found
    assert run.path() is None and run.why() == ""


def test_a_graph_with_two_goals_is_refused_in_the_app() -> None:
    g = Graph.of(["A", "B", "C"], [], start="A", goals=("B", "C"))
    assert "2 goals" in app_refusal(g)
    with pytest.raises(ValueError, match="2 goals"):
        BiRun(g, "bibfs")


def test_no_proof_is_claimed_with_a_heuristic_that_overestimates() -> None:
    """Manhattan with diagonal moves overestimates: the front-to-end bound proves nothing,
    and here the answer is not the cheapest (UCS: 8.24), which the reason says it may not be."""
    from tui_search.engine.maps.load import parse_map_text

    grid = parse_map_text("G.....#...\n...##.#..#\n.#.##.#.#.\n.......S#.\n", "m.txt")
    run = BiRun(grid, "biastar", Semantics(heuristic="manhattan"))
    run.goto(10**6)
    assert round(run.path_cost(), 2) == 9.07
    assert "proven" not in run.why() and "it may not be the cheapest" in run.why()
    octile = BiRun(grid, "biastar", Semantics())
    octile.goto(10**6)
    assert round(octile.path_cost(), 2) == 8.24 and "is proven the cheapest" in octile.why()

"""Bidirectional search (engine/search/bidirectional/, the reference): with the ``proven``
stopping rule its path costs what uniform-cost search's does (bidirectional BFS: BFS's fewest
moves) on random maps and random graphs, one-way roads included; with ``first-meeting`` it
finds a path whenever there is one, never a cheaper one; its paths are legal; its steps
alternate forward and backward; and the choices it does not take are refused."""

from __future__ import annotations

import itertools

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.test_graph_search import app_graph, graphs
from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import DIRECTIONS, Grid
from tui_search.engine.search.bidirectional.loop import (
    BidirectionalSearch,
    stream_bidirectional,
)
from tui_search.engine.search.choices import CORNER_RULES, TURN_RULES, Semantics
from tui_search.engine.search.heuristics import HEURISTICS, admissible
from tui_search.engine.search.reference import stream
from tui_search.engine.search.registry import get_algorithm

BIG = 10**6
UCS, BFS = get_algorithm("ucs"), get_algorithm("bfs")
bidirectional = settings(max_examples=150, deadline=None,
                         suppress_health_check=[HealthCheck.too_slow])


@st.composite
def grid_choices(draw: st.DrawFn) -> Semantics:
    """Any moves in any order (one-way ones too: backward, a move is taken against its
    way), any corner rule, an admissible heuristic."""
    order = tuple(draw(st.lists(st.sampled_from(DIRECTIONS), min_size=1, max_size=8,
                                unique=True)))
    heuristic = draw(st.sampled_from([h for h in sorted(HEURISTICS) if admissible(h, order)]))
    return Semantics(order=order, corners=draw(st.sampled_from(CORNER_RULES)),
                     heuristic=heuristic, turn=draw(st.sampled_from(TURN_RULES)))


def assert_legal(board: Grid | Graph, sem: Semantics, path: list, moves: list[str]) -> None:
    """``path`` goes from the start to the goal by legal moves, named by ``moves``."""
    if isinstance(board, Graph):
        assert path[0] == board.start and path[-1] in board.goals
        for a, b in itertools.pairwise(path):
            assert b in {name for name, _, _ in board.successors(a)}
        assert moves == path[1:]
        return
    assert path[0] == board.start and path[-1] == board.goal
    assert len(moves) == len(path) - 1
    for (a, b), move in zip(itertools.pairwise(path), moves, strict=True):
        legal = dict(board.neighbours(a, sem.order, sem.corners))
        assert legal.get(move) == b


@bidirectional
@given(random_grids(max_side=10, costs=True), grid_choices())
def test_proven_costs_equal_uniform_cost_searchs_on_random_maps(grid: Grid,
                                                                sem: Semantics) -> None:
    """Under either turn: a step each in turn, or the smaller frontier's."""
    ucs = stream(grid, get_algorithm("ucs"), sem.fitted(UCS), BIG)
    bfs = stream(grid, get_algorithm("bfs"), sem.fitted(BFS), BIG)
    for key in ("biucs", "biastar"):
        out = stream(grid, get_algorithm(key), sem, BIG)
        assert out.found == ucs.found, key
        if ucs.cost is not None:
            assert out.cost == pytest.approx(ucs.cost, abs=1e-9), key
            assert out.path is not None and out.moves is not None
            assert_legal(grid, sem, out.path, out.moves)
    out = stream(grid, get_algorithm("bibfs"), sem, BIG)
    assert out.found == bfs.found
    assert out.length == bfs.length  # BFS's cost is its moves


@bidirectional
@given(random_grids(max_side=10, costs=True), grid_choices())
def test_first_meeting_finds_a_path_never_cheaper_than_the_optimum(grid: Grid,
                                                                   sem: Semantics) -> None:
    ucs = stream(grid, get_algorithm("ucs"), sem.fitted(UCS), BIG)
    bfs = stream(grid, get_algorithm("bfs"), sem.fitted(BFS), BIG)
    first = sem.replace(stop="first-meeting")
    for key, best in (("biucs", ucs), ("biastar", ucs), ("bibfs", bfs)):
        out = stream(grid, get_algorithm(key), first, BIG)
        assert out.found == best.found, key
        if out.path is not None:
            assert out.moves is not None and out.cost is not None and best.cost is not None
            assert_legal(grid, first, out.path, out.moves)
            assert out.length is not None and bfs.length is not None
            assert out.length >= bfs.length  # never fewer moves than BFS's
            if key != "bibfs":  # BFS's path is not the cheapest: only the fewest moves
                assert out.cost >= best.cost - 1e-9


@bidirectional
@given(graphs(), st.sampled_from(("zero", "euclidean")), st.sampled_from(TURN_RULES))
def test_proven_costs_equal_uniform_cost_searchs_on_random_graphs(g, heuristic: str,
                                                                  turn: str) -> None:
    """Roads one way are taken against their way backward; closed nodes are never entered."""
    graph = app_graph(g)
    sem = Semantics(order=("file",), heuristic=heuristic, turn=turn)
    ucs = stream(graph, get_algorithm("ucs"), sem.fitted(UCS), BIG)
    bfs = stream(graph, get_algorithm("bfs"), sem.fitted(BFS), BIG)
    for key in ("biucs", "biastar"):
        for stop in ("proven", "first-meeting"):
            out = stream(graph, get_algorithm(key), sem.replace(stop=stop), BIG)
            assert out.found == ucs.found
            if out.path is not None:
                assert out.moves is not None and ucs.cost is not None
                assert_legal(graph, sem, out.path, out.moves)
                assert not set(out.path) & set(graph.closed)
                if stop == "proven":
                    assert out.cost == pytest.approx(ucs.cost, abs=1e-9)
                else:
                    assert out.cost is not None and out.cost >= ucs.cost - 1e-9
    out = stream(graph, get_algorithm("bibfs"), sem, BIG)
    assert out.length == bfs.length


@bidirectional
@given(random_grids(max_side=8), st.sampled_from(("bibfs", "biucs", "biastar")),
       st.sampled_from(("proven", "first-meeting")))
def test_the_steps_alternate_forward_then_backward(grid: Grid, key: str, stop: str) -> None:
    """One step each in turn, the forward search first (a discarded step takes its turn);
    a step's node is the forward search's from the start's side, and the first step of
    each direction expands its root."""
    search = BidirectionalSearch(grid, get_algorithm(key), Semantics(stop=stop))
    steps = list(search)
    assert [s.direction for s in steps] == [("forward", "backward")[i % 2]
                                            for i in range(len(steps))]
    assert [s.index for s in steps] == list(range(1, len(steps) + 1))
    if steps:
        assert steps[0].node.cell == grid.start
    if len(steps) > 1:
        assert steps[1].node.cell == grid.goal
    assert sum(s.found for s in steps) == (search.stopped_by == "meeting" and bool(steps))


@bidirectional
@given(random_grids(max_side=8, costs=True), st.sampled_from(("bibfs", "biucs", "biastar")),
       st.sampled_from(("proven", "first-meeting")))
def test_the_smaller_frontier_takes_the_next_step(grid: Grid, key: str, stop: str) -> None:
    """``turn smaller``: each step is the search's whose frontier was smaller before it (the
    forward's on a tie)."""
    sem = Semantics(stop=stop, turn="smaller")
    search = BidirectionalSearch(grid, get_algorithm(key), sem)
    sizes = (len(search.forward.queue), len(search.backward.queue))
    for step in search:
        if not (sizes[0] or sizes[1]):  # before the roots are pushed: the first step
            sizes = (1, 1)
        assert step.direction == ("backward" if sizes[0] > sizes[1] else "forward")
        sizes = (len(search.forward.queue), len(search.backward.queue))


def test_the_start_is_the_goal() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    grid.goal = grid.start
    for stop in ("proven", "first-meeting"):
        out = stream_bidirectional(grid, get_algorithm("biastar"), Semantics(stop=stop), BIG)
        assert out.path == [grid.start] and out.moves == [] and out.cost == 0.0
        assert out.expanded == 0 and out.generated == 2


def test_no_path_stops_when_a_frontier_empties() -> None:
    grid = grid_from_rows(["S#.", "##.", "..G"])
    search = BidirectionalSearch(grid, get_algorithm("bibfs"), Semantics())
    steps = list(search)
    assert search.path is None and search.stopped_by == "empty"
    assert len(steps) == 1  # the start has no move: its frontier empties at once


def test_a_run_that_gives_up_answers_nothing() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    out = stream_bidirectional(grid, get_algorithm("bibfs"), Semantics(), 3)
    assert out.gave_up and out.path is None and out.expanded == 3


@pytest.mark.parametrize(("key", "changes", "words"), [
    ("bibfs", {"visit": "expand"}, "visit rule does not apply"),
    ("biucs", {"tree_search": True}, "no tree search"),
    ("biastar", {"goal_test": "expand"}, "no goal test"),
    ("biastar", {"weight": 2.0}, "a weight applies to A*"),
    ("biastar", {"ties": "lifo"}, "plain choices"),
    ("astar", {"stop": "first-meeting"}, "a stopping rule or a turn applies to a bidirect"),
    ("ucs", {"turn": "smaller"}, "a stopping rule or a turn applies to a bidirectional"),
])
def test_choices_a_bidirectional_search_does_not_take(key: str, changes: dict,
                                                      words: str) -> None:
    sem = Semantics().replace(**changes)
    with pytest.raises(ValueError, match=words):
        sem.check(get_algorithm(key))
    assert sem.fitted(get_algorithm(key)).refusal(get_algorithm(key)) == ""


def test_the_json_names_the_stopping_rule_of_a_bidirectional_search_only() -> None:
    sem = Semantics(stop="first-meeting")
    assert sem.as_json(get_algorithm("biastar"))["stop"] == "first-meeting"
    assert "stop" not in Semantics().as_json(get_algorithm("astar"))
    assert sem.differences(get_algorithm("biastar")) == ["stop at the first meeting"]
    both = sem.replace(turn="smaller")
    assert both.as_json(get_algorithm("bibfs"))["turn"] == "smaller"
    assert both.differences(get_algorithm("bibfs")) == ["stop at the first meeting",
                                                        "the smaller frontier first"]

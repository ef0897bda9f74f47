"""The choices of published code (ties, a cost tolerance, a closed set, recursion, tree search
with no path check, an unmarked start, a node expanded again): the loop that records them
equals the reference, array for array, under both cores (either core routes them to it), and
the run's position and frontier model follow them; then what each choice promises."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.cores import CORES, using_core
from tests.engine.test_core import (
    LIMIT,
    assert_expanded_as_the_reference,
    recorded_arrays,
    reference_arrays,
)
from tests.engine.test_run import snapshot
from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.maps.grid import DIRECTIONS, Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import (
    CORNER_RULES,
    GOAL_TESTS,
    RECURSIVE_FORMS,
    TIE_RULES,
    Semantics,
)
from tui_search.engine.search.heuristics import CHEAPER_BY, HEURISTICS
from tui_search.engine.search.loops.dispatch import loop_for
from tui_search.engine.search.loops.published import published
from tui_search.engine.search.reference import ReferenceSearch, stream
from tui_search.engine.search.registry import ALGORITHMS, get_algorithm
from tui_search.engine.search.space import GridSpace


@st.composite
def published_semantics(draw, algorithm: str | None = None) -> tuple[str, Semantics]:
    """An algorithm and choices with at least one choice of published code set (drawn
    among those that apply to it)."""
    key = algorithm or draw(st.sampled_from(sorted(ALGORITHMS)))
    algo = get_algorithm(key)
    moves = draw(st.lists(st.sampled_from(DIRECTIONS), min_size=1, max_size=8, unique=True))
    recursive = draw(st.sampled_from(("", *RECURSIVE_FORMS))) if key in ("dfs", "iddfs") else ""
    tree = draw(st.booleans())
    path_check = draw(st.booleans()) if tree else True
    visit = "generate"
    if not (tree or recursive or algo.iterative or algo.weighted):
        visit = draw(st.sampled_from(("generate", "expand", "expand-again")))
    mark_start = True
    if not (tree or recursive) and visit == "generate":
        mark_start = draw(st.booleans())
    ties, tolerance, reopen = "fifo", CHEAPER_BY, True
    if algo.queued:
        allowed = [t for t in TIE_RULES if not ((t.endswith("-h") and not algo.informed)
                                                or (t.endswith("-g") and algo.priority == "g"))]
        ties = draw(st.sampled_from(allowed))
        tolerance = draw(st.sampled_from((CHEAPER_BY, 0.0)))
        reopen = draw(st.booleans())
    sem = Semantics(order=tuple(moves), corners=draw(st.sampled_from(CORNER_RULES)),
                    visit=visit, goal_test=draw(st.sampled_from((None, *GOAL_TESTS))),
                    tree_search=tree, heuristic=draw(st.sampled_from(sorted(HEURISTICS))),
                    ties=ties, cost_tolerance=tolerance, reopen=reopen, recursive=recursive,
                    path_check=path_check, mark_start=mark_start,
                    flip_even=draw(st.booleans()))
    if sem.plain:  # none drawn: set one that applies
        sem = sem.replace(**draw(st.sampled_from(_one_published(key, sem))))
    return key, sem


def _one_published(key: str, sem: Semantics) -> list[dict]:
    algo = get_algorithm(key)
    if sem.tree_search:
        return [{"path_check": False}]
    out: list[dict] = [{"flip_even": True}]
    out += [{"mark_start": False}] if sem.visit == "generate" else []
    if algo.queued:
        out += [{"ties": "node"}, {"ties": "lifo"}, {"cost_tolerance": 0.0}, {"reopen": False}]
    elif not algo.iterative:
        out += [{"visit": "expand-again", "mark_start": True}]
    if key in ("dfs", "iddfs") and sem.visit == "generate":
        out += [{"recursive": "neighbours", "mark_start": True},
                {"recursive": "calls", "mark_start": True}]
    return out


choices = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@pytest.mark.parametrize("core_name", CORES)
@choices
@given(random_grids(max_side=8, costs=True), published_semantics())
def test_the_published_choices_are_recorded_as_the_reference_runs_them(core_name: str,
                                                                       grid: Grid,
                                                                       choice) -> None:
    key, sem = choice
    assert not sem.plain
    with using_core(core_name):
        assert getattr(loop_for(get_algorithm(key), sem), "func", None) is published
        recorded = recorded_arrays(Run(grid, key, sem, LIMIT))
    assert recorded == reference_arrays(grid, key, sem, LIMIT)


@choices
@given(random_grids(max_side=8, costs=True), published_semantics())
def test_the_streamed_outcome_equals_the_recorded_one_under_them(grid: Grid, choice) -> None:
    key, sem = choice
    assert stream(grid, get_algorithm(key), sem, LIMIT) == Run(grid, key, sem, LIMIT).outcome()


@settings(max_examples=150, deadline=None)
@given(random_grids(max_side=6, costs=True), published_semantics(),
       st.lists(st.integers(0, 400), min_size=1, max_size=5), st.sampled_from([0, 3, 10**9]))
def test_the_position_and_frontier_follow_them(grid, choice, targets, rebuild) -> None:
    """A jump (stepping either way, or a bulk rebuild) lands where stepping forwards does,
    the frontier model in the order the search takes its entries: the next out is the
    event the next step expands (a recursion's first call, a tie rule's pick)."""
    key, sem = choice
    run = Run(grid, key, sem, 400)
    run.REBUILD_AFTER = rebuild
    run.advance()
    for t in targets:
        k = t % (run.total + 1)
        run.goto(k)
        fresh = Run(grid, key, sem, 400)
        fresh.advance()
        for _ in range(k):
            fresh.forward()
        assert snapshot(run) == snapshot(fresh)
        if k < run.total and run.steps.first_of_iteration(run.steps.iteration_of(k + 1)) != k + 1:
            assert run.now.frontier(0, 1) == [run.steps.expanded_event(k + 1)]
    assert_expanded_as_the_reference(grid, key, sem, targets, rebuild)


# -- what the choices promise ------------------------------------------------------------------


def test_a_tie_goes_to_the_smallest_cell_under_ties_node() -> None:
    """Moving E or S from the middle of an open map ties on f for A* with Manhattan: the
    older entry (E, pushed first) comes out under fifo, the smallest (x, y) under node, the
    newer under lifo."""
    grid = grid_from_rows(["...", ".S.", "..G"])
    order = ("N", "W", "E", "S")
    for ties, second in (("fifo", (2, 1)), ("node", (1, 2)), ("lifo", (1, 2))):
        sem = Semantics(order=order, heuristic="manhattan", ties=ties)
        steps = list(ReferenceSearch(grid, get_algorithm("astar"), sem))
        assert steps[1].node.cell == second, ties


def test_without_re_opening_a_closed_cell_is_never_pushed_again() -> None:
    """Manhattan beside diagonals is inconsistent: A* re-opens a cell; with a closed set it
    does not, and pushes no cell after its expansion."""
    rows = ["S..#.", ".#..#", "....#", "#.###", ".#.#G"]
    grid = grid_from_rows(rows)
    sem = Semantics(heuristic="manhattan")
    reopened = _pushed_after_expansion(grid, sem)
    assert reopened
    assert not _pushed_after_expansion(grid, sem.replace(reopen=False))


def _pushed_after_expansion(grid: Grid, sem: Semantics) -> list:
    expanded, out = set(), []
    for step in ReferenceSearch(grid, get_algorithm("astar"), sem):
        if not step.discarded:
            expanded.add(step.node.cell)
        out += [s.cell for s in step.successors if s.cell in expanded]
    return out


def test_an_unmarked_start_is_pushed_again() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    for key in ("bfs", "dfs", "ucs", "astar"):
        steps = list(ReferenceSearch(grid, get_algorithm(key), Semantics(mark_start=False)))
        assert any(s.cell == grid.start for step in steps for s in step.successors), key


def test_the_order_reversed_on_every_other_cell() -> None:
    """Under flip_even a cell whose x + y is even takes its moves in the reverse order, every
    other cell in the order itself; the moves and their costs are the same."""
    grid = grid_from_rows(["S...", "....", "...G"])
    order = ("E", "W", "N", "S")
    plain = GridSpace(grid, Semantics(order=order), False)
    flipped = GridSpace(grid, Semantics(order=order, flip_even=True), False)
    for cell in ((1, 1), (2, 1), (0, 0), (1, 0), (3, 2)):
        want = plain.successors(cell)
        got = flipped.successors(cell)
        assert got == (want[::-1] if sum(cell) % 2 == 0 else want), cell
    assert not Semantics(flip_even=True).plain
    with pytest.raises(ValueError, match="grid's"):
        Semantics(order=("file",), flip_even=True)


def test_expanded_again_expands_a_cell_twice_and_discards_nothing() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    steps = list(ReferenceSearch(grid, get_algorithm("bfs"), Semantics(visit="expand-again")))
    cells = [step.node.cell for step in steps]
    assert len(cells) > len(set(cells)) and not any(step.discarded for step in steps)


def test_no_path_check_pushes_the_parent_back() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    sem = Semantics(tree_search=True, path_check=False)
    steps = list(ReferenceSearch(grid, get_algorithm("bfs"), sem))
    assert grid.start in [s.cell for s in steps[1].successors]


def test_the_calls_form_lists_the_cells_recursed_into() -> None:
    """The neighbours form lists what the call will try; the calls form what it did: the
    same cells expanded, in the same order, none discarded."""
    grid = grid_from_rows(["S..", ".#.", "..G"])
    dfs = get_algorithm("dfs")
    neighbours = list(ReferenceSearch(grid, dfs, Semantics(recursive="neighbours",
                                                           goal_test="expand")))
    calls = list(ReferenceSearch(grid, dfs, Semantics(recursive="calls", goal_test="expand")))
    assert [s.node.cell for s in neighbours if not s.discarded] == [s.node.cell for s in calls]
    assert [[c.cell for c in s.successors] for s in calls] == [
        [(0, 1)], [(0, 2)], [(1, 2)], [(2, 2)], []]
    assert [c.cell for c in neighbours[0].successors] == [(0, 1), (1, 0)]


def test_the_new_choices_are_refused_where_they_do_not_apply() -> None:
    bfs, ucs, astar = (get_algorithm(k) for k in ("bfs", "ucs", "astar"))
    assert "priority queue" in Semantics(ties="node").refusal(bfs)
    assert "h" in Semantics(ties="low-h").refusal(ucs)
    assert Semantics(ties="low-h").refusal(astar) == ""
    assert "depth-first" in Semantics(recursive="calls").refusal(ucs)
    for bad in ({"recursive": "calls", "visit": "expand"}, {"path_check": False},
                {"cost_tolerance": -1.0}, {"ties": "random"}):
        with pytest.raises(ValueError):
            Semantics(**bad)

"""IDA* (``-a idastar``): depth-first within limits on f = g + h, each the smallest f cut off
by the iteration before.  With an admissible heuristic its path costs what A*'s costs, in
both forms (graph search: a cell pushed again within an iteration only when reached
cheaper; tree search: only the node's own path skipped); weighted, at most W times that.
The app's recorded run is the reference loop recorded (``tests/engine/test_core.py`` holds
it equal, array for array, with IDA* among the algorithms drawn)."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from tests.engine.test_search import random_grids
from tests.engine.test_weighted import WEIGHTS, admissible_choices
from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.maps.graph_file import load_graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.loops.dispatch import loop_for
from tui_search.engine.search.reference import ReferenceSearch, stream
from tui_search.engine.search.registry import get_algorithm

IDASTAR, ASTAR = get_algorithm("idastar"), get_algorithm("astar")
#: Tree search is exponential: a run past this many steps is not compared (few are).
STEPS = 200_000
ida = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@ida
@given(random_grids(max_side=9, costs=True), admissible_choices(), st.booleans())
def test_idastar_costs_what_astar_costs_with_an_admissible_heuristic(
        grid: Grid, sem: Semantics, tree: bool) -> None:
    """Both forms, on random maps with terrain, any moves and corner rule."""
    sem = sem.replace(reopen=True, tree_search=tree)
    astar = stream(grid, ASTAR, sem.replace(tree_search=False), 10**6)
    ida_star = stream(grid, IDASTAR, sem, STEPS)
    assume(not ida_star.gave_up)
    assert ida_star.found == astar.found
    if astar.cost is not None:
        assert ida_star.cost == pytest.approx(astar.cost, abs=1e-9)


@ida
@given(random_grids(max_side=9, costs=True), admissible_choices(), WEIGHTS)
def test_weighted_idastar_costs_at_most_w_times_the_optimum(grid: Grid, sem: Semantics,
                                                            weight: float) -> None:
    sem = sem.replace(reopen=True)
    best = stream(grid, ASTAR, sem, 10**6)
    heavy = stream(grid, IDASTAR, sem.replace(weight=weight), STEPS)
    assume(not heavy.gave_up)
    assert heavy.found == best.found
    if best.cost is not None:
        assert heavy.cost is not None
        assert best.cost - 1e-9 <= heavy.cost <= weight * best.cost + 1e-9


def limits(board: Grid, sem: Semantics) -> list[float]:
    """Each iteration's limit on f, as the reference ran them."""
    out = []
    for step in ReferenceSearch(board, IDASTAR, sem):
        if step.index == 1 or step.new_root is not None:
            assert step.f_limit is not None
            out.append(round(step.f_limit, 2))
    return out


def test_the_limits_start_at_h_of_the_start_and_rise_to_the_smallest_f_cut_off() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    assert limits(grid, Semantics()) == [5.83, 6.41, 7.0, 7.24, 7.83, 8.07, 8.41, 8.66]
    search = ReferenceSearch(grid, IDASTAR, Semantics())
    steps = list(search)
    assert search.goal is not None and search.iterations == 8
    assert round(search.space.path_cost(search.goal.path()) or 0, 2) == 8.66
    for step in steps:  # a step is cut off when its f is over the limit, with no successors
        assert step.f_limit is not None
        f = step.node.g + search.space.estimate()(step.node.cell)
        if f > step.f_limit + 1e-9:
            assert not step.successors and not step.found and step.next_limit <= f
    # the next limit, as it goes, is the smallest f cut off so far in the iteration
    assert steps[-1].found and steps[-1].f_limit == pytest.approx(8.65685424949238)


def test_with_no_path_it_stops_when_an_iteration_cuts_nothing_off() -> None:
    grid = grid_from_rows(["S.#..", "..#.G", "..#.."])
    out = stream(grid, IDASTAR, Semantics(), 10**6)
    assert out.path is None and not out.gave_up
    tree = stream(grid, IDASTAR, Semantics(tree_search=True), 3000)
    assert tree.path is None and not tree.gave_up  # every simple path tried, none over


def test_the_graph_form_pushes_a_cell_again_only_when_reached_cheaper() -> None:
    """Within an iteration the graph form never pushes a cell with a g no lower than it was
    pushed with before; the tree form skips only the node's own path."""
    grid = grid_from_rows(TUTORIAL_ROWS)
    for tree in (False, True):
        best: dict = {}
        seen_again = False
        for step in ReferenceSearch(grid, IDASTAR, Semantics(tree_search=tree)):
            if step.new_root is not None:
                best = {step.new_root.cell: 0.0}
            if step.index == 1:
                best = {grid.start: 0.0}
            for s in step.successors:
                assert not step.node.on_path(s.cell)
                if s.cell in best:
                    seen_again = True
                    if not tree:
                        assert s.g < best[s.cell] - 1e-9
                best[s.cell] = min(s.g, best.get(s.cell, s.g))
        assert seen_again


def test_the_recorded_run_says_each_iterations_limit_and_the_next() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    run = Run(grid, "idastar", Semantics(), 10**6)
    run.advance()
    assert run.outcome().cost == pytest.approx(8.65685424949238)
    assert run.steps.f_limits(0) == (pytest.approx(5.82842712474619), float("inf"))
    first_of_second = run.steps.first_of_iteration(1)
    limit, nxt = run.steps.f_limits(first_of_second - 1) or (0, 0)
    assert (round(limit, 2), round(nxt, 2)) == (5.83, 6.41)  # the first iteration's last step
    assert run.steps.f_limits(first_of_second)[0] == pytest.approx(6.414213562373095)


def test_its_loop_is_the_reference_recorded_and_it_runs_on_graphs() -> None:
    assert getattr(loop_for(IDASTAR, Semantics()), "func", None).__name__ == "published"
    romania = load_graph(Path(__file__).parents[2] / "maps" / "graphs" / "romania.graph")
    for tree in (False, True):
        sem = Semantics(order=("file",), heuristic="table", tree_search=tree)
        out = stream(romania, IDASTAR, sem, 10**5)
        assert out.cost == 418 and out.path is not None
        assert Run(romania, "idastar", sem, 10**5).outcome() == out


@pytest.mark.parametrize(("change", "words"), [
    ({"ties": "lifo"}, "ties apply to a priority queue's"),
    ({"reopen": False}, "re-opening apply to a priority queue's"),
    ({"recursive": "neighbours"}, "recursion is a depth-first search's"),
    ({"visit": "expand"}, "the visit rule does not apply to IDA*"),
])
def test_the_priority_queues_choices_and_recursion_do_not_apply(change: dict,
                                                                words: str) -> None:
    assert words in Semantics(**change).refusal(IDASTAR)
    assert Semantics(**change).fitted(IDASTAR).refusal(IDASTAR) == ""
    assert Semantics(weight=2).refusal(IDASTAR) == ""  # weighted IDA*: f = g + 2·h


IDA_EXERCISE = """\
title = "The price of a small stack"
text = "IDA* finds A*'s path: make it expand more than four times A*'s nodes."
map = "tutorial.txt"
searches = ["astar", "idastar"]
edits = ["obstacles"]
solved = "idastar.cost == astar.cost and idastar.expanded > 4 * astar.expanded"
"""


def test_an_exercise_names_idastar() -> None:
    from tests.helpers import MAPS
    from tui_search.engine.course.exercise_file import parse_exercise
    from tui_search.engine.course.grading import grade

    exercise = parse_exercise(IDA_EXERCISE, str(MAPS / "ida.toml"))
    assert [name for name, _ in exercise.searches] == ["astar", "idastar"]
    verdict = grade(exercise, grid_from_rows(TUTORIAL_ROWS))
    assert verdict.solved  # 97 steps against A*'s 16, the same cost 8.66
    assert verdict.figures["idastar.expanded"] == 97
    assert verdict.figures["idastar.cost"] == pytest.approx(verdict.figures["astar.cost"])
    open_map = grid_from_rows(["S...", "....", "...G"])
    assert not grade(exercise, open_map).solved  # h is exact there: few iterations


def test_by_hand_a_node_over_the_limit_adds_nothing() -> None:
    from tui_search.engine.traces.hand import HandRun

    hand = HandRun(grid_from_rows(TUTORIAL_ROWS), "idastar", Semantics())
    assert hand.pick((0, 0)).ok and hand.mark((0, 1)).ok and hand.end_step().ok
    assert hand.pick((0, 1)).ok  # f 6.41, over the first limit 5.83
    assert hand.hint_why().startswith("IDA* adds nothing from (0,1): its f = 6.41 is over the "
                                      "limit 5.83")
    told = hand.mark((0, 2))
    assert not told.ok and told.mistake is not None and told.mistake.cause == "cut-off"
    assert hand.end_step().ok and hand.pick((0, 0)).ok  # the second iteration, from START

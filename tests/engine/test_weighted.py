"""Weighted A* (``weight``: f = g + W·h): every loop records what the reference does under a
weight, a weight of 1 is A* itself, and with an admissible heuristic the path costs at most W
times the optimum (uniform-cost search's cost)."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.engine.cores import CORES, using_core
from tests.engine.test_core import LIMIT, recorded_arrays, reference_arrays, semantics
from tests.engine.test_search import random_grids
from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.maps.grid import DIRECTIONS, Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import CORNER_RULES, DEFAULT_SEMANTICS, Semantics
from tui_search.engine.search.compare import parse_compare
from tui_search.engine.search.heuristics import HEURISTICS, admissible
from tui_search.engine.search.pseudocode import pseudocode
from tui_search.engine.search.reference import stream
from tui_search.engine.search.registry import get_algorithm

ASTAR = get_algorithm("astar")
#: Weights drawn: the settings screen's, and any float from 1 to 6.
WEIGHTS = st.one_of(st.sampled_from((1.0, 1.5, 2.0, 3.0)),
                    st.floats(1.0, 6.0, allow_nan=False, allow_infinity=False))
weighted = settings(max_examples=150, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])


@pytest.mark.parametrize("core_name", CORES)
@weighted
@given(random_grids(max_side=8, costs=True), semantics("astar"), WEIGHTS)
def test_every_loop_records_weighted_astar_as_the_reference(core_name: str, grid: Grid,
                                                            choice, weight: float) -> None:
    """Both cores, array for array, under any weight and any other choice (tree search,
    corner rules, goal tests, heuristics, terrain)."""
    key, sem = choice
    sem = sem.replace(weight=weight)
    with using_core(core_name):
        recorded = recorded_arrays(Run(grid, key, sem, LIMIT))
    assert recorded == reference_arrays(grid, key, sem, LIMIT)


@st.composite
def admissible_choices(draw) -> Semantics:
    """Graph search with the goal tested on expansion (A*'s own) and an admissible
    heuristic (each here is consistent too): the choices under which A* is optimal, with
    re-opening or a closed set (weighted A* keeps its bound either way)."""
    order = tuple(draw(st.lists(st.sampled_from(DIRECTIONS), min_size=1, max_size=8,
                                unique=True)))
    heuristic = draw(st.sampled_from([h for h in sorted(HEURISTICS) if admissible(h, order)]))
    return Semantics(order=order, corners=draw(st.sampled_from(CORNER_RULES)),
                     heuristic=heuristic, reopen=draw(st.booleans()))


@weighted
@given(random_grids(max_side=12, costs=True), admissible_choices(), WEIGHTS)
def test_weighted_astar_costs_at_most_w_times_the_optimum(grid: Grid, sem: Semantics,
                                                          weight: float) -> None:
    ucs = stream(grid, get_algorithm("ucs"), sem, 10**6)
    astar = stream(grid, ASTAR, sem, 10**6)
    heavy = stream(grid, ASTAR, sem.replace(weight=weight), 10**6)
    assert heavy.found == astar.found == ucs.found
    if ucs.cost is not None:
        assert heavy.cost is not None and astar.cost is not None
        assert astar.cost == pytest.approx(ucs.cost, abs=1e-9)
        assert heavy.cost <= weight * ucs.cost + 1e-9
        assert heavy.cost >= ucs.cost - 1e-9


@weighted
@given(random_grids(max_side=8, costs=True), semantics("astar"))
def test_a_weight_of_one_is_astar_exactly(grid: Grid, choice) -> None:
    """Weight 1 is no choice at all: the same value as A*'s choices, the same records and
    costs bit for bit, the same JSON but its weight, the same pseudocode."""
    key, sem = choice
    one = sem.replace(weight=1)
    assert one == sem and one.weight == 1.0 and not one.differences(ASTAR)[len(
        sem.differences(ASTAR)):]
    assert recorded_arrays(Run(grid, key, one, LIMIT)) == reference_arrays(grid, key, sem, LIMIT)
    assert pseudocode(ASTAR, one) == pseudocode(ASTAR, sem)


def test_a_weight_above_one_changes_the_tutorial_run_and_keeps_the_bound() -> None:
    grid = grid_from_rows(TUTORIAL_ROWS)
    plain = Run(grid, "astar", DEFAULT_SEMANTICS, LIMIT).outcome()
    heavy = Run(grid, "astar", Semantics(weight=5.0), LIMIT).outcome()
    assert heavy.semantics.weight == 5.0 and plain.semantics.weight == 1.0
    assert heavy.expanded < plain.expanded
    assert plain.cost is not None and heavy.cost is not None
    assert plain.cost <= heavy.cost <= 5 * plain.cost


def test_the_weight_is_a_choice_of_astar_only() -> None:
    for bad in (0.5, 0.0, -1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="a number 1 or more"):
            Semantics(weight=bad)
    sem = Semantics(weight=2.0)
    for key in ("bfs", "dfs", "iddfs", "ucs", "greedy"):
        assert "a weight applies to A*" in sem.refusal(get_algorithm(key))
        assert sem.fitted(get_algorithm(key)).weight == 1.0
    assert sem.refusal(ASTAR) == "" and sem.fitted(ASTAR) == sem
    assert sem.differences(ASTAR) == ["weight 2"]
    assert sem.as_json(ASTAR)["weight"] == 2.0
    assert sem.as_json(get_algorithm("ucs"))["weight"] is None
    assert Semantics(weight=1.5).differences() == ["weight 1.5"]


def test_the_pseudocode_says_f_is_g_plus_w_h() -> None:
    code = pseudocode(ASTAR, Semantics(weight=2.0))
    text = "\n".join(line.text for line in code.lines)
    assert "f = g + 2·h" in text and "(weight 2)" in code.title
    assert "f = g + h" in "\n".join(line.text for line in pseudocode(ASTAR, Semantics()).lines)


def test_compare_names_a_weight() -> None:
    contenders = parse_compare("ucs,astar:w=2,astar:manhattan:w=1.5")
    assert [c.label for c in contenders] == ["UCS", "A* (w=2)", "A* (manhattan, w=1.5)"]
    assert [c.semantics.weight for c in contenders] == [1.0, 2.0, 1.5]
    for bad, said in (("ucs:w=2,astar", "applies to astar only"),
                      ("astar:w=0.5,ucs", "a number 1 or more"),
                      ("astar:w=x,ucs", "a number 1 or more"),
                      ("astar:octile:zero,ucs", "one heuristic")):
        with pytest.raises(ValueError, match=said):
            parse_compare(bad)
    # the choices' weight is A*'s alone: the others take 1
    fitted = parse_compare("ucs,astar", Semantics(weight=3.0))
    assert [c.semantics.weight for c in fitted] == [1.0, 3.0]


WEIGHTED_EXERCISE = """\
title = "How far from the cheapest?"
text = "Move obstacles so that weighted A* (w=2) pays more than uniform-cost search."
map = "tutorial.txt"
searches = ["ucs", "astar:w=2", "astar:w=1.5"]
edits = ["obstacles"]
solved = "astar_w_2.cost > ucs.cost and astar_w_2.cost <= 2 * ucs.cost and astar_w_1_5.found"
"""


def test_an_exercise_names_weighted_astar_astar_w_2() -> None:
    from tests.helpers import MAPS
    from tui_search.engine.course.exercise_file import parse_exercise
    from tui_search.engine.course.grading import grade
    from tui_search.engine.maps.load import parse_map_text

    exercise = parse_exercise(WEIGHTED_EXERCISE, str(MAPS / "weighted.toml"))
    assert [name for name, _ in exercise.searches] == ["ucs", "astar_w_2", "astar_w_1_5"]
    assert [c.semantics.weight for _, c in exercise.searches] == [1.0, 2.0, 1.5]
    tutorial = grid_from_rows(TUTORIAL_ROWS)
    detour = parse_map_text("\n".join(
        ["S....#......", "#.##...#...#", "..####....##", "#....#.#....", "#...#...#...",
         "#...#.###...", ".......#.##G"]) + "\n", "detour.txt")
    assert not grade(exercise, tutorial).solved  # the same path as UCS's there
    verdict = grade(exercise, detour)
    assert verdict.figures["astar_w_2.cost"] == pytest.approx(17.142136, abs=1e-6)

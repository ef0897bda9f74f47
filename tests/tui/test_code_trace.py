"""The lines the step at a run's position lit, on the tutorial's map: checked by hand for BFS
and DFS steps 1-4 (the tutorial's narrative), and for a discarded step, a skip by the corner
rule, tree search, iterative deepening's new iteration, the goal found and no path."""

from __future__ import annotations

import pytest

from tests.helpers import MAPS, TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.tui.view.code_trace import Skip, code_of, lit_lines, skipped


def at(run: Run, k: int) -> Run:
    run.goto(k)
    return run


def tutorial(algorithm: str, **choices: object) -> Run:
    return Run(grid_from_rows(TUTORIAL_ROWS), algorithm, Semantics(**choices))  # type: ignore[arg-type]


# BFS's and DFS's code (tests/engine/test_pseudocode.py prints BFS's): 1 frontier <- START,
# 2 mark START visited, 3 goal test START, 4 while, 5 take off, 6 for each successor,
# 7 off the map or an obstacle: skip, 8 already visited: skip, 9 push, 10 mark s visited,
# 11 goal test s, 12 return no path.
SETUP, STEP_NOTHING_VISITED, STEP = {1, 2}, {4, 5, 6, 7, 9, 10}, {4, 5, 6, 7, 8, 9, 10}

#: step -> (lit lines, the successors skipped as already visited), worked out by hand on
#: the map: START (0,0) has one free neighbour, S (0,1); every other move is off the map or
#: into an obstacle.
BFS = {
    0: (SETUP, []),
    1: (STEP_NOTHING_VISITED, []),  # START: S pushed, the rest off the map or obstacles
    2: (STEP, [(0, 0)]),  # (0,1): N is START; S (0,2) and SE (1,2) pushed
    3: (STEP, [(0, 1), (1, 2)]),  # (0,2): N visited, E (1,2) on the queue already
    4: (STEP, [(0, 1), (0, 2), (0, 3), (1, 3)]),  # SE (1,2): E and NE pushed
}
DFS = {
    0: (SETUP, []),
    1: (STEP_NOTHING_VISITED, []),
    2: (STEP, [(0, 0)]),  # (0,1): S and SE pushed; SE on top
    3: (STEP, [(0, 1), (0, 2)]),  # SE (1,2): SW, S, E, NE pushed; NE on top
    4: (STEP, [(1, 2), (2, 2)]),  # NE (2,1): N (2,0) and NE (3,0) pushed
}


@pytest.mark.parametrize(("algorithm", "expected"), [("bfs", BFS), ("dfs", DFS)])
def test_the_first_four_steps_light_the_lines_the_tutorial_walks_through(
        algorithm: str, expected: dict[int, tuple[set[int], list[tuple[int, int]]]]) -> None:
    run = tutorial(algorithm)
    for k, (lines, visited) in expected.items():
        assert lit_lines(at(run, k)) == lines, (algorithm, k)
        assert [s.cell for s in skipped(run) if s.kind == "reached"] == visited, (algorithm, k)


def test_stepping_back_lights_the_earlier_step_s_lines() -> None:
    run = tutorial("bfs")
    before = lit_lines(at(run, 1))
    at(run, 4)
    run.backward(), run.backward(), run.backward()
    assert run.k == 1 and lit_lines(run) == before


def test_a_discarded_step_lights_the_line_that_discards_it() -> None:
    """BFS with visit on expand takes a cell already expanded off the queue at step 7.  Its
    code: 1 frontier, 2 goal test START, 3 while, 4 take off, 5 discard, 6 mark node ..."""
    run = at(tutorial("bfs", visit="expand"), 7)
    code = code_of(run)
    assert run.steps.is_discarded(7)
    assert code.lines[4].text == "if node is already visited: discard it, go on"
    assert lit_lines(run) == {3, 4, 5} == code.numbers({"while", "take", "discard"})
    assert lit_lines(at(run, 6)) >= code.numbers({"mark_node", "push"})


def test_a_diagonal_refused_by_the_corner_rule_lights_the_corner_line() -> None:
    """Corner rule never: from (0,1), SE (1,2) passes the obstacle (1,1): skipped there."""
    run = at(tutorial("bfs", corners="never"), 2)
    assert Skip("corner", "SE", (1, 2)) in skipped(run)
    code = code_of(run)
    assert code.number("corner") in lit_lines(run)
    assert code.number("corner") not in lit_lines(at(run, 1))


def test_tree_search_lights_the_on_the_path_line() -> None:
    run = at(tutorial("bfs", tree_search=True), 2)
    assert skipped(run) and skipped(run)[0] == Skip("on_path", "N", (0, 0))
    assert code_of(run).number("on_path") in lit_lines(run)


def test_iterative_deepening_lights_its_outer_loop_at_each_new_iteration() -> None:
    run = tutorial("iddfs")
    code = code_of(run)
    new = code.numbers({"deepen", "init", "mark_start"})
    assert lit_lines(at(run, 0)) == new
    assert lit_lines(at(run, 1)) >= new | {code.number("cutoff")}  # limit 0: START cut off
    assert lit_lines(at(run, 2)) >= new  # limit 1 begins
    assert code.number("cutoff") not in lit_lines(run)
    assert code.number("deepen") not in lit_lines(at(run, 3))


def test_the_goal_found_lights_its_goal_test() -> None:
    bfs = tutorial("bfs")
    bfs.advance()
    assert code_of(bfs).number("goal_succ") in lit_lines(at(bfs, bfs.recorded))
    ucs = tutorial("ucs")
    ucs.advance()
    assert code_of(ucs).number("goal_node") in lit_lines(at(ucs, ucs.recorded))


def test_no_path_lights_the_last_line() -> None:
    run = Run(load_map(MAPS / "no-path.txt"), "bfs")
    run.advance()
    code = code_of(run)
    assert code.number("fail") in lit_lines(at(run, run.recorded))
    assert code.number("fail") not in lit_lines(at(run, run.recorded - 1))


def test_a_recursion_lights_its_call_and_its_skip_of_a_cell_visited_meanwhile() -> None:
    """The neighbours form: each call entered lights the function, its mark and ``visit(s)``;
    a neighbour visited deeper down since it was listed lights the skip instead."""
    run = tutorial("dfs", recursive="neighbours", order=("N", "W", "S", "E"))
    code = code_of(run)
    run.advance()
    discarded = next(k for k in range(1, run.total + 1) if run.steps.is_discarded(k))
    assert code.number("discard") in lit_lines(at(run, discarded))
    entered = lit_lines(at(run, 2))
    assert {code.number("while"), code.number("mark_node"), code.number("recurse")} <= entered
    assert code.number("discard") not in entered


def test_a_closed_set_names_the_neighbours_it_skips_as_closed() -> None:
    """A* with no re-opening: a neighbour expanded already is skipped by the closed line."""
    run = tutorial("astar", reopen=False)
    code = code_of(run)
    k = next(k for k in range(2, 9) if any(s.kind == "closed" for s in skipped(at(run, k))))
    assert code.number("closed") in lit_lines(at(run, k))
    assert all(s.kind != "reached" or not run.now.times_reached(s.cell)[1]
               for s in skipped(run))

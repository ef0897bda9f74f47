"""The CS188 autograder's ``.test`` and ``.solution`` files: read as a graph or a layout with
its search, each parser error one line with its place, ``costFn`` recognised as text and never
run, and the app's runs in the course's words held equal to states derived by hand.

The graph of ``examples/cs188_style/tests/graph_*.test`` (directed; successors in this order)::

    A -> B 1,  A -> C 2,  A -> D 4,  B -> D 1,  C -> G 8,  D -> G 1;  start A, goal G

Each search visits a state when it expands it and tests the goal when it takes it off, as the
course's do (``--preset cs188``).  By hand, the frontier after each expansion (oldest first):

* BFS: A -> [B C D]; B -> [C D D]; C -> [D D G]; D -> [D G G]; D again is discarded; G is the
  goal, reached from C: solution ``1:A->C 0:C->G``, expanded ``A B C D``.  Reversed (each
  state's successors last to first): A -> [D C B]; D -> [C B G]; C -> [B G G]; B -> [G G D];
  G from D: ``2:A->D 0:D->G``, expanded ``A D C B``.
* DFS (a stack, its top last): A -> [B C D]; D -> [B C G]; G: ``2:A->D 0:D->G``, expanded
  ``A D``.  Reversed: A -> [D C B]; B -> [D C D]; D -> [D C G]; G: ``0:A->B 0:B->D 0:D->G``,
  expanded ``A B D``.
* UCS (g; ties the oldest): A -> B1 C2 D4; B -> D2 (cheaper); C2 before D2 (older) -> G10;
  D2 -> G3; G3: ``0:A->B 0:B->D 0:D->G``, expanded ``A B C D`` (reversed the same: C2 is
  still pushed before D2).
* A* with h A 3, B 2, C 6, D 1, G 0 (consistent): A -> B f3, C f8, D f5; B -> D f3; D -> G f3;
  G: ``0:A->B 0:B->D 0:D->G``, expanded ``A B D`` (reversed the same).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.engine.map_helpers import error_of, write
from tests.engine.test_layouts import course_search
from tui_search.engine.course.autograder_check import course_semantics, run_course_test
from tui_search.engine.course.autograder_files import read_course_test
from tui_search.engine.maps.read import MapError

ROOT = Path(__file__).resolve().parents[2]
TESTS = ROOT / "examples" / "cs188_style" / "tests"
GRAPH = '''class: "GraphSearchTest"
algorithm: "{algorithm}"
graph: """
start_state: A
goal_states: G
A 0:A->B B 1.0
A 1:A->C C 2.0
A 2:A->D D 4.0
B 0:B->D D 1.0
C 0:C->G G 8.0
D 0:D->G G 1.0
"""
'''


def both(test_file: Path) -> tuple[tuple, tuple]:
    test = read_course_test(str(test_file))
    sem = course_semantics(test)
    run, rev = (run_course_test(test, sem, 1000, reverse=r) for r in (False, True))
    return (" ".join(run.solution or []), " ".join(run.expanded)), (
        " ".join(rev.solution or []), " ".join(rev.expanded))


@pytest.mark.parametrize(("name", "forward", "reverse"), [
    ("bfs", ("1:A->C 0:C->G", "A B C D"), ("2:A->D 0:D->G", "A D C B")),
    ("dfs", ("2:A->D 0:D->G", "A D"), ("0:A->B 0:B->D 0:D->G", "A B D")),
    ("ucs", ("0:A->B 0:B->D 0:D->G", "A B C D"), ("0:A->B 0:B->D 0:D->G", "A B C D")),
    ("astar", ("0:A->B 0:B->D 0:D->G", "A B D"), ("0:A->B 0:B->D 0:D->G", "A B D")),
])
def test_the_graph_tests_give_the_states_derived_by_hand(name: str, forward: tuple,
                                                         reverse: tuple) -> None:
    test_file = TESTS / f"graph_{name}.test"
    assert both(test_file) == (forward, reverse)
    answer = read_course_test(str(test_file)).solution  # the .solution says the same
    assert (answer["solution"], answer["expanded_states"]) == forward
    assert (answer["rev_solution"], answer["rev_expanded_states"]) == reverse


def test_a_layout_test_is_held_equal_to_the_course_style_search() -> None:
    test = read_course_test(str(TESTS / "pacman_bfs.test"))
    assert test.kind == "PacmanSearchTest" and test.layout_name == "smallTwists"
    assert test.grid is not None and test.algorithm == "bfs"
    run = run_course_test(test, course_semantics(test), 1000)
    lines = (TESTS / "pacman_bfs.test").read_text().split('"""')[1].strip("\n").splitlines()
    assert course_search(lines, "fifo") == (len(run.expanded), len(run.solution or []))
    assert run.expanded[0] == "(10, 5)"  # Pacman's start, y from the bottom
    assert " ".join(run.solution or []) == test.solution["solution"].strip()
    assert str(len(run.expanded)) == test.solution["expanded_nodes"]


@pytest.mark.parametrize(("text", "name"), [
    ("lambda pos: 1", "1"), ("lambda pos: .5 ** pos[0]", "0.5 ** x"),
    ("lambda p: 0.5**p[0]", "0.5 ** x"), ("lambda  xy :  2 ** xy[0]", "2 ** x"),
])
def test_the_courses_three_cost_functions_are_recognised_as_text(tmp_path: Path, text: str,
                                                                 name: str) -> None:
    test = write(tmp_path, "t.test", 'algorithm: "ucs"\ncostFn: "' + text
                 + '"\nlayout: """\n%%%%%\n%P .%\n%%%%%\n"""\n')
    read = read_course_test(str(test))
    assert read.cost_fn == name and read.grid is not None
    assert read.grid.cost((3, 1)) == {"1": 1.0, "0.5 ** x": 0.125, "2 ** x": 8.0}[name]


def test_any_other_cost_function_is_refused_and_never_run(tmp_path: Path) -> None:
    mark = tmp_path / "ran"
    test = write(tmp_path, "t.test", 'algorithm: "ucs"\ncostFn: "lambda pos: __import__(\'os\')'
                 f'.system(\'touch {mark}\')"\nlayout: """\n%P.%\n"""\n')
    message = error_of(read_course_test, str(test))
    assert message.startswith(f"{test}:2:10: costFn \"lambda pos: __import__('os').system(")
    assert message.endswith("is not one the course uses (lambda pos: 1, .5 ** pos[0], 2 ** "
                            "pos[0]): it is never run")
    assert not mark.exists()


@pytest.mark.parametrize(("text", "error"), [
    ('algorithm "bfs"\n', ':1:1: expected key: "value" or key: """ (a block)'),
    ('algorithm: bfs\n', ":1:12: the value of 'algorithm' is not in quotes: \"...\""),
    ('algorithm: "bfs"\nalgorithm: "dfs"\n', ":2:1: a second 'algorithm' (the first is at "
     "line 1)"),
    ('# a comment\ngraph: """\nstart_state: A\n', ":2:8: the \"\"\" block of 'graph' is never "
     "closed"),
    ('graph: """\n"""\n', ": no 'algorithm': the test needs one"),
    ('algorithm: "bestFirstSearch"\n', ":1:13: algorithm 'bestFirstSearch': use "
     "depthFirstSearch, breadthFirstSearch, uniformCostSearch or aStarSearch"),
    ('class: "EightPuzzleTest"\n', ":1:9: class 'EightPuzzleTest': this reads "
     "GraphSearchTest and PacmanSearchTest"),
    ('algorithm: "bfs"\ngraph: """\ngoal_states: G\nstart_state: A\n"""\n',
     ":3:1: the graph's first line is start_state: STATE"),
    ('algorithm: "bfs"\ngraph: """\nstart_state: A\ngoal: G\n"""\n',
     ":4:1: the graph's second line is goal_states: STATE ..."),
    ('algorithm: "bfs"\ngraph: """\nstart_state: A\ngoal_states: G\nA G\n"""\n',
     ":5:1: an edge is FROM ACTION TO [COST]"),
    ('algorithm: "bfs"\ngraph: """\nstart_state: A\ngoal_states: G\nA x G nan\n"""\n',
     ":5:7: 'nan' is not a number"),
    ('algorithm: "bfs"\ngraph: """\nstart_state: A\ngoal_states: G\nA x G 0\n"""\n',
     ":5:7: the cost 0 is not above 0"),
    ('algorithm: "bfs"\ngraph: """\nstart_state: A\ngoal_states: G\nA x G\nA y G\n"""\n',
     ":6:1: a second edge from A to G"),
    ('algorithm: "astar"\ngraph: """\nstart_state: A\ngoal_states: G\nA x G\n"""\n'
     'heuristic: """\nZ 1\n"""\n', ":8:1: no state 'Z' in the graph"),
    ('algorithm: "bfs"\nlayout: """\n%%%%\n%P?.\n"""\n', ":4:3: unknown layout character "
     "'?' (use % walls, P the start, . food, o G digits and spaces free)"),
    ('algorithm: "bfs"\n# the maze\nlayout: """\n%%%%\n%P.%\n%.P%\n"""\n', ":6:3: a second P "
     "(the first is at line 5, column 2)"),
    ('algorithm: "bfs"\nlayout: """\n%%%%\n%P.%%\n"""\n', ":4:5: row has 5 cells, expected 4"),
    ('algorithm: "bfs"\nheuristic: "octileHeuristic"\nlayout: """\n%P.%\n"""\n',
     ":2:13: heuristic 'octileHeuristic': use manhattanHeuristic, euclideanHeuristic, "
     "nullHeuristic"),
])
def test_each_bad_test_file_is_one_line_with_its_place(tmp_path: Path, text: str,
                                                       error: str) -> None:
    test = write(tmp_path, "t.test", text)
    assert error_of(read_course_test, str(test)) == f"{test}{error}"


def test_a_bad_solution_file_is_one_line_too(tmp_path: Path) -> None:
    test = write(tmp_path, "t.test", GRAPH.format(algorithm="bfs"))
    write(tmp_path, "t.solution", 'solution "1:A->C"\n')
    with pytest.raises(MapError, match=r"t\.solution:1:1: expected key"):
        read_course_test(str(test))

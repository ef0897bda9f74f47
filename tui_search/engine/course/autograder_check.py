"""A course test run as the app runs it: the path and the expanded states in the course's
words, forwards and with the successors reversed, and whether they agree with its
``.solution``.

The course counts a state expanded when its successors are asked for (``getSuccessors``):
the goal, taken off and returned, never is.  The reversed run is the course's
``rev_expanded_states``: the same search with each state's successors in the reverse order
(a layout's W, E, S, N).
"""

from __future__ import annotations

from tui_search.engine.course.autograder_files import CourseTest
from tui_search.engine.course.presets import preset_semantics
from tui_search.engine.maps.graph import Edge, Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.reference import stream
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.rules import Expansion
from tui_search.engine.util.frozen import Frozen

__all__ = ["COURSE_MOVES", "CourseRun", "course_semantics", "run_course_test", "state_words"]

#: The app's moves in the course's words.
COURSE_MOVES = {"N": "North", "S": "South", "E": "East", "W": "West"}


class CourseRun(Frozen):
    """One run in the course's words: the actions (None: no path) and the expanded states."""

    __slots__ = _FIELDS = ("solution", "expanded", "gave_up")

    solution: list[str] | None
    expanded: list[str]
    gave_up: bool

    def __init__(self, solution: list[str] | None, expanded: list[str], gave_up: bool) -> None:
        self._assign(solution=solution, expanded=expanded, gave_up=gave_up)


def course_semantics(test: CourseTest) -> Semantics:
    """The course's choices for the test's search (``--preset cs188``), on its graph or grid;
    costs compared exactly where a cost function makes them tiny (``.5 ** x``)."""
    algorithm = get_algorithm(test.algorithm)
    sem = preset_semantics("cs188", algorithm)
    if test.graph is not None:
        sem = sem.replace(order=("file",))
    if test.heuristic is not None and algorithm.informed:
        sem = sem.replace(heuristic=test.heuristic)
    elif algorithm.informed:
        sem = sem.replace(heuristic="zero")
    if test.cost_fn != "1" and algorithm.weighted:
        sem = sem.replace(cost_tolerance=0.0)
    return sem


def state_words(board: Grid | Graph, state: object) -> str:
    """A state as the course writes it: a graph's name, a layout's ``(x, y)`` from below."""
    if isinstance(board, Grid) and isinstance(state, tuple):
        return f"({state[0]}, {board.height - 1 - state[1]})"
    return str(state)


def reversed_graph(graph: Graph) -> Graph:
    """The graph with each state's successors in the reverse order."""
    edges = list(reversed(graph.edges))
    names = list(graph.names)
    h = graph.h
    return Graph.of(names, [Edge(e.a, e.b, e.cost, e.directed, e.line) for e in edges],
                    h=h, start=graph.start, goals=graph.goals, name=graph.name)


def run_course_test(test: CourseTest, semantics: Semantics, max_steps: int,
                    reverse: bool = False) -> CourseRun:
    """The test's search under ``semantics`` (successors reversed with ``reverse``)."""
    board: Grid | Graph
    if test.graph is not None:
        board = reversed_graph(test.graph) if reverse else test.graph
    else:
        assert test.grid is not None, "a layout test has its grid"
        board = test.grid
        if reverse:
            semantics = semantics.replace(order=tuple(reversed(semantics.order)))
    algorithm = get_algorithm(test.algorithm)
    goal_test = semantics.goal_test_for(algorithm)
    expanded: list[str] = []

    def on_step(step: Expansion) -> None:
        if step.discarded or (step.found and goal_test == "expand"):
            return  # the goal taken off is returned: its successors are never asked for
        expanded.append(state_words(board, step.node.cell))

    outcome = stream(board, algorithm, semantics, max_steps, on_step)
    solution = None
    if outcome.path is not None:
        if test.graph is not None:
            solution = [test.actions[(a, b)] for a, b in zip(outcome.path, outcome.path[1:],
                                                              strict=False)]
        else:
            solution = [COURSE_MOVES.get(m, m) for m in outcome.moves or []]
    return CourseRun(solution, expanded, outcome.gave_up)

"""Picture of a challenge (look at it as a PNG before accepting a change)."""

from __future__ import annotations

from tests.helpers import ROOT
from tests.tui.test_app import MAPS
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp

EXERCISES = ROOT / "tests" / "data" / "exercises"


def test_an_exercise_solved(snap_compare) -> None:
    """Exercise 1 on the tutorial's map with only the goal moved to (0,4): the panel above the
    queue quotes the exercise and says 'Solved ✓ BFS expanded 5 nodes, DFS 18; BFS's path has
    4 moves, DFS's 8'."""
    path = MAPS / "exercise1-goal-moved.txt"
    app = SearchApp(load_map(path), path=path, exercise=1)
    assert snap_compare(app, terminal_size=(100, 30))


def test_a_teacher_s_exercise(snap_compare) -> None:
    """A teacher's exercise file on the tutorial's map: the panel is titled 'Greedy is not
    optimal', quotes its text and says 'Not solved yet: both found the goal; both paths cost
    8.66', then the file's hint."""
    from tui_search.engine.course.exercise_file import load_exercise

    exercise = load_exercise(EXERCISES / "greedy-not-optimal.toml")
    path = MAPS / "tutorial.txt"
    app = SearchApp(load_map(path), path=path, exercise=exercise)
    assert snap_compare(app, terminal_size=(100, 30))

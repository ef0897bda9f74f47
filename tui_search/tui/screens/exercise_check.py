"""The challenge panel's verdict on the map as it is now, for the screen of panes
(:class:`~tui_search.tui.screens.panes.PanesScreen`, which imports this only once an
exercise is shown).

The exercise's whole searches run at once on a map of at most ``LIVE_CELLS`` cells, else in a
thread (a worker of the screen's) once the edits pause; a verdict comes back only if the map
and the exercise are still the same.
"""

from __future__ import annotations

from time import sleep
from typing import TYPE_CHECKING

from textual.worker import get_current_worker

from tui_search.engine.course.grading import LIVE_CELLS, grade
from tui_search.engine.util.numbers import group_digits

if TYPE_CHECKING:
    from textual.screen import Screen

    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.course.grading import Verdict
    from tui_search.engine.maps.grid import Grid
    from tui_search.tui.model.session import Session
    from tui_search.tui.widgets.challenge import ChallengePanel

#: On a map too big to check an exercise at each edit, the check waits for the edits to pause
#: this long (seconds): a mouse stroke is an edit a cell.
EXERCISE_PAUSE = 0.3


def check_exercise(screen: Screen[None], session: Session, panel: ChallengePanel) -> None:
    """Show the verdict on the session's exercise (one is shown) in ``panel``."""
    exercise = session.exercise
    assert exercise is not None
    if session.graph is not None:  # a graph's exercise: a few nodes, checked at each edit
        verdict = session.verdict()
        panel.show(exercise, verdict)
        _record(screen, session, verdict)
        return
    grid = session.grid
    if exercise.by_hand:  # no map to grade: the run by hand is the answer
        result = getattr(screen, "hand_result", None)
        panel.show_by_hand(exercise, result)
    elif grid.start is None or grid.goal is None:
        panel.show(exercise, None, "Place a start (s) and a goal (g) to check it.")
    elif grid.width * grid.height > LIVE_CELLS:
        panel.show(exercise, None, f"Checking on this map ({group_digits(grid.width)}"
                   f" × {group_digits(grid.height)})…")
        copy = grid.copy()
        screen.run_worker(lambda: _check_big(screen, session, panel, exercise, copy),
                          thread=True, exclusive=True, group="exercise")
    else:
        verdict = session.verdict()
        panel.show(exercise, verdict)
        _record(screen, session, verdict)


def _record(screen: Screen[None], session: Session, verdict: Verdict) -> None:
    """The verdict in the student's records (``--records``), when they are kept."""
    if session.records is not None:
        problem = session.records.verdict(verdict, session.board)
        if problem:
            screen.notify(problem, severity="warning", timeout=8)


def _check_big(screen: Screen[None], session: Session, panel: ChallengePanel,
               exercise: Exercise, grid: Grid) -> None:
    """(In a thread.)  Check ``exercise`` on ``grid``, a copy of the map as it was, once no
    edit has come for a moment (each edit starts a new check and cancels this one), and show
    the verdict if the map and the exercise are still the same."""
    sleep(EXERCISE_PAUSE)
    if get_current_worker().is_cancelled:
        return
    verdict = grade(exercise, grid, session.max_steps)
    screen.app.call_from_thread(_show_big_verdict, session, panel, exercise, grid, verdict)


def _show_big_verdict(session: Session, panel: ChallengePanel, exercise: Exercise, grid: Grid,
                      verdict: Verdict) -> None:
    now = session.grid
    if exercise is session.exercise and (grid.start, grid.goal) == (
            now.start, now.goal) and grid.blocked == now.blocked:
        panel.show(exercise, verdict)
        if session.records is not None:
            session.records.verdict(verdict, grid)

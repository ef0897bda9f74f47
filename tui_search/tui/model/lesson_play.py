"""A lesson open in the app, without Textual: which section is shown, and what showing one
does to the :class:`~tui_search.tui.model.session.Session` (its map, its searches, a pane each,
their choices, their step, the exercise and the Code panel).

The screen calls :meth:`LessonPlay.move` for ``pgdn`` and ``pgup`` and then shows the session
as it shows it after any other change.
"""

from __future__ import annotations

from pathlib import Path
from typing import Protocol

from tui_search.engine.course.exercise_file import Exercise
from tui_search.engine.course.lesson import Lesson, Section, State
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_board
from tui_search.engine.maps.read import MapError
from tui_search.engine.search.choices import Semantics
from tui_search.tui.model.boards import semantics_for


class Session(Protocol):
    """What a lesson sets of the session (:class:`~tui_search.tui.model.session.Session`, which
    holds the lesson: named here, not imported, so the two modules make no circle)."""

    algorithm: str
    semantics: Semantics
    show_code: bool
    note: str

    @property
    def board(self) -> Grid | Graph: ...
    def stop(self) -> None: ...
    def use_map(self, grid: Grid | Graph, path: Path | None,
                untitled: str | None = None) -> None: ...
    def show_searches(self, spec: str) -> str | None: ...
    def goto(self, k: int | None) -> None: ...
    def show_exercise(self, exercise: Exercise | int | None) -> str: ...


class LessonPlay:
    """``lesson`` open at section ``index`` (0-based)."""

    def __init__(self, lesson: Lesson) -> None:
        self.lesson = lesson
        self.index = 0

    @property
    def section(self) -> Section:
        return self.lesson.sections[self.index]

    @property
    def where(self) -> str:
        """``tutorial 2/10``: the lesson and the section shown."""
        return f"{self.lesson.name} {self.index + 1}/{len(self.lesson.sections)}"

    def open(self, session: Session) -> None:
        """Show the first section."""
        self.index = 0
        self._apply(session)

    def move(self, session: Session, by: int) -> bool:
        """The next (``by`` 1) or previous (-1) section; False when there is none."""
        index = self.index + by
        if not 0 <= index < len(self.lesson.sections):
            return False
        self.index = index
        self._apply(session)
        return True

    def _apply(self, session: Session) -> None:
        state = self.section.state
        if state is not None:
            apply_state(session, state)


def apply_state(session: Session, state: State) -> None:
    """Put ``session`` in ``state``: its map (read anew from the file; an exercise file's own
    when it names none), its searches at
    ``state.step`` (None: the end), the choices, the exercise and the Code panel."""
    session.stop()
    problem = ""
    if state.map is not None:
        try:
            session.use_map(load_board(state.map), state.map)  # read anew: edits undone
        except MapError as exc:  # checked when the lesson was read, changed since
            problem = str(exc)
    elif state.exercise is not None and not isinstance(state.exercise, int):
        own = state.exercise  # a file's exercise, no map named: its own map, anew
        session.use_map(own.grid.copy(), None, f"{Path(own.path).name}'s map")
    session.algorithm = state.algorithm
    session.semantics = semantics_for(session.board, state.semantics)  # a graph's or a grid's
    session.show_exercise(state.exercise)  # its rules are the state's (lesson.py)
    session.show_code = state.code
    refusal = session.show_searches(state.spec)
    assert refusal is None, refusal  # checked when the lesson was read
    session.goto(state.step)
    session.note = problem or session.note


__all__ = ["LessonPlay", "apply_state"]

"""Undo and redo without Textual: the history of edits (:mod:`tui_search.tui.model.history`) and the
session's edits recorded in it, with Hypothesis for any sequence of edits."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import TUTORIAL
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.tui.model.history import Edit, History
from tui_search.tui.model.session import Session

#: An edit of the session on the tutorial's 6x6 map: the cursor to (x, y), then ``s``, ``g``,
#: ``o``, or a mouse stroke over those cells (painting what the first cell became).
EDITS = st.one_of(
    st.tuples(st.sampled_from(["start", "goal", "wall"]), st.integers(0, 5), st.integers(0, 5)),
    st.tuples(st.just("stroke"), st.lists(st.tuples(st.integers(0, 5), st.integers(0, 5)),
                                          min_size=1, max_size=6)),
)


def tutorial() -> Session:
    return Session(load_map(TUTORIAL), TUTORIAL)


def snapshot(grid: Grid) -> tuple[bytes, object, object]:
    return bytes(grid.blocked), grid.start, grid.goal


def edit(session: Session, what: tuple[object, ...]) -> bool:
    """Make the edit ``what`` as the screen does; True when it changed the map."""
    if what[0] == "stroke":
        cells: list[tuple[int, int]] = what[1]  # type: ignore[assignment]
        history, grid = session.edits.history, session.grid
        first = cells[0]
        if first in (grid.start, grid.goal):
            return False
        history.begin_stroke()
        paint = not grid.is_blocked(first)
        session.move_cursor(first)
        changed = session.edits.toggle_wall(session.cursor) is None
        for cell in cells[1:]:
            changed = session.edits.paint(cell, paint) or changed
        history.end_stroke()
        return changed
    kind, x, y = what
    session.move_cursor((x, y))  # type: ignore[arg-type]
    edits, at = session.edits, session.cursor
    refusal = edits.toggle_wall(at) if kind == "wall" else edits.place(kind, at)  # type: ignore[arg-type]
    return refusal is None


@settings(max_examples=60, deadline=None)
@given(st.lists(EDITS, max_size=12))
def test_undoing_every_edit_gives_the_map_back_and_redoing_them_the_edited_one(
        edits: list[tuple[object, ...]]) -> None:
    session = tutorial()
    original = snapshot(session.grid)
    states = [original]  # the map after each edit that changed it
    for what in edits:
        if edit(session, what):
            states.append(snapshot(session.grid))
    assert session.dirty == (len(states) > 1)
    for state in reversed(states[:-1]):  # one undo a recorded edit: a stroke is one
        assert session.edits.undo() is None
        assert snapshot(session.grid) == state
    assert session.edits.undo() == "Nothing to undo"
    assert snapshot(session.grid) == original and not session.dirty
    assert session.title == "tutorial.txt"
    for state in states[1:]:
        assert session.edits.undo(redo=True) is None
        assert snapshot(session.grid) == state
    assert session.edits.undo(redo=True) == "Nothing to redo"
    assert session.dirty == (len(states) > 1)


@settings(max_examples=40, deadline=None)
@given(st.lists(EDITS, min_size=1, max_size=8), st.integers(1, 8), EDITS)
def test_a_new_edit_after_undo_drops_the_edits_undone(
        edits: list[tuple[object, ...]], undos: int, new: tuple[object, ...]) -> None:
    session = tutorial()
    for what in edits:
        edit(session, what)
    for _ in range(undos):
        session.edits.undo()
    before = snapshot(session.grid)
    if edit(session, new):
        assert not session.edits.history.can_redo() and session.dirty
        assert session.edits.undo() is None and snapshot(session.grid) == before
    else:
        assert snapshot(session.grid) == before


def test_an_edit_makes_new_runs_and_undo_does_too_with_the_cursor_on_the_cell() -> None:
    session = tutorial()
    session.step(forward=True)
    session.move_cursor((1, 2))
    assert session.edits.toggle_wall(session.cursor) is None
    assert session.title == "tutorial.txt · modified"
    session.step(forward=True)
    session.move_cursor((4, 4))
    old = session.runs[0]
    assert session.edits.undo() is None
    assert session.cursor == (1, 2) and not session.grid.is_blocked((1, 2))
    assert session.runs[0] is not old and session.runs[0].k == 0
    assert session.runs[0].grid == session.grid and not session.dirty
    assert session.edits.undo(redo=True) is None
    assert session.grid.is_blocked((1, 2)) and session.dirty


def test_undoing_a_moved_start_puts_it_back_and_the_cursor_on_it() -> None:
    session = tutorial()
    session.move_cursor((0, 2))
    assert session.edits.place("start", session.cursor) is None and session.grid.start == (0, 2)
    assert session.edits.undo() is None
    assert session.grid.start == (0, 0) and session.cursor == (0, 0)
    assert session.edits.undo(redo=True) is None
    assert session.grid.start == (0, 2) and session.cursor == (0, 2)


def test_a_save_is_the_new_clean_point(tmp_path: object) -> None:
    session = tutorial()
    session.move_cursor((1, 2))
    session.edits.toggle_wall(session.cursor)
    session.saved(TUTORIAL)  # what a save does once the file is written
    assert not session.dirty
    session.edits.undo()
    assert session.dirty  # the file holds the obstacle now
    session.edits.undo(redo=True)
    assert not session.dirty


def test_a_save_in_the_edits_undone_is_lost_by_a_new_edit() -> None:
    session = tutorial()
    session.move_cursor((1, 2))
    session.edits.toggle_wall(session.cursor)
    session.saved(TUTORIAL)
    session.edits.undo()
    session.move_cursor((2, 2))
    session.edits.toggle_wall(session.cursor)  # the state saved can no longer be reached
    assert session.dirty
    session.edits.undo()
    assert session.dirty  # the map as read, not as saved


def test_a_new_map_has_a_new_history() -> None:
    session = tutorial()
    session.move_cursor((1, 2))
    session.edits.toggle_wall(session.cursor)
    session.use_map(load_map(TUTORIAL), TUTORIAL)
    assert not session.edits.history.can_undo() and not session.dirty
    assert session.edits.undo() == "Nothing to undo"


def test_the_history_keeps_the_last_edits_only() -> None:
    grid = Grid(4, 1)
    history = History(limit=2)
    for x in range(3):
        grid.set_blocked((x, 0), True)
        history.add(Edit([((x, 0), False, True)]))
    assert history.undo(grid) == (2, 0) and history.undo(grid) == (1, 0)
    assert history.undo(grid) is None  # the first edit was dropped
    assert bytes(grid.blocked) == b"\x01\x00\x00\x00" and history.modified
    history.saved()
    history.redo(grid)
    history.redo(grid)
    history.redo(grid)  # nothing more
    assert bytes(grid.blocked) == b"\x01\x01\x01\x00" and history.modified


def test_a_stroke_is_one_edit_and_an_undo_in_it_starts_a_new_one() -> None:
    grid = Grid(4, 1)
    history = History()
    history.begin_stroke()
    for x in range(2):
        grid.set_blocked((x, 0), True)
        history.add(Edit([((x, 0), False, True)]))
    assert history.undo(grid) == (0, 0) and not any(grid.blocked)
    grid.set_blocked((3, 0), True)  # the stroke goes on after the undo: a new edit
    history.add(Edit([((3, 0), False, True)]))
    history.end_stroke()
    assert history.undo(grid) == (3, 0) and not history.can_undo() and history.can_redo()

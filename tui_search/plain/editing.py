"""Plain mode's edits of the map and its files: the start, the goal, obstacles, the terrain
brush, undo and redo, saving, opening and generating a map -- each what the app's key does,
then the searches from step 0 and the exercise checked again.  Leaving a map with unsaved
edits (``q``, ``open``, ``generate``) asks first: the same command again leaves them.
"""

from __future__ import annotations

from pathlib import Path
from typing import Protocol

from tui_search.engine.maps.read import MapError
from tui_search.engine.search.state import as_cell
from tui_search.plain.files import save_lines
from tui_search.tui.model.file_rules import one_line
from tui_search.tui.model.map_edits import BRUSHES, brush_name
from tui_search.tui.model.session import Session
from tui_search.tui.view.narration import cell_text


class Mode(Protocol):
    """What the edits need of the mode they are part of
    (:class:`~tui_search.plain.mode.PlainMode`)."""

    session: Session

    def say(self, *lines: str) -> None: ...

    def start(self) -> None: ...

    def report(self, moved: list[bool] | None = None) -> None: ...

    def exercise_said(self, always: bool = False) -> None: ...


class EditCommands:
    """The edit and file commands of a :class:`~tui_search.plain.mode.PlainMode`."""

    def __init__(self, mode: Mode) -> None:
        self.mode = mode
        self._asked = ""  # the command that asked to leave unsaved edits, just before

    def asked_before(self, action: str) -> None:
        """A command is typed: a question asked by another one is forgotten."""
        if action != self._asked:
            self._asked = ""

    def may_leave(self, action: str, what: str) -> bool:
        """May ``action`` leave the map (none unsaved, or asked already)?  Else ask."""
        if not self.mode.session.dirty or self._asked == action:
            return True
        self._asked = action
        self.mode.say(f"The map has unsaved edits: save (or save as FILE) keeps them; "
                      f"{action if action != 'quit' else 'q'} again {what} without saving.")
        return False

    def _edited(self, refusal: str | None, done: str) -> None:
        if refusal is not None:
            self.mode.say(refusal + ("" if refusal.endswith(".") else "."))
            return
        self.mode.say(f"{done} The searches start again from step 0.")
        self.mode.report()
        self.mode.exercise_said()

    def do_place_start(self, rest: str, word: str) -> None:
        s = self.mode.session
        self._edited(s.edits.place("start", s.cursor), f"Start at {cell_text(s.cursor)}.")

    def do_place_goal(self, rest: str, word: str) -> None:
        s = self.mode.session
        self._edited(s.edits.place("goal", s.cursor), f"Goal at {cell_text(s.cursor)}.")

    def do_obstacle(self, rest: str, word: str) -> None:
        s = self.mode.session
        wall = not s.grid.is_blocked(as_cell(s.cursor))
        self._edited(s.edits.toggle_wall(s.cursor),
                     f"{'An obstacle' if wall else 'No obstacle'} at {cell_text(s.cursor)}.")

    def do_brush(self, rest: str, word: str) -> None:
        edits = self.mode.session.edits
        if not rest:
            edits.cycle_brush()
        elif rest == "off":
            edits.brush = None
        else:
            cost = next((c for c in BRUSHES if f"{c:g}" == rest), None)
            if cost is None:
                costs = ", ".join(f"{c:g}" for c in BRUSHES)
                self.mode.say(f"brush takes a cost ({costs}: 1 is plain floor) or off.")
                return
            edits.brush = cost
        chosen = edits.brush
        self.mode.say("Terrain brush off." if chosen is None else
                      f"Terrain brush: {brush_name(chosen)} (m paints it at the cursor).")

    def do_paint(self, rest: str, word: str) -> None:
        s = self.mode.session
        self._edited(s.edits.paint_cost(s.cursor), f"Painted {cell_text(s.cursor)}.")

    def do_undo(self, rest: str, word: str) -> None:
        self._edited(self.mode.session.edits.undo(), "Undone.")

    def do_redo(self, rest: str, word: str) -> None:
        self._edited(self.mode.session.edits.undo(redo=True), "Redone.")

    def do_save(self, rest: str, word: str) -> None:
        self.mode.say(*save_lines(self.mode.session, rest))

    def do_open(self, rest: str, word: str) -> None:
        if not rest:
            self.mode.say("open takes a map file: open maps/tutorial.txt.")
            return
        if not self.may_leave("open", "opens the other map"):
            return
        from tui_search.engine.maps.load import load_map

        try:
            grid = load_map(Path(rest))
        except MapError as exc:
            self.mode.say(f"Not opened: {one_line(exc)}.")
            return
        self.mode.session.use_map(grid, Path(rest))
        self.mode.start()

    def do_generate(self, rest: str, word: str) -> None:
        from tui_search.engine.maps.generate import generate, make_recipe
        from tui_search.engine.maps.recipes import DEFAULT_SEED, DEFAULT_SIZE

        kind, size, seed = ([*rest.split(), "", "", ""])[:3]
        if not kind:
            self.mode.say("generate takes a kind, then a size and a seed: generate maze 21x15 7.")
            return
        try:
            recipe = make_recipe(kind, size or DEFAULT_SIZE, seed or DEFAULT_SEED)
        except ValueError as exc:
            self.mode.say(f"Not generated: {exc}.")
            return
        if not self.may_leave("generate", "replaces the map"):
            return
        self.mode.session.use_map(generate(recipe), None, untitled=str(recipe.title))
        self.mode.start()

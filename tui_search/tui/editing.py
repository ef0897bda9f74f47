"""Edits of the map: the cursor, start/goal/obstacle keys and mouse strokes.

:func:`place` and :func:`set_wall` edit a grid and return ``None``, or a one-line reason they
refused (start on an obstacle, an obstacle on the goal ...); :class:`EditActions` is the app's
side (a mixin of :class:`~tui_search.tui.app.SearchApp`): every edit that happens marks the map
dirty and starts a new run at step 0.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.grid import Cell, Grid
from tui_search.tui.mixin import AppMixinBase

if TYPE_CHECKING:
    from tui_search.tui.widgets.grid_view import GridView


def cell_text(cell: Cell) -> str:
    return f"({cell[0]},{cell[1]})"


def place(grid: Grid, what: str, cell: Cell) -> str | None:
    """Put the start or the goal (``what``) at ``cell``."""
    other = grid.goal if what == "start" else grid.start
    if grid.is_blocked(cell):
        return f"Cannot put the {what} on an obstacle at {cell_text(cell)}"
    if cell == other:
        taken = "goal" if what == "start" else "start"
        return f"Cannot put the {what} on the {taken} at {cell_text(cell)}"
    if what == "start":
        if grid.start == cell:
            return f"The start is already at {cell_text(cell)}"
        grid.start = cell
    else:
        if grid.goal == cell:
            return f"The goal is already at {cell_text(cell)}"
        grid.goal = cell
    return None


def set_wall(grid: Grid, cell: Cell, blocked: bool) -> str | None:
    """Make ``cell`` an obstacle (or free it)."""
    if blocked and cell in (grid.start, grid.goal):
        what = "start" if cell == grid.start else "goal"
        return f"Cannot put an obstacle on the {what} at {cell_text(cell)}"
    if grid.is_blocked(cell) == blocked:
        return f"{cell_text(cell)} is already {'an obstacle' if blocked else 'free'}"
    grid.set_blocked(cell, blocked)
    return None


class EditActions(AppMixinBase):
    """Keys s, g, o and the arrows, and the grid view's mouse messages.  A left-button stroke
    paints what its first cell became (an obstacle, or free); start and goal are never
    painted over; the right button only moves the cursor."""


    def action_move(self, dx: int, dy: int) -> None:
        x, y = self.cursor_cell
        cell = (x + dx, y + dy)
        if self.grid.in_bounds(cell):
            self._move_cursor(cell)

    def _move_cursor(self, cell: Cell) -> None:
        self.cursor_cell = cell
        for view in self.views:  # compare mode: one cursor, on every pane's map
            view.set_cursor(cell)
        self._show_pick()
        self.show_readout()

    def _edited(self, refusal: str | None) -> bool:
        if refusal is not None:
            self.notify(refusal, severity="warning", timeout=3)
            return False
        self.dirty = True
        self._new_run()
        return True

    def action_place(self, what: str) -> None:
        self._edited(place(self.grid, what, self.cursor_cell))

    def action_toggle_wall(self) -> None:
        cell = self.cursor_cell
        self._edited(set_wall(self.grid, cell, not self.grid.is_blocked(cell)))

    def on_grid_view_cell_clicked(self, message: GridView.CellClicked) -> None:
        self._move_cursor(message.cell)
        self._stroke = None
        cell = message.cell
        if message.button == 1 and not self.views[0].overview and cell not in (
            self.grid.start, self.grid.goal
        ):
            self._stroke = not self.grid.is_blocked(cell)
            self._edited(set_wall(self.grid, cell, self._stroke))

    def on_grid_view_cell_dragged(self, message: GridView.CellDragged) -> None:
        if self._stroke is None:
            return
        self._move_cursor(message.cell)
        cell = message.cell
        if cell not in (self.grid.start, self.grid.goal) and (
            self.grid.is_blocked(cell) != self._stroke
        ):
            self._edited(set_wall(self.grid, cell, self._stroke))

    def on_grid_view_stroke_ended(self, message: GridView.StrokeEnded) -> None:
        self._stroke = None

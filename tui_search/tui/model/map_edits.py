"""The session's edits of the map: start and goal, obstacles, the terrain brush, and undo.

A part the :class:`~tui_search.tui.model.session.Session` has (``session.edits``; no Textual): each
edit changes the grid through :mod:`~tui_search.tui.model.cell_edits`, is recorded in the history
(:mod:`~tui_search.tui.model.history`: a key press or a whole mouse stroke is one edit), and tells
the session, which starts new runs at step 0.
"""

from __future__ import annotations

from collections.abc import Callable

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.search.state import State, as_cell
from tui_search.tui.model.cell_edits import paint_terrain, place, set_wall
from tui_search.tui.model.history import Edit, History

#: The terrain brush's costs, in the order ``b`` picks them (then off): 1 is plain floor.
BRUSHES: tuple[float, ...] = (2.0, 3.0, 5.0, 9.0, 1.0)
NO_BRUSH = "No terrain brush: b picks a cost"


def brush_name(cost: float) -> str:
    """``cost 5``, ``cost 1 (plain floor)``: a brush as the key bar and the palette say it."""
    return f"cost {cost:g}" + (" (plain floor)" if cost == 1 else "")


class MapEdits:
    """The edits of one map, at a cell (the cursor's, for a key; a mouse stroke's): None, or
    why not.  ``on_edit`` is called after every edit and undo, with the cell an undo or a redo
    puts the cursor on (None for an edit, made where the cursor or the stroke is)."""

    def __init__(self, grid: Grid, on_edit: Callable[[State | None], None],
                 brush: float | None = None) -> None:
        self.grid = grid
        self.board = grid  # what the session edits (a graph's edits: graph_edits.py)
        self.history = History()  # the map's edits: undo, redo, and "modified"
        #: The terrain brush's cost (None: off): what ``m`` and a mouse stroke paint.
        self.brush = brush
        self._on_edit = on_edit

    def _edited(self, refusal: str | None, edit: Edit) -> str | None:
        if refusal is None:
            self.history.add(edit)
            self._on_edit(None)
        return refusal

    def place(self, what: str, at: State) -> str | None:
        """The start or the goal at ``cell``: None, or why not."""
        grid, cell = self.grid, as_cell(at)
        before = (grid.start, grid.goal)
        refusal = place(grid, what, cell)
        return self._edited(refusal, Edit(ends=(before, (grid.start, grid.goal))))

    def toggle_wall(self, at: State) -> str | None:
        cell = as_cell(at)
        return self._set_wall(cell, not self.grid.is_blocked(cell))

    def _set_wall(self, cell: Cell, wall: bool) -> str | None:
        cost = self.grid.cost(cell)  # an obstacle costs 1: undo puts the terrain back
        costs = [(cell, cost, 1.0)] if wall and cost != 1.0 else []
        return self._edited(set_wall(self.grid, cell, wall), Edit([(cell, not wall, wall)],
                                                                  costs=costs))

    def paint(self, at: State, wall: bool) -> bool:
        """A mouse stroke over ``cell``: an obstacle or free (start and goal stay).  True
        when it changed the map."""
        cell = as_cell(at)
        if cell in (self.grid.start, self.grid.goal) or self.grid.is_blocked(cell) == wall:
            return False
        return self._set_wall(cell, wall) is None

    # -- the terrain brush -----------------------------------------------------------------
    def cycle_brush(self) -> float | None:
        """The next cost of the brush (:data:`BRUSHES`, then off); returns it."""
        at = BRUSHES.index(self.brush) if self.brush in BRUSHES else -1
        self.brush = (BRUSHES + (None,))[at + 1]
        return self.brush

    def paint_cost(self, at: State) -> str | None:
        """The brush's cost on ``cell``: None, or why not."""
        cell = as_cell(at)
        cost = self.brush
        if cost is None:
            return NO_BRUSH
        before = self.grid.cost(cell)
        return self._edited(paint_terrain(self.grid, cell, cost),
                            Edit(costs=[(cell, before, cost)]))

    def stroke_cost(self, at: State) -> bool:
        """A mouse stroke of the brush over ``cell`` (an obstacle, or a cell that costs that
        already, stays): True when it changed the map."""
        cell = as_cell(at)
        grid = self.grid
        if self.brush is None or grid.is_blocked(cell) or grid.cost(cell) == self.brush:
            return False
        return self.paint_cost(cell) is None

    def undo(self, redo: bool = False) -> str | None:
        """Undo the last edit of the map (``redo``: make the last one undone again), the
        cursor on it, from step 0: None, or why nothing changed."""
        history = self.history
        cell = history.redo(self.grid) if redo else history.undo(self.grid)
        if cell is None:
            return "Nothing to redo" if redo else "Nothing to undo"
        self._on_edit(cell)
        return None


__all__ = ["BRUSHES", "NO_BRUSH", "MapEdits", "brush_name"]

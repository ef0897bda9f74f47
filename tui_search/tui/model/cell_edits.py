"""Edits of the map: the cursor, start/goal/obstacle/terrain keys and mouse strokes.

:func:`place`, :func:`set_wall` and :func:`paint_terrain` edit a grid and return ``None``, or a
one-line reason they refused (start on an obstacle, an obstacle on the goal ...).  The session
(:class:`~tui_search.tui.model.session.Session`) records every edit that happens (undo, redo, the
title's "modified": :mod:`~tui_search.tui.model.history`) and starts new runs at step 0.
"""

from __future__ import annotations

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.search.state import State, state_text


def cell_text(cell: State) -> str:
    return state_text(cell)


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


def paint_terrain(grid: Grid, cell: Cell, cost: float) -> str | None:
    """Make ``cell`` cost ``cost`` (the terrain brush; 1 is plain floor)."""
    if grid.is_blocked(cell):
        return f"Cannot paint terrain on an obstacle at {cell_text(cell)}"
    if grid.cost(cell) == cost:
        return f"{cell_text(cell)} already costs {cost:g}"
    grid.set_cost(cell, cost)
    return None

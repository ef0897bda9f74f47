"""Pacman layouts (``.lay``): the mazes of Berkeley CS188's search project, and of the courses
that copy it, read into a grid and written back.

``%`` is a wall, ``P`` Pacman's start, ``.`` a food dot: the goal.  ``o`` (a capsule), ``G`` (a
ghost), the digits (numbered ghosts) and spaces are free cells.  Every row is as wide as the
first.  With several dots the first in the file (the top line first, left to right) is the
goal, and the grid's source says so (:attr:`~tui_search.engine.maps.source.MapSource.note`).

The course counts ``y`` from the bottom row up (``y = 0`` is the last line of the file); the
app counts from the top, as for every map.  :func:`course_cell` turns one into the other.

A save writes the file back with only the cells that changed rewritten (:func:`layout_rows`):
a wall ``%``, the start ``P``, the goal ``.``; a free cell keeps its character (a capsule, a
ghost, a dot after the goal) unless it was the start or a dot before the goal, then a space.
"""

from __future__ import annotations

import os
from array import array

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import MapError, split_lines
from tui_search.engine.maps.source import LAY, MapSource

__all__ = ["FREE", "course_cell", "is_layout", "layout_rows", "parse_layout"]

#: The free cells' characters (besides the start and the dots).
FREE = " oG0123456789"
_KNOWN = frozenset(FREE + "%P.")


def is_layout(path: str | os.PathLike[str]) -> bool:
    """Whether the file is read as a Pacman layout: its name ends in ``.lay``."""
    return os.fsdecode(path).lower().endswith(".lay")


def course_cell(grid: Grid, cell: Cell) -> Cell:
    """``cell`` (y from the top) in the course's coordinates (y from the bottom), and back."""
    return cell[0], grid.height - 1 - cell[1]


def parse_layout(text: str, path: str = "<layout>", *, need_start: bool = True,
                 need_goal: bool = True) -> Grid:
    """The layout's grid; a MapError (``path:line:col: message``) for any text that is not
    one.  ``need_start``/``need_goal`` false: the start, the goal given elsewhere (flags)."""
    bom, raw = split_lines(text)
    lines = [line.removesuffix("\r") for line in raw]
    while lines and not lines[-1].strip():
        lines.pop()  # blank lines at the end (a final newline)
    if not lines:
        raise MapError(path, "empty layout: no rows of % walls, P and .")
    width = len(lines[0])
    blocked = bytearray()
    start: Cell | None = None
    start_at = (0, 0)
    dots: list[Cell] = []
    for y, line in enumerate(lines):
        number = y + 1
        if not line.strip():
            raise MapError(path, "blank line inside the layout", number)
        if len(line) != width:
            raise MapError(path, f"row has {len(line)} cells, expected {width}", number)
        for x, char in enumerate(line):
            if char not in _KNOWN:
                raise MapError(path, f"unknown layout character {char!r} (use % walls, P the "
                               "start, . food, o G digits and spaces free)", number, x + 1)
            if char == "P":
                if start is not None:
                    raise MapError(path, f"a second P (the first is at line {start_at[0]}, "
                                   f"column {start_at[1]})", number, x + 1)
                start, start_at = (x, y), (number, x + 1)
            elif char == ".":
                dots.append((x, y))
        blocked.extend(1 if char == "%" else 0 for char in line)
    if start is None and need_start:
        raise MapError(path, "no P: the layout has no start")
    if not dots and need_goal:
        raise MapError(path, "no . (food): the layout has no goal")
    height = len(lines)
    goal = dots[0] if dots else None
    note = ""
    if len(dots) > 1 and goal is not None:
        cx, cy = goal[0], height - 1 - goal[1]
        note = (f"{len(dots)} dots: the goal is the first, ({goal[0]},{goal[1]}) "
                f"(the course's ({cx},{cy}))")
    source = MapSource(LAY, raw, array("I", range(len(lines))), width, bom, note=note)
    return Grid(width, height, blocked, start, goal, source)


def layout_rows(grid: Grid, old: list[str] | None) -> list[str]:
    """The grid's rows as layout lines; ``old``: the file's rows, whose characters are kept
    where they still mean the cell (see the module's docstring)."""
    goal = grid.goal
    after_goal = (goal[1], goal[0]) if goal is not None else (-1, -1)
    rows = []
    for y in range(grid.height):
        row = []
        for x in range(grid.width):
            cell = (x, y)
            if grid.is_blocked(cell):
                row.append("%")
            elif cell == grid.start:
                row.append("P")
            elif cell == goal:
                row.append(".")
            else:
                was = old[y][x] if old is not None else " "
                keep = was in FREE or (was == "." and (y, x) > after_goal)
                row.append(was if keep else " ")
        rows.append("".join(row))
    return rows

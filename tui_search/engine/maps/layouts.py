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
import re

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import MapError, split_lines
from tui_search.engine.maps.source import LAY, MapSource

__all__ = ["FREE", "course_cell", "is_layout", "layout_rows", "parse_layout"]

#: The free cells' characters (besides the start and the dots).
FREE = " oG0123456789"
_BAD = re.compile(r"[^%P. oG0-9]")
#: A row's bytes to its cells' ``blocked``: 1 for a wall, else 0.
_WALLS = bytes(1 if i == ord("%") else 0 for i in range(256))


def is_layout(path: str | os.PathLike[str]) -> bool:
    """Whether the file is read as a Pacman layout: its name ends in ``.lay``."""
    return os.fsdecode(path).lower().endswith(".lay")


def course_cell(grid: Grid, cell: Cell) -> Cell:
    """``cell`` (y from the top) in the course's coordinates (y from the bottom), and back."""
    return cell[0], grid.height - 1 - cell[1]


def parse_layout(text: str, path: str = "<layout>", *, need_start: bool = True,
                 need_goal: bool = True, first_line: int = 1) -> Grid:
    """The layout's grid; a MapError (``path:line:col: message``) for any text that is not
    one.  ``need_start``/``need_goal`` false: the start, the goal given elsewhere (flags).
    ``first_line``: the file's line of the text's first (a layout inside a course test).

    Read a line at a time into one byte a cell (the file's lines kept as its one string), so
    that a big file costs a few times its size."""
    bom, raw = split_lines(text)
    height = len(raw)
    while height and not raw[height - 1].strip():
        height -= 1  # blank lines at the end (a final newline)
    if not height:
        raise MapError(path, "empty layout: no rows of % walls, P and .")
    width = len(raw[0].removesuffix("\r"))
    blocked = bytearray()
    start: Cell | None = None
    start_at = (0, 0)
    goal: Cell | None = None
    dots = 0
    for y in range(height):
        line, number = raw[y].removesuffix("\r"), y + first_line
        if not line.strip():
            raise MapError(path, "blank line inside the layout", number)
        if len(line) != width:
            raise MapError(path, f"row has {len(line)} cells, expected {width}", number,
                           min(len(line), width) + 1)  # its first extra or missing cell
        bad = _BAD.search(line)
        if bad is not None:
            raise MapError(path, f"unknown layout character {bad.group()!r} (use % walls, P "
                           "the start, . food, o G digits and spaces free)", number,
                           bad.start() + 1)
        row = line.encode("ascii")
        x = row.find(b"P")
        if x >= 0:
            again = row.find(b"P", x + 1) if start is None else x
            if start is not None or again >= 0:
                first = start_at if start is not None else (number, x + 1)
                raise MapError(path, f"a second P (the first is at line {first[0]}, column "
                               f"{first[1]})", number, (again if start is None else x) + 1)
            start, start_at = (x, y), (number, x + 1)
        found = row.count(b".")
        if found and goal is None:
            goal = (row.find(b"."), y)
        dots += found
        blocked += row.translate(_WALLS)
    if start is None and need_start:
        raise MapError(path, "no P: the layout has no start")
    if goal is None and need_goal:
        raise MapError(path, "no . (food): the layout has no goal")
    note = ""
    if dots > 1 and goal is not None:
        note = (f"{dots:,} dots: the goal is the first, ({goal[0]},{goal[1]}) "
                f"(the course's ({goal[0]},{height - 1 - goal[1]}))")
    source = MapSource(LAY, raw, range(height), width, bom, note=note)
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

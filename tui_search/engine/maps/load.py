"""Loading a map file of either format, with the command line's start and goal overrides.

A file whose name ends in ``.lay`` is read as a Pacman layout
(:mod:`tui_search.engine.maps.layouts`); a file whose first non-empty line is ``type ...`` as a
MovingAI map (:mod:`tui_search.engine.maps.movingai`), anything else as our text format
(:mod:`tui_search.engine.maps.text`).  Problems are :class:`~tui_search.engine.maps.read.MapError`;
saving is :mod:`tui_search.engine.maps.write`, scenario files
:mod:`tui_search.engine.maps.scenarios`.
"""

from __future__ import annotations

import os
import re
from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import MAX_DIGITS, MapError, check_cell, quoted, read_map_file
from tui_search.engine.maps.terrain import Terrain
from tui_search.engine.maps.text import parse_text_map

__all__ = ["load_map", "parse_cell", "parse_map_text"]

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph


_TYPE_LINE = re.compile(r"\ufeff?\s*type(?:\s|$)", re.IGNORECASE)


def _is_movingai(text: str) -> bool:
    """Whether the first non-empty line starts with the word ``type`` (without splitting
    the whole text into lines: a big map would be split twice)."""
    return _TYPE_LINE.match(text) is not None


def parse_map_text(
    text: str, path: str = "<map>", *, start: Cell | None = None, goal: Cell | None = None,
    terrain: Terrain | None = None,
) -> Grid:
    """Parse either format (a first line ``type ...`` means MovingAI).

    ``start``/``goal`` override the file's ``S``/``G`` (and make them optional), which is
    how MovingAI maps, having none, get a start and goal.  ``terrain`` is a table of the
    map's characters (``--terrain``; :mod:`tui_search.engine.maps.terrain`).  A start or goal
    placed on a costed cell keeps its cost.
    """
    from tui_search.engine.maps.layouts import is_layout  # (a small module)

    if is_layout(path):
        from tui_search.engine.maps.layouts import parse_layout

        if terrain is not None and terrain.pairs():
            raise MapError(path, "a Pacman layout has no terrain: every move costs 1")
        grid = parse_layout(text, path, need_start=start is None, need_goal=goal is None)
    elif _is_movingai(text):
        from tui_search.engine.maps.movingai import parse_movingai_map  # only for a .map

        grid = parse_movingai_map(text, path, terrain)
    else:
        grid = parse_text_map(text, path, need_start=start is None, need_goal=goal is None,
                              terrain=terrain)
    for cell, what in ((start, "start"), (goal, "goal")):
        if cell is None:
            continue
        check_cell(grid, cell, what, path, None)
        if what == "start":
            grid.start = (cell[0], cell[1])
        else:
            grid.goal = (cell[0], cell[1])
    return grid


def load_board(path: str | os.PathLike[str]) -> Grid | Graph:
    """A map file, or a graph: a ``.graph`` file or a built-in one by name (``romania``)."""
    from tui_search.engine.maps.graph_file import BUILT_IN, built_in_graph, is_graph_file
    from tui_search.engine.maps.graph_file import load_graph as read_graph

    name = os.fspath(path)
    if name in BUILT_IN:
        return built_in_graph(name)
    return read_graph(name) if is_graph_file(name) else load_map(name)


def load_map(
    path: str | os.PathLike[str], *, start: Cell | None = None, goal: Cell | None = None,
    terrain: Terrain | None = None,
) -> Grid:
    """Read a map file of either format (see :func:`parse_map_text` for the overrides).

    The grid's ``source`` remembers the file as read (its ``stamp``), so that saving can
    tell whether someone else changed it since; loading again is how to reload."""
    where = os.fsdecode(path)
    text, stamp = read_map_file(where)
    grid = parse_map_text(text, where, start=start, goal=goal, terrain=terrain)
    if grid.source is not None:
        grid.source = grid.source._replace(stamp=stamp)
    return grid


_CELL = re.compile(r"\(?\s*(-?[0-9]+)\s*,\s*(-?[0-9]+)\s*\)?")


def parse_cell(text: str) -> Cell:
    """``"3,4"`` -> ``(3, 4)`` (column, row from 0); ValueError with a one-line reason."""
    match = _CELL.fullmatch(text.strip())
    if not match:
        raise ValueError(f"expected a cell as X,Y (column,row counted from 0), got {quoted(text)}")
    if any(len(part.lstrip("-0")) > MAX_DIGITS for part in match.groups()):
        raise ValueError(f"cell {quoted(text)} is far too large")
    x, y = int(match.group(1)), int(match.group(2))
    if x < 0 or y < 0:
        raise ValueError(f"cell {quoted(text)} has a negative coordinate")
    return (x, y)

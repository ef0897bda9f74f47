"""Saving a grid: the file for it in either format, written atomically.

Saving keeps the file: a map read from a file carries its text (``Grid.source``, a
:class:`~tui_search.engine.mapsource.MapSource`), and :func:`save_map` writes that text back
with only the characters of edited cells changed, so comments, the MovingAI header, CRLF
line ends and a missing final newline all survive.
"""

from __future__ import annotations

import os

from tui_search.engine.atomic import os_reason, write_atomically
from tui_search.engine.grid import Grid
from tui_search.engine.mapread import MapError
from tui_search.engine.mapsource import MOVINGAI, TEXT, MapSource
from tui_search.engine.movingai import movingai_rows
from tui_search.engine.textmap import text_rows

__all__ = ["format_map", "format_text_map", "kind_for_path", "save_map", "save_text_map"]


def _fits(source: MapSource, grid: Grid) -> bool:
    return (source.width, len(source.rows)) == (grid.width, grid.height)


def _updated(source: MapSource, grid: Grid) -> MapSource:
    """This file with ``grid``'s cells written into its rows (the grid must fit)."""
    if not _fits(source, grid):
        raise ValueError("the grid is not the size of the map file")
    w = source.width
    old = [source.lines[i][:w] for i in source.rows]
    new = text_rows(grid) if source.kind == TEXT else movingai_rows(grid, old)
    lines = list(source.lines)
    for i, before, after in zip(source.rows, old, new):
        if before != after:
            lines[i] = after + lines[i][w:]
    return source._replace(lines=tuple(lines))


def _fresh_source(grid: Grid, kind: str) -> MapSource:
    """A new file for ``grid``: its rows, one per line, ending with a newline (a MovingAI one
    after the ``type octile`` header)."""
    if kind == TEXT:
        header: list[str] = []
        rows = text_rows(grid)
    else:
        header = ["type octile", f"height {grid.height}", f"width {grid.width}", "map"]
        rows = movingai_rows(grid)
    lines = (*header, *rows, "")
    return MapSource(kind, lines, tuple(range(len(header), len(header) + len(rows))), grid.width)


def kind_for_path(path: str | os.PathLike[str]) -> str:
    """The format a new file of this name gets: MovingAI for ``.map``, else the text format."""
    return MOVINGAI if os.fsdecode(path).lower().endswith(".map") else TEXT


def format_map(grid: Grid, kind: str = TEXT) -> MapSource:
    """The file for ``grid`` in format ``kind``: the file it was read from with the edited
    cells rewritten when that file is of this kind, else a fresh one.

    A MovingAI file has no start or goal: they are not written.
    """
    source = grid.source
    if source is not None and source.kind == kind and _fits(source, grid):
        return _updated(source, grid)
    return _fresh_source(grid, kind)


def format_text_map(grid: Grid) -> str:
    """The text-format file for ``grid`` (see :func:`format_map`)."""
    return format_map(grid, TEXT).text()


def save_text_map(grid: Grid, path: str | os.PathLike[str]) -> None:
    """:func:`save_map` in the text format."""
    save_map(grid, path, TEXT)


def save_map(grid: Grid, path: str | os.PathLike[str], kind: str = TEXT) -> MapSource:
    """Write :func:`format_map` of ``grid`` atomically (:func:`write_atomically`) and return
    what was written (the caller makes it the grid's ``source``, so the next save compares with
    the file on disk).  On failure the old file is untouched and a MapError says why."""
    target = os.fsdecode(path)
    source = format_map(grid, kind)
    try:
        write_atomically(target, source.text().encode("utf-8"))
    except FileNotFoundError:
        raise MapError(target, "cannot save: the folder does not exist") from None
    except OSError as err:
        raise MapError(target, f"cannot save: {os_reason(err)}") from None
    return source

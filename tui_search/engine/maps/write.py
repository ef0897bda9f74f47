"""Saving a grid: the file for it in either format, written atomically.

Saving keeps the file: a map read from a file carries its text (``Grid.source``, a
:class:`~tui_search.engine.maps.source.MapSource`), and :func:`save_map` writes that text back
with only the characters of edited cells changed, so comments, the MovingAI header, CRLF
line ends and a missing final newline all survive -- a text map's ``; terrain`` table among
them, and every letter of a terrain table whose cell keeps its cost.  What a format cannot hold
(a start or goal in a ``.map``; the cost under ``S`` or ``G`` in a text map; a cost no character
writes) is said by :func:`save_notes`.  A save never loses someone's work: it
refuses (a MapError subclass the app can ask about) to write a file that would not load, a
read-only file, one changed on disk since it was read, or one with hard links.
"""

from __future__ import annotations

import os
import stat

from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import parse_map_text
from tui_search.engine.maps.movingai import movingai_costs, movingai_rows
from tui_search.engine.maps.read import MAX_MAP_BYTES, MapError, current_stamp, stamp_of, too_big
from tui_search.engine.maps.source import LAY, MOVINGAI, TEXT, FileStamp, MapSource
from tui_search.engine.maps.terrain import TEXT_OWN, Terrain, comment_table, lost_costs, text_costs
from tui_search.engine.maps.text import text_rows
from tui_search.engine.util.atomic import os_reason, write_atomically, write_in_place

__all__ = [
    "ChangedOnDisk",
    "HardLinked",
    "ReadOnlyFile",
    "WouldNotLoad",
    "format_map",
    "format_text_map",
    "kind_for_path",
    "save_map",
    "save_new",
    "save_notes",
    "save_text_map",
]


def _fits(source: MapSource, grid: Grid) -> bool:
    return (source.width, len(source.rows)) == (grid.width, grid.height)


def _updated(source: MapSource, grid: Grid) -> MapSource:
    """This file with ``grid``'s cells written into its rows (the grid must fit)."""
    if not _fits(source, grid):
        raise ValueError("the grid is not the size of the map file")
    w = source.width
    old = [source.lines[i][:w] for i in source.rows]
    chars = characters(grid, source.kind, source)
    if source.kind == LAY:
        from tui_search.engine.maps.layouts import layout_rows

        new = layout_rows(grid, old)
    else:
        new = (text_rows(grid, old, chars) if source.kind == TEXT
               else movingai_rows(grid, old, chars))
    lines = list(source.lines)
    for i, before, after in zip(source.rows, old, new, strict=True):
        if before != after:
            lines[i] = after + lines[i][w:]
    return source._replace(lines=tuple(lines))


def _fresh_source(grid: Grid, kind: str) -> MapSource:
    """A new file for ``grid``: its rows, one per line, ending with a newline (a MovingAI one
    after the ``type octile`` header)."""
    chars = characters(grid, kind)
    if kind == TEXT:
        header: list[str] = []
        rows = text_rows(grid, None, chars)
    elif kind == LAY:
        from tui_search.engine.maps.layouts import layout_rows

        header, rows = [], layout_rows(grid, None)
    else:
        header = ["type octile", f"height {grid.height}", f"width {grid.width}", "map"]
        rows = movingai_rows(grid, None, chars)
    lines = (*header, *rows, "")
    return MapSource(kind, lines, range(len(header), len(header) + len(rows)), grid.width,
                     terrain=given_table(grid, kind).pairs())


def given_table(grid: Grid, kind: str) -> Terrain:
    """The table given with the grid's file (``--terrain``) that a file of ``kind`` can use:
    a text map's takes none of the text format's own characters."""
    pairs = grid.source.terrain if grid.source is not None else ()
    return Terrain({c: v for c, v in pairs if kind != TEXT or c not in TEXT_OWN}, {})


def characters(grid: Grid, kind: str, source: MapSource | None = None
               ) -> dict[str, float | None]:
    """Every character a file of ``kind`` for ``grid`` may write, with what it means: the
    format's own, the table given with the grid's file, and (``source``: the text file being
    written back) its own comment table."""
    if kind == LAY:  # walls and free cells costing 1: no table
        return {"%": None, " ": 1.0}
    table = given_table(grid, kind)
    if kind != TEXT:
        return movingai_costs(table)
    if source is not None:
        table = comment_table(source.lines, "<map>").merged(table)
    return text_costs(table)


def save_notes(grid: Grid, kind: str) -> list[str]:
    """What a save of ``grid`` in format ``kind`` does not keep, one sentence each (the app
    shows them beside "Saved"): the cost under a start or goal in a text map (``S`` and ``G``
    cost 1), and costs no character of the format writes (written as 1)."""
    notes = []
    if kind == TEXT:
        for cell, what in ((grid.start, "start"), (grid.goal, "goal")):
            if cell is not None and grid.is_free(cell) and grid.cost(cell) != 1.0:
                notes.append(f"text format: S and G cost 1, so the cost {grid.cost(cell):g} "
                             f"under the {what} is not kept")
    if grid.costs is not None:
        source = grid.source if grid.source is not None and grid.source.kind == kind else None
        free = [c for c, b in zip(grid.costs, grid.blocked, strict=True) if not b]
        lost = lost_costs(free, characters(grid, kind, source), "SG" if kind == TEXT else "")
        if lost:
            costs = ", ".join(f"{c:g}" for c in lost)
            notes.append(f"no character of this format has cost {costs}: written as 1")
    return notes


def kind_for_path(path: str | os.PathLike[str]) -> str:
    """The format a new file of this name gets: MovingAI for ``.map``, a Pacman layout for
    ``.lay``, else the text format."""
    name = os.fsdecode(path).lower()
    return MOVINGAI if name.endswith(".map") else LAY if name.endswith(".lay") else TEXT


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


def save_new(grid: Grid, path: str | os.PathLike[str]) -> None:
    """Write ``grid`` as a text map to a file that does not exist yet: an existing file (or
    a link, even a dangling one) is never replaced, but refused with a MapError, as is any
    other failure (saying why).  The file is created exclusively, so no other program's
    file made in the meantime is replaced either."""
    target = os.fsdecode(path)
    data = format_text_map(grid).encode("utf-8")
    try:
        with open(target, "xb") as out:
            out.write(data)
    except FileExistsError:
        raise MapError(target, "the file exists; a generated map never replaces a file "
                       "(choose another name)") from None
    except FileNotFoundError:
        raise MapError(target, "cannot save: the folder does not exist") from None
    except (OSError, ValueError) as err:
        reason = os_reason(err) if isinstance(err, OSError) else str(err)
        raise MapError(target, f"cannot save: {reason}") from None


class ReadOnlyFile(MapError):
    """The file may not be written (no write permission bit, or not for this user)."""


class ChangedOnDisk(MapError):
    """Someone else changed the file since it was read or last saved: saving would lose
    their changes.  Save with ``overwrite=True`` to replace them, or load the file again."""


class HardLinked(MapError):
    """The file has other hard links, which replacing it would split.  Save with
    ``in_place=True`` to write it where it is (not atomic), keeping the links."""


class WouldNotLoad(MapError):
    """What would be written could not be opened again (e.g. a text map whose start is its
    goal, or without a start): nothing is written."""


def save_map(
    grid: Grid,
    path: str | os.PathLike[str],
    kind: str = TEXT,
    *,
    overwrite: bool = False,
    in_place: bool = False,
) -> MapSource:
    """Write :func:`format_map` of ``grid`` atomically (:func:`write_atomically`: a symlink's
    target is written, the owner, group and mode are kept) and return what was written with
    its new ``stamp`` (the caller makes it the grid's ``source``, so the next save compares
    with the file on disk).

    Refused, with the file untouched, when what would be written does not load
    (:class:`WouldNotLoad`), the file is not a regular one, is read-only
    (:class:`ReadOnlyFile`), changed on disk since ``grid.source`` was read or saved
    (:class:`ChangedOnDisk`, unless ``overwrite``) or has hard links (:class:`HardLinked`,
    unless ``in_place``: then it is written where it is).  Any other failure is a MapError
    saying why; the old file is then untouched too.
    """
    target = os.fsdecode(path)
    source = format_map(grid, kind)
    text = source.text()
    try:
        parse_map_text(text, target, terrain=given_table(grid, kind))
    except MapError as err:
        raise WouldNotLoad(target,
                           f"cannot save: the file would not open again: {err.message}") from err
    data = text.encode("utf-8")
    if len(data) > MAX_MAP_BYTES:  # (a .map's header, or costs written out, can add bytes)
        raise WouldNotLoad(target, f"cannot save: the file would not open again: "
                           f"{too_big(len(data))}")
    real = os.path.realpath(target)
    old = _existing(target, real)
    if old is not None and not overwrite:
        stamp = grid.source.stamp if grid.source is not None else None
        if stamp is not None and stamp.path == real and _changed(stamp, real, old):
            raise ChangedOnDisk(target, "cannot save: the file changed on disk since it was "
                                "opened or saved")
    if old is not None and old.st_nlink > 1 and not in_place:
        raise HardLinked(target, f"cannot save: the file has {old.st_nlink} hard links, which "
                         "replacing it would split")
    try:
        if old is not None and old.st_nlink > 1:
            write_in_place(real, data)
        else:
            write_atomically(real, data)
        written = os.stat(real)
    except FileNotFoundError:
        raise MapError(target, "cannot save: the folder does not exist") from None
    except OSError as err:
        raise MapError(target, f"cannot save: {os_reason(err)}") from None
    return source._replace(stamp=stamp_of(real, data, written))


def _existing(target: str, real: str) -> os.stat_result | None:
    """The file to be replaced (None when there is none yet), or a MapError when it must not
    be: not a regular file, or read-only (even to root, whose writes the mode does not stop:
    the file's own mode says it is not to be changed)."""
    try:
        st = os.stat(real)
    except OSError:
        return None  # no file yet, or one the write will fail on and say why
    if stat.S_ISDIR(st.st_mode):
        return None  # the write says "is a directory"
    if not stat.S_ISREG(st.st_mode):
        raise MapError(target, "cannot save: not a regular file")
    if not st.st_mode & 0o222 or not os.access(real, os.W_OK):
        raise ReadOnlyFile(target, "cannot save: the file is read-only")
    return st


def _changed(stamp: FileStamp, real: str, now: os.stat_result) -> bool:
    """Whether the file's bytes differ from ``stamp``'s (one that can't be read counts as
    changed: it can't be shown to be the same)."""
    if now.st_size != stamp.size:
        return True
    current = current_stamp(real)
    return current is None or not current.same_bytes(stamp)

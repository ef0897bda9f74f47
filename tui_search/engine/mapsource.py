"""The record of the file a grid was read from (:class:`MapSource`), and the two formats.

It lives apart from the readers and writers so that :class:`~tui_search.engine.grid.Grid`
can hold one (``Grid.source``) without importing them: this module imports nothing from the
engine.  Saving (:mod:`tui_search.engine.mapwrite`) writes the text back with only the
characters of edited cells changed, and refuses to write over a file that changed on disk
since it was read or saved (:class:`FileStamp`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

__all__ = ["MOVINGAI", "TEXT", "FileStamp", "MapSource"]

TEXT, MOVINGAI = "text", "movingai"


class FileStamp(NamedTuple):
    """What a file on disk was when it was read or written: its real path (symlinks
    resolved), size, modification time and the SHA-256 of its bytes.  A file whose size or
    hash differs has been changed by someone else (the time alone only says it was touched)."""

    path: str
    size: int
    mtime_ns: int
    sha256: str

    def same_bytes(self, other: FileStamp) -> bool:
        return (self.size, self.sha256) == (other.size, other.sha256)


class MapSource(NamedTuple):
    """The text a map file holds, kept with the grid read from it so that saving rewrites
    only the characters of the cells that were edited.

    ``lines`` are the file split on ``\\n`` only, each exactly as written (a CRLF line keeps
    its ``\\r``, trailing spaces stay; the last is ``""`` when the file ends in a newline), so
    ``text()`` gives the file back byte for byte.  Row ``y`` of the grid is the first
    ``width`` characters of ``lines[rows[y]]`` (a BOM, if any, is kept apart in ``bom``).
    ``stamp`` is the file as last read or saved (None for text not from a file).
    """

    kind: str  # TEXT or MOVINGAI
    lines: tuple[str, ...]
    rows: Sequence[int]  # a range, or an array of ints: compact for millions of rows
    width: int
    bom: bool = False
    stamp: FileStamp | None = None
    #: The terrain table given with the file (``--terrain``; a text map's own comment table
    #: is in its lines): each character's cost, None for blocked.  Saving reads the file's
    #: characters with it.
    terrain: tuple[tuple[str, float | None], ...] = ()

    def text(self) -> str:
        return ("\ufeff" if self.bom else "") + "\n".join(self.lines)

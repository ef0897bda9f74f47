"""The record of the file a grid was read from (:class:`MapSource`), and the two formats.

It lives apart from the readers and writers so that :class:`~tui_search.engine.maps.grid.Grid`
can hold one (``Grid.source``) without importing them: this module imports nothing from the
engine.  Saving (:mod:`tui_search.engine.maps.write`) writes the text back with only the
characters of edited cells changed, and refuses to write over a file that changed on disk
since it was read or saved (:class:`FileStamp`).
"""

# No future import: CONTRIBUTING.md, "Start-up".
from array import array
from collections.abc import Iterable, Iterator, Sequence
from itertools import accumulate, islice, repeat
from operator import add
from typing import NamedTuple, overload

__all__ = ["LAY", "MOVINGAI", "TEXT", "FileStamp", "Lines", "MapSource"]

TEXT, MOVINGAI, LAY = "text", "movingai", "lay"


class FileStamp(NamedTuple):
    """What a file on disk was when it was read or written: its real path (symlinks
    resolved), size, modification time and the CRC-32 of its bytes.  A file whose size or
    CRC differs has been changed by someone else (the time alone only says it was touched).
    The CRC catches every edit of up to 32 bits in a row and any other but one in 2**32 (of
    the same size): a guard against someone's edit, not an adversary.  Not SHA-256: it is
    taken as the map loads, and ``hashlib`` loads OpenSSL (benchmarks/README.md, "startup";
    ``zlib`` is imported by Textual already)."""

    path: str
    size: int
    mtime_ns: int
    crc32: int

    def same_bytes(self, other: "FileStamp") -> bool:
        return (self.size, self.crc32) == (other.size, other.crc32)


class Lines(Sequence[str]):
    """A text's lines split on ``\\n`` only, each as written, kept as the one string and where
    each line ends.  A map of millions of short rows then costs 4 bytes a line instead of a
    string object each: a few times the file's size to read, not tens of times
    (benchmarks/README.md, "big_map").  A line is made when asked for."""

    __slots__ = ("_found_ends", "text")

    _CHUNK = 1 << 16  # characters split at a time while finding the line ends (a string each)

    def __init__(self, text: str) -> None:
        self.text = text
        self._found_ends: array[int] | None = None

    @property
    def _ends(self) -> "array[int]":
        """Where each line ends, found when a line is first asked for: a map read only to
        be searched never asks (and 4 bytes a row are twice a file of one-cell rows)."""
        if self._found_ends is None:
            self._found_ends = self._line_ends(self.text)
        return self._found_ends

    @classmethod
    def _line_ends(cls, text: str) -> "array[int]":
        # "I" (4 bytes) holds every offset of a map (at most 64 MB); longer texts take "q".
        ends: array[int] = array("I" if len(text) < 1 << 32 else "q")
        for start in range(0, len(text), cls._CHUNK):
            parts = text[start : start + cls._CHUNK].split("\n")
            del parts[-1]  # what follows the chunk's last newline (or the whole chunk)
            # each newline's offset: the lengths before it, plus one for each newline before
            steps = map(add, map(len, parts), repeat(1))
            ends.extend(islice(accumulate(steps, initial=start - 1), 1, None))
        ends.append(len(text))  # the last line ends with the text
        return ends

    @classmethod
    def joined(cls, lines: Iterable[str]) -> "Lines":
        return cls("\n".join(lines))

    def offset(self, index: int) -> int:
        """Where line ``index`` (from 0) starts in the text."""
        return self._ends[index - 1] + 1 if index else 0

    def __len__(self) -> int:
        if self._found_ends is None:
            return self.text.count("\n") + 1
        return len(self._found_ends)

    @overload
    def __getitem__(self, index: int) -> str: ...
    @overload
    def __getitem__(self, index: slice) -> list[str]: ...
    def __getitem__(self, index: int | slice) -> str | list[str]:
        if isinstance(index, slice):
            first, stop, step = index.indices(len(self))
            if step != 1:
                return [self[i] for i in range(first, stop, step)]
            if first >= stop:
                return []
            begin = self._ends[first - 1] + 1 if first else 0
            return self.text[begin : self._ends[stop - 1]].split("\n")
        n = len(self._ends)
        if index < 0:
            index += n
        if not 0 <= index < n:
            raise IndexError("line index out of range")
        begin = self._ends[index - 1] + 1 if index else 0
        return self.text[begin : self._ends[index]]

    def __iter__(self) -> Iterator[str]:
        for start in range(0, len(self), 4096):
            yield from self[start : start + 4096]

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Lines):
            return self.text == other.text
        if isinstance(other, (tuple, list)):
            return len(other) == len(self) and all(a == b for a, b in zip(self, other, strict=True))
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.text)

    def __repr__(self) -> str:
        return f"Lines({len(self)} lines)"


class MapSource(NamedTuple):
    """The text a map file holds, kept with the grid read from it so that saving rewrites
    only the characters of the cells that were edited.

    ``lines`` are the file split on ``\\n`` only, each exactly as written (a CRLF line keeps
    its ``\\r``, trailing spaces stay; the last is ``""`` when the file ends in a newline), so
    ``text()`` gives the file back byte for byte.  Row ``y`` of the grid is the first
    ``width`` characters of ``lines[rows[y]]`` (a BOM, if any, is kept apart in ``bom``).
    ``stamp`` is the file as last read or saved (None for text not from a file).
    """

    kind: str  # TEXT, MOVINGAI or LAY (a Pacman layout)
    lines: Sequence[str]  # Lines, read from a file; a tuple, written by the app
    rows: Sequence[int]  # a range, or an array of ints: compact for millions of rows
    width: int
    bom: bool = False
    stamp: FileStamp | None = None
    #: The terrain table given with the file (``--terrain``; a text map's own comment table
    #: is in its lines): each character's cost, None for blocked.  Saving reads the file's
    #: characters with it.
    terrain: tuple[tuple[str, float | None], ...] = ()
    #: What the reader has to say of the file as read, in a sentence ("" nothing): a Pacman
    #: layout's several dots, the first of which is the goal.
    note: str = ""

    def text(self) -> str:
        body = self.lines.text if isinstance(self.lines, Lines) else "\n".join(self.lines)
        return ("\ufeff" if self.bom else "") + body

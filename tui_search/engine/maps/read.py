"""What every map and scenario reader shares: :class:`MapError`, reading a file safely, and
the small helpers the parsers use.

Every problem with an input file becomes a :class:`MapError` whose ``str`` is one line,
``path:line:col: message``, so the CLI and the app can show it as is instead of a traceback.
The parsers raise nothing else on any text (the tests check this with hypothesis).

Stdlib only: the engine must not depend on the UI libraries.
"""

from __future__ import annotations

import math
import os
import re
import stat
import zlib
from collections.abc import Iterator
from typing import BinaryIO

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.source import FileStamp, Lines
from tui_search.engine.util.atomic import os_reason
from tui_search.engine.util.filenames import describe_name
from tui_search.engine.util.untrusted import BadInput, decode_text

__all__ = [
    "MAX_DIGITS",
    "MAX_MAP_BYTES",
    "NUMBER",
    "MapError",
    "bad_file",
    "block_table",
    "check_cell",
    "each_line",
    "current_stamp",
    "first_bad",
    "plain_rows",
    "quoted",
    "read_map_file",
    "read_text",
    "split_lines",
    "stamp_of",
    "stripped_lines",
    "too_big",
]

#: Bigger files are refused before reading: a 512x512 MovingAI map is 257 KB, so anything
#: near this is a mistake (a wrong file), not a map, and would only hang the app.
MAX_MAP_BYTES = 64 * 1024 * 1024
#: How much more a read asks for at a time when a file holds more than ``os.stat`` said.
_READ_CHUNK = 1024 * 1024

#: Header numbers longer than this are refused: no map is that big, and Python refuses to
#: convert very long digit strings (ValueError) anyway.
MAX_DIGITS = 9
#: A whole number >= 0 as the files write it (header values, scenario fields).
NUMBER = re.compile(r"[0-9]+")


class MapError(Exception):
    """One-line, user-facing error about an input file."""

    def __init__(
        self, path: str, message: str, line: int | None = None, col: int | None = None
    ) -> None:
        # All four go to Exception so that the error pickles and copies like any other.
        super().__init__(path, message, line, col)
        self.path = path
        self.message = message
        self.line = line
        self.col = col

    def __str__(self) -> str:
        where = describe_name(self.path)  # a terminal shows an escape sequence, never runs it
        if self.line is not None:
            where += f":{self.line}"
        if self.col is not None:
            where += f":{self.col}"
        return f"{where}: {self.message}"


def split_lines(text: str) -> tuple[bool, Lines]:
    """Whether the text starts with a BOM, and its lines split on ``\\n`` only (not
    ``str.splitlines``, which also splits on form feeds and other separators, so that line
    numbers match what an editor shows), each as written: a CRLF line keeps its ``\\r``."""
    bom = text.startswith("\ufeff")
    return bom, Lines(text[1:] if bom else text)


def each_line(text: str) -> Iterator[str]:
    """``text.split("\\n")``, a line at a time: a text of millions of lines never becomes a
    list of them (a pointer a line is many times a file of short lines)."""
    start = 0
    while True:
        end = text.find("\n", start)
        if end < 0:
            yield text[start:]
            return
        yield text[start:end]
        start = end + 1


def stripped_lines(text: str) -> Iterator[str]:
    """The lines of :func:`split_lines` without a BOM and trailing whitespace (the ``\\r`` of
    CRLF files included), a line at a time: what the parsers read."""
    return (line.rstrip() for line in each_line(text.removeprefix("\ufeff")))


def quoted(text: str, limit: int = 40) -> str:
    """A short ``repr`` of user text for an error message (keeps the message one line)."""
    if len(text) > limit:
        text = text[:limit] + "..."
    return repr(text)


def read_text(path: str, what: str = "a map", limit: int | None = None) -> str:
    """The file's text, or a MapError saying why it cannot be ``what`` (a map, a trace, an
    exercise file ...; see :func:`read_map_file`).  ``limit``: its largest size in bytes
    (:data:`MAX_MAP_BYTES` unless given)."""
    return read_map_file(path, what, limit)[0]


def read_map_file(path: str, what: str = "a map", limit: int | None = None
                  ) -> tuple[str, FileStamp]:
    """The file's text and its :class:`FileStamp`, or a MapError saying why it cannot be a
    map (or ``what`` it should be), at the line and column of a NUL or of a byte that is not
    UTF-8.

    Only a regular file is read: a FIFO or a device is refused at once (it could block the
    read forever).  The size is checked with ``os.stat`` before anything is read, and the
    read itself is capped too, for files that grow while we look (:func:`_read_capped`).
    """
    data, st = _read_regular(path, what, limit)
    try:
        text = decode_text(data, what)
    except BadInput as err:
        raise bad_file(path, err) from None
    return text, stamp_of(path, data, st)


def bad_file(path: str, err: BadInput) -> MapError:
    """The :class:`MapError` of what is wrong with the file at ``path``."""
    return MapError(path, err.message, err.line, err.col)


def stamp_of(path: str, data: bytes, st: os.stat_result) -> FileStamp:
    """The stamp of the file at ``path`` holding ``data`` (``st`` its ``os.stat``)."""
    real = os.path.realpath(path)
    return FileStamp(real, len(data), st.st_mtime_ns, zlib.crc32(data))


def current_stamp(path: str) -> FileStamp | None:
    """The stamp of the file now at ``path``, or None when there is none (or it cannot be
    read as a map file: then nothing in it can be lost by a save the OS allows)."""
    try:
        data, st = _read_regular(path)
    except MapError:
        return None
    return stamp_of(path, data, st)


def _open_nonblocking(name: str, flags: int) -> int:
    """``open``'s opener: a FIFO swapped in after the ``os.stat`` must not block the open."""
    return os.open(name, flags | getattr(os, "O_NONBLOCK", 0))


def _check_kind(path: str, st: os.stat_result, what: str = "a map",
                limit: int | None = None) -> None:
    if stat.S_ISDIR(st.st_mode):
        raise MapError(path, f"is a directory, not {what} file")
    if not stat.S_ISREG(st.st_mode):
        raise MapError(path, "not a regular file")
    limit = MAX_MAP_BYTES if limit is None else limit
    if st.st_size > limit:
        raise MapError(path, too_big(st.st_size, limit, what))


def _read_regular(path: str, what: str = "a map", limit: int | None = None
                  ) -> tuple[bytes, os.stat_result]:
    """The bytes of the regular file at ``path`` (at most the cap) and its ``os.fstat``."""
    limit = MAX_MAP_BYTES if limit is None else limit
    try:
        _check_kind(path, os.stat(path), what, limit)
    except (FileNotFoundError, NotADirectoryError):
        raise MapError(path, "no such file") from None
    except OSError as err:
        raise MapError(path, os_reason(err)) from None
    except ValueError:  # e.g. an embedded NUL in the path
        raise MapError(path, "not a valid file name") from None
    try:
        with open(path, "rb", opener=_open_nonblocking) as handle:
            st = os.fstat(handle.fileno())
            _check_kind(path, st, what, limit)
            data = _read_capped(handle, st.st_size, limit)
    except IsADirectoryError:
        raise MapError(path, f"is a directory, not {what} file") from None
    except OSError as err:
        raise MapError(path, os_reason(err)) from None
    if len(data) > limit:
        raise MapError(path, too_big(len(data), limit, what))
    return data, st


def _read_capped(handle: BinaryIO, expected: int, limit: int) -> bytes:
    """At most ``limit + 1`` bytes of ``handle`` (one more than the file may have, so a file
    over the limit is seen as one).

    ``handle.read(n)`` allocates ``n`` bytes before it reads, so asking for the cap at once
    costs 64 MB for a six-line map.  Instead ask for what ``os.stat`` said plus one byte (which
    sees a file that grew), then, only while every read is filled (a growing file), for
    bounded chunks up to the cap.  A buffered read returns less than asked only at the end.
    """
    limit += 1
    chunks: list[bytes] = []
    total = 0
    want = min(expected + 1, limit)
    while want > 0:
        chunk = handle.read(want)
        chunks.append(chunk)
        total += len(chunk)
        if len(chunk) < want:
            break
        want = min(_READ_CHUNK, limit - total)
    return b"".join(chunks)


def too_big(size: int, limit: int | None = None, what: str = "a map") -> str:
    """Why a file of ``size`` bytes is refused: ``what`` may be at most ``limit``."""
    limit = MAX_MAP_BYTES if limit is None else limit
    return f"file is {_size(size, ceil=True)}; {what} may be at most {_size(limit)}"


def _size(n: int, ceil: bool = False) -> str:
    """``n`` bytes in MB or KB: a limit as it was set (64 MB), a file's size to a tenth,
    rounded up so that a file just over the limit never reads as "64.0 MB"."""
    unit, name = (1024 * 1024, "MB") if n >= 1024 * 1024 else (1024, "KB")
    if not ceil:
        return f"{n // unit} {name}"
    return f"{math.ceil(n * 10 / unit) / 10:.1f} {name}"


def plain_rows(body: str, allowed: str) -> tuple[int, int] | None:
    """The width and height of ``body`` when it is rows of the ASCII characters ``allowed``,
    all as wide, each but the last ended by ``\\n`` (no ``\\r``, space, blank line or other
    character): a map's rows checked in a few passes over the whole text, not a line at a
    time.  None for any other text, which a reader then reads line by line (and names its
    first problem)."""
    width = body.find("\n")
    width = len(body) if width < 0 else width
    if not width or not body.isascii() or re.search("[^" + re.escape(allowed + "\n") + "]", body):
        return None  # also any "\r", space or tab
    height = (len(body) + 1) // (width + 1)
    if (height * (width + 1) - 1 != len(body) or body.count("\n") != height - 1
            or body[width :: width + 1] != "\n" * (height - 1)):
        return None  # rows of other widths, or blank lines: each newline where a row ends
    return width, height


def first_bad(row: str, bad: re.Pattern[str]) -> int:
    """Index of the first character of ``row`` that ``bad`` matches, or -1."""
    found = bad.search(row)
    return -1 if found is None else found.start()


def block_table(blocked_chars: str) -> bytes:
    table = bytearray(256)
    for ch in blocked_chars:
        table[ord(ch)] = 1
    return bytes(table)


def check_cell(grid: Grid, cell: Cell, what: str, path: str, line: int | None) -> None:
    x, y = cell
    if not grid.in_bounds(cell):
        raise MapError(
            path, f"{what} ({x},{y}) is outside the {grid.width}x{grid.height} map", line
        )
    if grid.is_blocked(cell):
        raise MapError(path, f"{what} ({x},{y}) is on an obstacle", line)

"""Reading and writing map files: our text format, MovingAI ``.map`` and ``.scen``.

Every problem with an input file becomes a :class:`MapError` whose ``str`` is one line,
``path:line:col: message``, so the CLI and the app can show it as is instead of a traceback.
The parsers raise nothing else on any text (the tests check this with hypothesis).

Saving keeps the file: a map read from a file carries its text (:class:`MapSource`), and
:func:`save_map` writes that text back with only the characters of edited cells changed, so
comments, the MovingAI header, CRLF line ends and a missing final newline all survive.

Text format::

    ; a comment
    S#...#
    .#.##G

``.`` free, ``#`` obstacle, ``S`` start, ``G`` goal.  A file whose first non-empty line is
``type ...`` is read as a MovingAI map instead (https://movingai.com/benchmarks/formats.html).

Stdlib only: the engine must not depend on the UI libraries.
"""

from __future__ import annotations

import math
import os
import re
import stat
from typing import BinaryIO, NamedTuple

from tui_search.engine.grid import Cell, Grid

__all__ = [
    "MAX_MAP_BYTES",
    "MOVINGAI",
    "TEXT",
    "MapError",
    "MapSource",
    "Scenario",
    "check_scenario_map",
    "check_scenario_matches",
    "format_map",
    "format_text_map",
    "kind_for_path",
    "load_map",
    "load_scenario",
    "parse_cell",
    "parse_map_text",
    "parse_movingai_map",
    "parse_scenarios",
    "parse_text_map",
    "read_scenarios",
    "save_map",
    "save_text_map",
]

#: Bigger files are refused before reading: a 512x512 MovingAI map is 257 KB, so anything
#: near this is a mistake (a wrong file), not a map, and would only hang the app.
MAX_MAP_BYTES = 64 * 1024 * 1024
#: How much more a read asks for at a time when a file holds more than ``os.stat`` said.
_READ_CHUNK = 1024 * 1024

#: Header numbers longer than this are refused: no map is that big, and Python refuses to
#: convert very long digit strings (ValueError) anyway.
_MAX_DIGITS = 9


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
        where = self.path
        if self.line is not None:
            where += f":{self.line}"
        if self.col is not None:
            where += f":{self.col}"
        return f"{where}: {self.message}"


# -- helpers ------------------------------------------------------------------------------


def _split(text: str) -> tuple[bool, list[str]]:
    """Whether the text starts with a BOM, and its lines split on ``\\n`` only (not
    ``str.splitlines``, which also splits on form feeds and other separators, so that line
    numbers match what an editor shows), each as written: a CRLF line keeps its ``\\r``."""
    bom = text.startswith("\ufeff")
    return bom, (text[1:] if bom else text).split("\n")


def _lines(text: str) -> list[str]:
    """The lines of :func:`_split` without a BOM and trailing whitespace (the ``\\r`` of
    CRLF files included): what the parsers read."""
    return [line.rstrip() for line in _split(text)[1]]


def _show(text: str, limit: int = 40) -> str:
    """A short ``repr`` of user text for an error message (keeps the message one line)."""
    if len(text) > limit:
        text = text[:limit] + "..."
    return repr(text)


def os_reason(err: OSError) -> str:
    """A short lower-case reason for an OS error, without the path (the message names it)."""
    if isinstance(err, FileNotFoundError):
        return "no such file"
    if isinstance(err, PermissionError):
        return "permission denied"
    if isinstance(err, IsADirectoryError):
        return "is a directory"
    if isinstance(err, NotADirectoryError):
        return "a part of the path is not a directory"
    reason = err.strerror or str(err) or type(err).__name__
    return reason[:1].lower() + reason[1:]


def _read_text(path: str) -> str:
    """The file's text, or a MapError saying why it cannot be a map.

    The size is checked with ``os.stat`` before anything is read, and the read itself is
    capped too, for pipes and files that grow while we look (:func:`_read_capped`).
    """
    try:
        st = os.stat(path)
    except (FileNotFoundError, NotADirectoryError):
        raise MapError(path, "no such file") from None
    except OSError as err:
        raise MapError(path, os_reason(err)) from None
    except ValueError:  # e.g. an embedded NUL in the path
        raise MapError(path, "not a valid file name") from None
    if stat.S_ISDIR(st.st_mode):
        raise MapError(path, "is a directory, not a map file")
    if st.st_size > MAX_MAP_BYTES:
        raise MapError(path, _too_big(st.st_size))
    try:
        with open(path, "rb") as handle:
            data = _read_capped(handle, st.st_size)
    except IsADirectoryError:
        raise MapError(path, "is a directory, not a map file") from None
    except OSError as err:
        raise MapError(path, os_reason(err)) from None
    if len(data) > MAX_MAP_BYTES:
        raise MapError(path, _too_big(len(data)))
    if b"\x00" in data:
        raise MapError(path, "binary file, not a text map")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise MapError(path, "binary file, not a text map") from None


def _read_capped(handle: BinaryIO, expected: int) -> bytes:
    """At most ``MAX_MAP_BYTES + 1`` bytes of ``handle`` (one more than a map may have, so a
    file over the limit is seen as one).

    ``handle.read(n)`` allocates ``n`` bytes before it reads, so asking for the cap at once
    costs 64 MB for a six-line map.  Instead ask for what ``os.stat`` said plus one byte (which
    sees a file that grew), then, only while every read is filled (a pipe, a growing file), for
    bounded chunks up to the cap.  A buffered read returns less than asked only at the end.
    """
    limit = MAX_MAP_BYTES + 1
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


def _too_big(size: int) -> str:
    # Round up to a tenth so a file just over the limit never reads as "64.0 MB".
    mb = math.ceil(size * 10 / (1024 * 1024)) / 10
    limit = MAX_MAP_BYTES // (1024 * 1024)
    return f"file is {mb:.1f} MB; a map may be at most {limit} MB"


def _first_bad(row: str, bad: re.Pattern[str]) -> int:
    """Index of the first character of ``row`` that ``bad`` matches, or -1."""
    found = bad.search(row)
    return -1 if found is None else found.start()


def _block_table(blocked_chars: str) -> bytes:
    table = bytearray(256)
    for ch in blocked_chars:
        table[ord(ch)] = 1
    return bytes(table)


# -- text format --------------------------------------------------------------------------

_TEXT_BAD = re.compile(r"[^.#SG]")
_TEXT_BLOCK = _block_table("#")


def parse_text_map(text: str, path: str = "<map>") -> Grid:
    """Parse our text format; the map must have exactly one ``S`` and one ``G``."""
    return _parse_text(text, path, need_start=True, need_goal=True)


def _parse_text(text: str, path: str, *, need_start: bool, need_goal: bool) -> Grid:
    bom, raw = _split(text)
    rows: list[bytes] = []
    row_lines: list[int] = []  # index in ``raw`` of each row
    width = 0
    cells: dict[str, Cell] = {}  # "S"/"G" -> (x, y)
    seen_at: dict[str, tuple[int, int]] = {}  # "S"/"G" -> (line, col), for "a second S"
    blank_line: int | None = None  # first blank line after the rows began
    for number, line in enumerate((line.rstrip() for line in raw), start=1):
        if line.lstrip().startswith(";"):
            continue
        if not line:
            if rows and blank_line is None:
                blank_line = number
            continue
        if blank_line is not None:
            raise MapError(path, "blank line inside the map", blank_line)
        bad = _first_bad(line, _TEXT_BAD)
        if bad >= 0:
            if not rows:
                _check_other_format(line, number, path)
            raise MapError(path, f"unknown cell character {line[bad]!r}", number, bad + 1)
        if not rows:
            width = len(line)
        elif len(line) != width:
            raise MapError(path, f"row has {len(line)} cells, expected {width}", number)
        for letter, what in (("S", "start"), ("G", "goal")):
            x = line.find(letter)
            if x < 0:
                continue
            if letter not in seen_at:
                cells[letter] = (x, len(rows))
                seen_at[letter] = (number, x + 1)
                x = line.find(letter, x + 1)
                if x < 0:
                    continue
            first_line, first_col = seen_at[letter]
            raise MapError(
                path,
                f"a second {what} {letter!r} (the first is at line {first_line}, "
                f"column {first_col})",
                number,
                x + 1,
            )
        rows.append(line.encode("ascii").translate(_TEXT_BLOCK))
        row_lines.append(number - 1)
    if not rows:
        raise MapError(path, "the map is empty")
    if "S" not in cells and need_start:
        raise MapError(path, "no start 'S' in the map")
    if "G" not in cells and need_goal:
        raise MapError(path, "no goal 'G' in the map")
    blocked = bytearray(b"".join(rows))
    source = MapSource(TEXT, tuple(raw), tuple(row_lines), width, bom)
    return Grid(width, len(rows), blocked, cells.get("S"), cells.get("G"), source)


_SCEN_START = re.compile(r"version(?:\s|$)", re.IGNORECASE)
_HEADER_START = re.compile(r"type|height|width|map", re.IGNORECASE)


def _check_other_format(line: str, number: int, path: str) -> None:
    """Name the real problem when the first row of a "text map" is another format's first
    line: a scenario file given as the map, or a MovingAI map whose ``type`` line is missing
    or garbled (no text row starts with a letter other than S or G)."""
    if _SCEN_START.match(line):
        raise MapError(path, "this is a MovingAI scenario file: pass it with --scen", number)
    if _HEADER_START.match(line):
        raise MapError(
            path, f"MovingAI header: expected 'type octile', found {_show(line)}", number
        )


def _text_rows(grid: Grid) -> list[str]:
    """The grid's rows in the text format: ``.`` free, ``#`` obstacle, ``S`` and ``G``.

    A grid without a start or goal has no ``S``/``G``; such a file loads only with
    ``--start``/``--goal`` overrides.  A start or goal on an obstacle is written as
    ``S``/``G``, so it comes back free.
    """
    w = grid.width
    text = bytes(grid.blocked).translate(bytes.maketrans(b"\x00\x01", b".#")).decode("ascii")
    rows = [text[y * w : (y + 1) * w] for y in range(grid.height)]
    for cell, letter in ((grid.start, "S"), (grid.goal, "G")):
        if cell is not None and grid.in_bounds(cell):
            x, y = cell
            rows[y] = rows[y][:x] + letter + rows[y][x + 1 :]
    return rows


def _movingai_rows(grid: Grid, old_rows: list[str] | None = None) -> list[str]:
    """The grid's rows as MovingAI cells.  With the rows of the file it was read from, every
    cell whose passability did not change keeps its letter (``T`` stays a tree, ``S`` swamp);
    a newly blocked cell becomes ``@``, a freed one ``.``."""
    w = grid.width
    out = []
    for y in range(grid.height):
        blocked = grid.row(y)
        old = old_rows[y] if old_rows is not None else None
        if old is not None and old.encode("ascii").translate(_MAI_BLOCK) == blocked:
            out.append(old)
            continue
        cells = list(old) if old is not None else ["."] * w
        for x in range(w):
            if old is None or _MAI_BLOCK[ord(cells[x])] != blocked[x]:
                cells[x] = "@" if blocked[x] else "."
        out.append("".join(cells))
    return out


TEXT, MOVINGAI = "text", "movingai"


class MapSource(NamedTuple):
    """The text a map file holds, kept with the grid read from it so that saving rewrites
    only the characters of the cells that were edited.

    ``lines`` are the file split on ``\\n`` only, each exactly as written (a CRLF line keeps
    its ``\\r``, trailing spaces stay; the last is ``""`` when the file ends in a newline), so
    ``text()`` gives the file back byte for byte.  Row ``y`` of the grid is the first
    ``width`` characters of ``lines[rows[y]]`` (a BOM, if any, is kept apart in ``bom``).
    """

    kind: str  # TEXT or MOVINGAI
    lines: tuple[str, ...]
    rows: tuple[int, ...]
    width: int
    bom: bool = False

    def text(self) -> str:
        return ("\ufeff" if self.bom else "") + "\n".join(self.lines)

    def fits(self, grid: Grid) -> bool:
        return (self.width, len(self.rows)) == (grid.width, grid.height)

    def updated(self, grid: Grid) -> MapSource:
        """This file with ``grid``'s cells written into its rows (the grid must fit)."""
        if not self.fits(grid):
            raise ValueError("the grid is not the size of the map file")
        w = self.width
        old = [self.lines[i][:w] for i in self.rows]
        new = _text_rows(grid) if self.kind == TEXT else _movingai_rows(grid, old)
        lines = list(self.lines)
        for i, before, after in zip(self.rows, old, new):
            if before != after:
                lines[i] = after + lines[i][w:]
        return self._replace(lines=tuple(lines))


def _fresh_source(grid: Grid, kind: str) -> MapSource:
    """A new file for ``grid``: its rows, one per line, ending with a newline (a MovingAI one
    after the ``type octile`` header)."""
    if kind == TEXT:
        header: list[str] = []
        rows = _text_rows(grid)
    else:
        header = ["type octile", f"height {grid.height}", f"width {grid.width}", "map"]
        rows = _movingai_rows(grid)
    lines = (*header, *rows, "")
    return MapSource(kind, lines, tuple(range(len(header), len(header) + len(rows))), grid.width)


def kind_for_path(path: str | os.PathLike) -> str:
    """The format a new file of this name gets: MovingAI for ``.map``, else the text format."""
    return MOVINGAI if os.fsdecode(path).lower().endswith(".map") else TEXT


def format_map(grid: Grid, kind: str = TEXT) -> MapSource:
    """The file for ``grid`` in format ``kind``: the file it was read from with the edited
    cells rewritten when that file is of this kind, else a fresh one.

    A MovingAI file has no start or goal: they are not written.
    """
    source = grid.source
    if source is not None and source.kind == kind and source.fits(grid):
        return source.updated(grid)
    return _fresh_source(grid, kind)


def format_text_map(grid: Grid) -> str:
    """The text-format file for ``grid`` (see :func:`format_map`)."""
    return format_map(grid, TEXT).text()


def save_text_map(grid: Grid, path: str | os.PathLike) -> None:
    """:func:`save_map` in the text format."""
    save_map(grid, path, TEXT)


def save_map(grid: Grid, path: str | os.PathLike, kind: str = TEXT) -> MapSource:
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


def write_atomically(target: str, data: bytes) -> None:
    """Replace ``target`` by ``data``: readers (and a crash) see the old file or the new one,
    never half of one.  A temporary file beside the target is written, fsynced and renamed
    over the target (keeping the target's permissions).  On failure the temporary file is
    removed, the old file is untouched, and the OSError propagates."""
    folder = os.path.dirname(os.path.abspath(target))
    try:
        old_mode: int | None = stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        old_mode = None
    tmp = ""  # set once the temporary file exists, cleared once it has been renamed
    try:
        # os.open with 0o666 applies the umask like any new file (mkstemp would make it
        # private); O_EXCL so that another writer's temporary file is never reused.
        for _ in range(100):
            name = os.path.join(folder, f".{os.path.basename(target)}.{os.urandom(4).hex()}.tmp")
            try:
                fd = os.open(name, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                continue
            tmp = name
            break
        else:  # pragma: no cover - 100 random clashes in a row
            raise FileExistsError("could not pick a temporary file name")
        with os.fdopen(fd, "wb") as handle:
            if old_mode is not None and hasattr(os, "fchmod"):
                os.fchmod(handle.fileno(), old_mode)
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, target)
        tmp = ""
    finally:
        if tmp:
            try:
                os.unlink(tmp)
            except OSError:
                pass
    _fsync_dir(folder)


def _fsync_dir(folder: str) -> None:
    """Make the rename itself durable; best effort (not every OS or filesystem allows it)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


# -- MovingAI .map --------------------------------------------------------------------------

_MAI_BAD = re.compile(r"[^.GS@OTW]")
_MAI_BLOCK = _block_table("@OTW")
_NUMBER = re.compile(r"[0-9]+")


def parse_movingai_map(text: str, path: str = "<map>") -> Grid:
    """Parse a MovingAI map: ``.``, ``G``, ``S`` passable; ``@``, ``O``, ``T``, ``W`` blocked.

    MovingAI maps carry no start or goal, so both are None.
    """
    bom, raw = _split(text)
    lines = [line.rstrip() for line in raw]
    n = len(lines)
    i = 0
    while i < n and not lines[i]:
        i += 1
    if i == n or lines[i].split()[0].lower() != "type":
        raise MapError(path, "expected 'type octile' on the first line", i + 1 if i < n else 1)
    i += 1
    header: dict[str, tuple[int, int]] = {}  # name -> (value, line)
    map_line = 0
    while i < n:
        number, line = i + 1, lines[i]
        i += 1
        if not line:
            continue
        words = line.split()
        key = words[0].lower()
        if key == "map" and len(words) == 1:
            map_line = number
            break
        if key in ("height", "width"):
            if key in header:
                raise MapError(path, f"{key} is given twice", number)
            if len(words) != 2 or not _NUMBER.fullmatch(words[1]):
                raise MapError(path, f"expected '{key} N', found {_show(line)}", number)
            if len(words[1].lstrip("0")) > _MAX_DIGITS:
                raise MapError(path, f"{key} is too large: {_show(words[1], 12)}", number)
            value = int(words[1])
            if value < 1:
                raise MapError(path, f"{key} must be at least 1", number)
            header[key] = (value, number)
            continue
        raise MapError(path, f"expected 'height', 'width' or 'map', found {_show(line)}", number)
    if not map_line:
        last_text = max((k + 1 for k in range(n) if lines[k]), default=1)
        raise MapError(path, "the header has no 'map' line", last_text)
    for key in ("height", "width"):
        if key not in header:
            raise MapError(path, f"the header has no {key}", map_line)
    height, height_line = header["height"]
    width = header["width"][0]
    last = n
    while last > i and not lines[last - 1]:
        last -= 1  # trailing blank lines (a final newline, or more) are not rows
    rows: list[bytes] = []
    for k in range(i, last):
        number, line = k + 1, lines[k]
        if len(rows) == height:
            raise MapError(path, f"more rows than the height ({height}) in the header", number)
        if not line:
            raise MapError(path, "blank line inside the map", number)
        bad = _first_bad(line, _MAI_BAD)
        if bad >= 0:
            raise MapError(path, f"unknown cell character {line[bad]!r}", number, bad + 1)
        if len(line) != width:
            raise MapError(path, f"row has {len(line)} cells, expected {width}", number)
        rows.append(line.encode("ascii").translate(_MAI_BLOCK))
    if len(rows) < height:
        found = f"{len(rows)} row" + ("" if len(rows) == 1 else "s")
        raise MapError(
            path, f"the header says height {height} but the map has {found}", height_line
        )
    source = MapSource(MOVINGAI, tuple(raw), tuple(range(i, last)), width, bom)
    return Grid(width, height, bytearray(b"".join(rows)), source=source)


# -- dispatch and loading ------------------------------------------------------------------


_TYPE_LINE = re.compile(r"\ufeff?\s*type(?:\s|$)", re.IGNORECASE)


def _is_movingai(text: str) -> bool:
    """Whether the first non-empty line starts with the word ``type`` (without splitting
    the whole text into lines: a big map would be split twice)."""
    return _TYPE_LINE.match(text) is not None


def parse_map_text(
    text: str, path: str = "<map>", *, start: Cell | None = None, goal: Cell | None = None
) -> Grid:
    """Parse either format (a first line ``type ...`` means MovingAI).

    ``start``/``goal`` override the file's ``S``/``G`` (and make them optional), which is
    how MovingAI maps, having none, get a start and goal.
    """
    if _is_movingai(text):
        grid = parse_movingai_map(text, path)
    else:
        grid = _parse_text(text, path, need_start=start is None, need_goal=goal is None)
    for cell, what in ((start, "start"), (goal, "goal")):
        if cell is None:
            continue
        _check_cell(grid, cell, what, path, None)
        if what == "start":
            grid.start = (cell[0], cell[1])
        else:
            grid.goal = (cell[0], cell[1])
    return grid


def load_map(
    path: str | os.PathLike, *, start: Cell | None = None, goal: Cell | None = None
) -> Grid:
    """Read a map file of either format (see :func:`parse_map_text` for the overrides)."""
    where = os.fsdecode(path)
    return parse_map_text(_read_text(where), where, start=start, goal=goal)


def _check_cell(grid: Grid, cell: Cell, what: str, path: str, line: int | None) -> None:
    x, y = cell
    if not grid.in_bounds(cell):
        raise MapError(
            path, f"{what} ({x},{y}) is outside the {grid.width}x{grid.height} map", line
        )
    if grid.is_blocked(cell):
        raise MapError(path, f"{what} ({x},{y}) is on an obstacle", line)


_CELL = re.compile(r"\(?\s*(-?[0-9]+)\s*,\s*(-?[0-9]+)\s*\)?")


def parse_cell(text: str) -> Cell:
    """``"3,4"`` -> ``(3, 4)`` (column, row from 0); ValueError with a one-line reason."""
    match = _CELL.fullmatch(text.strip())
    if not match:
        raise ValueError(f"expected a cell as X,Y (column,row counted from 0), got {_show(text)}")
    if any(len(part.lstrip("-0")) > _MAX_DIGITS for part in match.groups()):
        raise ValueError(f"cell {_show(text)} is far too large")
    x, y = int(match.group(1)), int(match.group(2))
    if x < 0 or y < 0:
        raise ValueError(f"cell {_show(text)} has a negative coordinate")
    return (x, y)


# -- MovingAI .scen ------------------------------------------------------------------------


class Scenario(NamedTuple):
    """One benchmark problem: a start and goal on a named map, with its optimal length."""

    bucket: int
    map_name: str  # as written in the file; may include directories (match by basename)
    width: int
    height: int
    start: Cell
    goal: Cell
    optimal_length: float
    line: int  # 1-based line in the .scen file, for error messages


_VERSION = re.compile(r"version\s+[0-9]+(\.[0-9]+)?", re.IGNORECASE)
_FIELDS = (
    "bucket", "map", "map width", "map height",
    "start x", "start y", "goal x", "goal y", "optimal length",
)  # fmt: skip


def read_scenarios(path: str | os.PathLike) -> list[Scenario]:
    """Every problem in a ``.scen`` file, in file order."""
    where = os.fsdecode(path)
    return parse_scenarios(_read_text(where), where)


def parse_scenarios(text: str, path: str = "<scen>") -> list[Scenario]:
    """Every problem in the text of a ``.scen`` file (``path`` is only for messages)."""
    lines = _lines(text)
    if not _VERSION.fullmatch(lines[0].strip()):
        found = _show(lines[0]) if lines[0] else "an empty line"
        raise MapError(path, f"expected 'version 1' on the first line, found {found}", 1)
    out = []
    for number, line in enumerate(lines[1:], start=2):
        if not line.strip():
            continue
        fields = [f.strip() for f in line.split("\t")]
        if len(fields) != 9:
            fields = line.split()
        if len(fields) != 9:
            raise MapError(
                path,
                f"expected 9 fields ({', '.join(_FIELDS)}), found {len(fields)}",
                number,
            )
        ints = []
        for k in (0, 2, 3, 4, 5, 6, 7):
            word = fields[k]
            if not _NUMBER.fullmatch(word) or len(word.lstrip("0")) > _MAX_DIGITS:
                raise MapError(
                    path, f"{_FIELDS[k]} is not a whole number >= 0: {_show(word)}", number
                )
            ints.append(int(word))
        bucket, width, height, sx, sy, gx, gy = ints
        try:
            length = float(fields[8])
        except ValueError:
            length = math.nan
        if not (math.isfinite(length) and length >= 0):
            raise MapError(path, f"optimal length is not a number >= 0: {_show(fields[8])}", number)
        if not fields[1]:
            raise MapError(path, "the map name is empty", number)
        if width < 1 or height < 1:
            raise MapError(path, f"map size {width}x{height} is empty", number)
        for what, (x, y) in (("start", (sx, sy)), ("goal", (gx, gy))):
            if x >= width or y >= height:
                raise MapError(
                    path, f"{what} ({x},{y}) is outside the {width}x{height} map", number
                )
        out.append(Scenario(bucket, fields[1], width, height, (sx, sy), (gx, gy), length, number))
    return out


def load_scenario(path: str | os.PathLike, row: int) -> Scenario:
    """Problem number ``row`` (from 0, after the version line) of a ``.scen`` file."""
    where = os.fsdecode(path)
    scenarios = read_scenarios(where)
    if 0 <= row < len(scenarios):
        return scenarios[row]
    if not scenarios:
        raise MapError(where, f"no row {row}: the file has no scenario rows")
    count = len(scenarios)
    rows = "1 row (row 0)" if count == 1 else f"{count} rows (0 to {count - 1})"
    raise MapError(where, f"no row {row}: the file has {rows}")


def _basename(name: str) -> str:
    """Basename for either separator: scenario files written on Windows use backslashes."""
    return re.split(r"[\\/]", name)[-1]


def check_scenario_map(
    scen: Scenario, scen_path: str | os.PathLike, map_path: str | os.PathLike
) -> None:
    """Raise MapError (at the scenario's line) unless ``scen`` names the map ``map_path``.

    Check this before the scenario's start and goal are put on the grid: on another map they
    would be refused for the wrong reason ("start is on an obstacle").  Maps are matched by
    basename because older files give a path (``maps/dao/x.map``).
    """
    where = os.fsdecode(scen_path)
    map_name = _basename(os.fsdecode(map_path))
    wanted = _basename(scen.map_name)
    if wanted != map_name:
        raise MapError(
            where, f"{_basename(where)} is for {wanted}, not {map_name}", scen.line
        )


def check_scenario_matches(
    scen: Scenario, grid: Grid, scen_path: str | os.PathLike, map_path: str | os.PathLike
) -> None:
    """Raise MapError (at the scenario's line) unless ``scen`` is a problem on this map:
    its name (:func:`check_scenario_map`), its size, then its start and goal.

    The spec's "scale the map to the scenario's size" is not supported: sizes must match.
    """
    check_scenario_map(scen, scen_path, map_path)
    where = os.fsdecode(scen_path)
    map_name = _basename(os.fsdecode(map_path))
    if (scen.width, scen.height) != (grid.width, grid.height):
        raise MapError(
            where,
            f"scenario says the map is {scen.width}x{scen.height}, "
            f"but {map_name} is {grid.width}x{grid.height}",
            scen.line,
        )
    _check_cell(grid, scen.start, "start", where, scen.line)
    _check_cell(grid, scen.goal, "goal", where, scen.line)

"""Our text map format: reading it into a grid, and the grid's rows written in it.

Text format::

    ; a comment
    S#...#
    .#.##G

``.`` free, ``#`` obstacle, ``S`` start, ``G`` goal; ``1``-``9`` free cells of that cost, and
the letters of a terrain table (:mod:`tui_search.engine.maps.terrain`: ``--terrain FILE``, or the
map's own ``; terrain f 5`` comment lines).  A first row that is really another
format's first line (a scenario file, a MovingAI header without its ``type`` line) is named
as such instead of as a bad cell.
"""

from __future__ import annotations

import re
from array import array

from tui_search.engine.maps.grid import Cell, Grid
from tui_search.engine.maps.read import MapError, first_bad, plain_rows, quoted, split_lines
from tui_search.engine.maps.source import TEXT, Lines, MapSource
from tui_search.engine.maps.terrain import (
    EMPTY,
    Alphabet,
    Terrain,
    comment_table,
    text_costs,
    write_row,
)

__all__ = ["parse_text_map", "text_rows"]

def parse_text_map(
    text: str, path: str = "<map>", *, need_start: bool = True, need_goal: bool = True,
    terrain: Terrain | None = None,
) -> Grid:
    """Parse our text format; the map must have exactly one ``S`` and one ``G`` (at most
    one where ``need_start``/``need_goal`` is false).  ``terrain``: a table from elsewhere
    (``--terrain``), which wins over the map's own comment table where both name a letter."""
    bom, raw = split_lines(text)  # kept in the grid's source (the text itself, not a copy)
    own = comment_table(raw, path) if ";" in raw.text else EMPTY  # (a plain map: no lines)
    table = own.merged(terrain or EMPTY)
    table.check_text()
    cells_of = Alphabet(text_costs(table))
    fast = _plain_map(raw, cells_of, path, need_start=need_start, need_goal=need_goal)
    if fast is not None:
        first, width, height, blocked, ends, costs = fast
        source = MapSource(TEXT, raw, range(first, first + height), width, bom,
                           terrain=(terrain or EMPTY).pairs())
        return Grid(width, height, blocked, ends.get("S"), ends.get("G"), source, costs)
    costs = None
    # Compact, as a big map has millions of rows: the cells, and where each row is in ``raw``.
    blocked = bytearray()
    row_lines = array("I")  # line numbers of a map of at most 64 MB
    height = 0
    width = 0
    cells: dict[str, Cell] = {}  # "S"/"G" -> (x, y)
    seen_at: dict[str, tuple[int, int]] = {}  # "S"/"G" -> (line, col), for "a second S"
    blank_line: int | None = None  # first blank line after the rows began
    for number, line in enumerate((line.rstrip() for line in raw), start=1):
        if line.lstrip().startswith(";"):
            continue
        if not line:
            if height and blank_line is None:
                blank_line = number
            continue
        if blank_line is not None:
            raise MapError(path, "blank line inside the map", blank_line)
        bad = first_bad(line, cells_of.bad)
        if bad >= 0:
            if not height:
                _check_other_format(line, number, path)
            raise MapError(path, f"unknown cell character {line[bad]!r}", number, bad + 1)
        if not height:
            width = len(line)
        elif len(line) != width:
            raise MapError(path, f"row has {len(line)} cells, expected {width}", number)
        _note_ends(line, number, height, cells, seen_at, path)
        costs = cells_of.add_row(line, blocked, costs)
        row_lines.append(number - 1)
        height += 1
    if not height:
        raise MapError(path, "the map is empty")
    if "S" not in cells and need_start:
        raise MapError(path, "no start 'S' in the map")
    if "G" not in cells and need_goal:
        raise MapError(path, "no goal 'G' in the map")
    first = row_lines[0]
    row_index = range(first, first + height) if row_lines[-1] == first + height - 1 else row_lines
    source = MapSource(TEXT, raw, row_index, width, bom, terrain=(terrain or EMPTY).pairs())
    return Grid(width, height, blocked, cells.get("S"), cells.get("G"), source, costs)


def _note_ends(line: str, number: int, y: int, cells: dict[str, Cell],
               seen_at: dict[str, tuple[int, int]], path: str) -> None:
    """The start and the goal on row ``y`` (``line``, line ``number`` of the file) put in
    ``cells``, and where each was in ``seen_at``; a second one is an error naming the first."""
    for letter, what in (("S", "start"), ("G", "goal")):
        x = line.find(letter)
        if x < 0:
            continue
        if letter not in seen_at:
            cells[letter] = (x, y)
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


_Plain = tuple[int, int, int, bytearray, dict[str, Cell], "array[float] | None"]

#: Comment and blank lines, each ended by its newline: what may come before and after the rows
#: of a map read whole.
_NOT_ROWS = re.compile(r"(?:[^\S\n]*(?:;[^\n]*)?\n)*")


def _not_rows(text: str) -> int:
    """Where the comment and blank lines at the start of ``text`` end."""
    found = _NOT_ROWS.match(text)
    return 0 if found is None else found.end()


def _plain_map(raw: Lines, cells_of: Alphabet, path: str, *, need_start: bool,
               need_goal: bool) -> _Plain | None:
    """The map read in a few passes over the whole text, when it is plain: rows of ASCII
    cells, all as wide, one after the other (each ended by ``\\n`` or ``\\r\\n``), with comment
    and blank lines only before and after them, at most one ``S`` and one ``G``.  None for
    any other text, which the line by line reader takes (and names its first problem).  A
    map of millions of rows then reads in a few passes, not line by line
    (benchmarks/README.md, "big_map").  Gives the lines before the rows and the same grid as
    the line by line reader (a hypothesis test checks it)."""
    text = raw.text
    start = _not_rows(text)
    first = text.count("\n", 0, start)
    allowed = "".join(cells_of.chars)  # never ";" nor a space: no table names them
    after = re.compile("\r?\n(?![" + re.escape(allowed) + "])").search(text, start)
    stop = len(text) if after is None else after.start()
    if after is not None and _not_rows(text[after.end():] + "\n") < len(text) - after.end() + 1:
        return None  # a row after a comment or a blank line, or a line of spaces and cells
    body = text[start:stop]
    if "\r" in body:
        body = body.replace("\r\n", "\n")
    size = plain_rows(body, allowed)
    if size is None:
        return None
    width, height = size
    cells: dict[str, Cell] = {}
    for letter in "SG":
        at = body.find(letter)
        if at >= 0 and body.find(letter, at + 1) >= 0:
            return None  # the line by line reader names the second one
        if at >= 0:
            cells[letter] = (at % (width + 1), at // (width + 1))
    for letter, what, needed in (("S", "start", need_start), ("G", "goal", need_goal)):
        if needed and letter not in cells:
            raise MapError(path, f"no {what} {letter!r} in the map")
    blocked, costs = cells_of.whole(body.replace("\n", ""))
    return first, width, height, blocked, cells, costs


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
            path, f"MovingAI header: expected 'type octile', found {quoted(line)}", number
        )


def text_rows(grid: Grid, old_rows: list[str] | None = None,
              chars: dict[str, float | None] | None = None) -> list[str]:
    """The grid's rows in the text format: ``.`` free, ``#`` obstacle, ``S`` and ``G``, and a
    costed cell's digit or letter (``chars``: the format's characters with the map's table).
    With the rows of the file it was read from, a cell that still means what it did keeps its
    character (a table's letter stays).

    A grid without a start or goal has no ``S``/``G``; such a file loads only with
    ``--start``/``--goal`` overrides.  A start or goal on an obstacle is written as
    ``S``/``G``, so it comes back free; on a costed cell, so it comes back at cost 1.
    """
    w = grid.width
    chars = chars or text_costs(EMPTY)
    text = bytes(grid.blocked).translate(bytes.maketrans(b"\x00\x01", b".#")).decode("ascii")
    rows = [text[y * w : (y + 1) * w] for y in range(grid.height)]
    costs = grid.costs
    for y in range(grid.height):
        old = old_rows[y] if old_rows is not None else None
        row_costs = costs[y * w : (y + 1) * w] if costs is not None else None
        plain_costs = row_costs is None or row_costs.count(1.0) == w
        if plain_costs and (old is None or _PLAIN_ROW.fullmatch(old)):
            continue
        rows[y] = write_row(grid.row(y), row_costs or [1.0] * w, old, chars, "#")
    for cell, letter in ((grid.start, "S"), (grid.goal, "G")):
        if cell is not None and grid.in_bounds(cell):
            x, y = cell
            rows[y] = rows[y][:x] + letter + rows[y][x + 1 :]
    return rows


_PLAIN_ROW = re.compile(r"[.#SG]*")

"""MovingAI ``.map`` files (https://movingai.com/benchmarks/formats.html): reading one into
a grid, and the grid's rows written as MovingAI cells.

A MovingAI map has a header (``type octile``, ``height``, ``width``, ``map``) and rows of
``.``, ``G``, ``S`` (passable) and ``@``, ``O``, ``T``, ``W`` (blocked); it has no start or
goal.  A terrain table (:mod:`tui_search.engine.maps.terrain`, ``--terrain``) gives its letters
costs or blocks them (``S 3`` a swamp of cost 3, ``T 5`` trees one may walk through, at 5); a
letter it does not name is passable or blocked as above.
"""

from __future__ import annotations

from array import array

from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.read import (
    MAX_DIGITS,
    NUMBER,
    MapError,
    block_table,
    first_bad,
    plain_rows,
    quoted,
    split_lines,
)
from tui_search.engine.maps.source import MOVINGAI, Lines, MapSource
from tui_search.engine.maps.terrain import EMPTY, Alphabet, Terrain, write_row

__all__ = ["movingai_rows", "parse_movingai_map"]

_MAI_BLOCK = block_table("@OTW")
#: MovingAI's characters and what they mean without a table (None: blocked).
MAI_OWN: dict[str, float | None] = {".": 1.0, "G": 1.0, "S": 1.0, "@": None, "O": None,
                                    "T": None, "W": None}


def movingai_costs(table: Terrain) -> dict[str, float | None]:
    """Every character of a MovingAI map with this table: its own and the table's."""
    return {**MAI_OWN, **table.costs}


def parse_movingai_map(text: str, path: str = "<map>", terrain: Terrain | None = None) -> Grid:
    """Parse a MovingAI map: ``.``, ``G``, ``S`` passable; ``@``, ``O``, ``T``, ``W`` blocked
    (unless the ``terrain`` table says otherwise).

    MovingAI maps carry no start or goal, so both are None.
    """
    table = terrain or EMPTY
    cells_of = Alphabet(movingai_costs(table))
    costs: array[float] | None = None
    bom, raw = split_lines(text)  # kept in the grid's source (the text itself, not a copy)
    lines = _Stripped(raw)  # each line without trailing whitespace, made when read
    n = len(lines)
    i, width, height, height_line = _read_header(lines, path)
    whole = _whole_rows(raw, i, width, height, cells_of)
    if whole is not None:
        source = MapSource(MOVINGAI, raw, range(i, i + height), width, bom, terrain=table.pairs())
        return Grid(width, height, whole[0], source=source, costs=whole[1])
    last = n
    while last > i and not lines[last - 1]:
        last -= 1  # trailing blank lines (a final newline, or more) are not rows
    blocked = bytearray()  # compact, as a big map has millions of rows
    for k in range(i, last):
        number, line = k + 1, lines[k]
        if k - i == height:
            raise MapError(path, f"more rows than the height ({height}) in the header", number)
        if not line:
            raise MapError(path, "blank line inside the map", number)
        bad = first_bad(line, cells_of.bad)
        if bad >= 0:
            raise MapError(path, f"unknown cell character {line[bad]!r}", number, bad + 1)
        if len(line) != width:
            raise MapError(path, f"row has {len(line)} cells, expected {width}", number)
        costs = cells_of.add_row(line, blocked, costs)
    if last - i < height:
        found = f"{last - i} row" + ("" if last - i == 1 else "s")
        raise MapError(
            path, f"the header says height {height} but the map has {found}", height_line
        )
    source = MapSource(MOVINGAI, raw, range(i, last), width, bom, terrain=table.pairs())
    return Grid(width, height, blocked, source=source, costs=costs)


def _whole_rows(raw: Lines, first: int, width: int, height: int,
                cells_of: Alphabet) -> "tuple[bytearray, array[float] | None] | None":
    """The rows from line ``first`` on read in a few passes over the whole text, when they
    are plain (:func:`~tui_search.engine.maps.read.plain_rows`, each ended by ``\\n`` or
    ``\\r\\n``, then only blank lines) and as many and as wide as the header says: which cells
    are blocked, and their costs.  None for any other rows, read line by line (which names
    their first problem); a hypothesis test holds the two equal."""
    body = raw.text[raw.offset(first):].rstrip()
    if "\r" in body:
        body = body.replace("\r\n", "\n")
    if plain_rows(body, "".join(cells_of.chars)) != (width, height):
        return None
    return cells_of.whole(body.replace("\n", ""))


def _read_header(lines: _Stripped, path: str) -> tuple[int, int, int, int]:
    """The header: ``type``, then ``height`` and ``width`` in any order, then ``map``, blank
    lines allowed.  The index of the line after ``map``, the width, the height and the
    height's line number."""
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
            header[key] = (_header_number(key, words, line, number, path), number)
            continue
        raise MapError(path, f"expected 'height', 'width' or 'map', found {quoted(line)}", number)
    if not map_line:
        last_text = max((k + 1 for k in range(n) if lines[k]), default=1)
        raise MapError(path, "the header has no 'map' line", last_text)
    for key in ("height", "width"):
        if key not in header:
            raise MapError(path, f"the header has no {key}", map_line)
    height, height_line = header["height"]
    return i, header["width"][0], height, height_line


def _header_number(key: str, words: list[str], line: str, number: int, path: str) -> int:
    """The value of the header's line ``key N`` (``words``: ``line``'s, line ``number``)."""
    if len(words) != 2 or not NUMBER.fullmatch(words[1]):
        raise MapError(path, f"expected '{key} N', found {quoted(line)}", number)
    if len(words[1].lstrip("0")) > MAX_DIGITS:
        raise MapError(path, f"{key} is too large: {quoted(words[1], 12)}", number)
    value = int(words[1])
    if value < 1:
        raise MapError(path, f"{key} must be at least 1", number)
    return value


def movingai_rows(grid: Grid, old_rows: list[str] | None = None,
                  chars: dict[str, float | None] | None = None) -> list[str]:
    """The grid's rows as MovingAI cells (``chars``: the format's characters with the map's
    table).  With the rows of the file it was read from, every cell that still means what it
    did keeps its letter (``T`` stays a tree, ``S`` swamp); a newly blocked cell becomes
    ``@``, a freed one ``.``, a cell of a new cost the table's letter of that cost."""
    w = grid.width
    chars = chars or MAI_OWN
    block = Alphabet(chars).block
    costs = grid.costs
    out = []
    for y in range(grid.height):
        blocked = grid.row(y)
        old = old_rows[y] if old_rows is not None else None
        row_costs = costs[y * w : (y + 1) * w] if costs is not None else None
        if row_costs is None or row_costs.count(1.0) == w:  # every cell costs 1
            if old is None:
                out.append(blocked.translate(_MAI_WRITE).decode("ascii"))
                continue
            if old.isascii() and old.encode("ascii").translate(block) == blocked and (
                    not _costed_in(old, chars)):
                out.append(old)
                continue
        out.append(write_row(blocked, row_costs or [1.0] * w, old, chars, "@", endpoints=""))
    return out


#: A plain row's cells: ``.`` free, ``@`` blocked.
_MAI_WRITE = bytes.maketrans(b"\x00\x01", b".@")


def _costed_in(row: str, chars: dict[str, float | None]) -> bool:
    return any(chars.get(c) not in (None, 1.0) for c in set(row))


class _Stripped:
    """The lines of a map without their trailing whitespace (a CRLF's ``\\r`` too), each made
    when asked for, so a map of millions of rows holds no second copy of them."""

    def __init__(self, lines: Lines) -> None:
        self._lines = lines

    def __len__(self) -> int:
        return len(self._lines)

    def __getitem__(self, index: int) -> str:
        return self._lines[index].rstrip()

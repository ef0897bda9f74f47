"""Terrain tables: which map characters are free cells of a cost, and which are blocked.

A table is a file of lines ``CHAR COST`` (a number from 0.01 on: ``0.5``, ``19``, ``99``) or
``CHAR blocked``, with ``;`` comment lines, given with ``--terrain FILE``.  It names the
characters of a map: letters in text maps (``f 5``, ``w 12``) and MovingAI's terrain letters
(``S`` swamp, ``W`` water, ``T`` trees) in ``.map`` files.  A text map may also carry its table
in its own comments, ``; terrain f 5`` lines (:func:`comment_table`).  Text maps have their own
characters, which no table may redefine: ``.``, ``S`` and ``G`` cost 1, ``#`` is blocked and the
digits ``1``-``9`` cost themselves.  Every problem is a one-line
:class:`~tui_search.engine.maps.read.MapError` naming the table's line.
"""

# No future import: CONTRIBUTING.md, "Start-up".
import math
import re
from array import array
from collections.abc import Iterable, Mapping
from typing import NamedTuple

from tui_search.engine.maps.read import MapError, block_table, each_line, quoted, read_text
from tui_search.engine.maps.source import Lines

__all__ = ["EMPTY", "MIN_COST", "TEXT_OWN", "Alphabet", "Terrain", "char_for", "comment_table",
           "load_terrain", "lost_costs", "parse_terrain", "text_costs", "write_row"]

#: Bigger terrain tables are refused before reading (a table is a line a terrain), and so are
#: tables of more terrains than this.
MAX_TERRAIN_BYTES = 16 * 1024
MAX_TERRAINS = 256
#: A cost as a table writes it: digits with at most one decimal point.
_COST = re.compile(r"[0-9]+(?:\.[0-9]*)?|\.[0-9]+")
#: Costs above this are refused: a typo, not a terrain (and no sum of them loses precision).
MAX_COST = 1e9
#: Costs below this are refused: the app shows costs to 2 decimals, so a smaller one would
#: show as 0.00 (and a path of them cost 0.0 in the JSON), against "every cost is above 0".
MIN_COST = 0.01
#: A comment line of a text map that is a table line: ``; terrain f 5``.
#: A comment line that is a table's line: ``; terrain CHAR COST`` (one character, one word).
#: Any other comment, ``; terrain is rough here`` included, stays a comment.
_COMMENT_TABLE = re.compile(r"\s*;\s*terrain\s+(\S\s+\S+)\s*$")
#: The same lines found in a whole text (``[^\S\n]``: a space that does not end the line).
_COMMENT_TABLES = re.compile(
    r"^[^\S\n]*;[^\S\n]*terrain[^\S\n]+(\S[^\S\n]+\S+)[^\S\n]*$", re.MULTILINE)

#: The text format's own characters and what they mean (None: blocked), which no table
#: redefines: the digits cost themselves.
TEXT_OWN: dict[str, float | None] = {
    ".": 1.0, "S": 1.0, "G": 1.0, "#": None, **{str(d): float(d) for d in range(1, 10)}}


class Terrain(NamedTuple):
    """A table: each character's cost (None: blocked), and where each was defined
    (``path``, line, column), for the errors that name the table's line."""

    costs: dict[str, float | None]
    where: dict[str, tuple[str, int, int]]

    def merged(self, other: "Terrain") -> "Terrain":
        """This table with ``other``'s lines added (``other`` wins where both name a
        character: the command line's ``--terrain`` over a map's own comments)."""
        return Terrain({**self.costs, **other.costs}, {**self.where, **other.where})

    def check_text(self) -> None:
        """Refuse a table that redefines one of the text format's own characters."""
        for char, (path, line, col) in self.where.items():
            if char in TEXT_OWN:
                raise MapError(path, f"a terrain table cannot redefine {char!r} in a text map "
                               "('.', 'S', 'G' cost 1, '#' is blocked, a digit costs itself)",
                               line, col)

    def pairs(self) -> tuple[tuple[str, float | None], ...]:
        return tuple(self.costs.items())


EMPTY = Terrain({}, {})


def parse_terrain(text: str, path: str = "<terrain>") -> Terrain:
    """Parse a terrain file (see the module's docstring)."""
    return _parse_lines(enumerate(each_line(text), start=1), path)


def load_terrain(path: str) -> Terrain:
    """Read and parse the terrain file at ``path`` (a MapError says why not)."""
    return parse_terrain(read_text(path, "a terrain table", MAX_TERRAIN_BYTES), path)


def comment_table(lines: Iterable[str], path: str) -> Terrain:
    """The table a text map carries in its comments: its ``; terrain CHAR COST`` lines."""
    found: list[tuple[int, str]] = []
    offsets: dict[int, int] = {}
    if isinstance(lines, Lines):  # a file's: searched whole, not a line at a time
        number, at = 1, 0
        for found_line in _COMMENT_TABLES.finditer(lines.text):
            number += lines.text.count("\n", at, found_line.start())
            at = found_line.start()
            found.append((number, found_line.group(1)))
            offsets[number] = found_line.start(1) - found_line.start()
            if len(found) > MAX_TERRAINS:
                break  # (_parse_lines names the line too many)
        lines = ()
    for number, line in enumerate(lines, start=1):
        match = _COMMENT_TABLE.match(line)
        if match is not None:
            found.append((number, match.group(1)))
            offsets[number] = match.start(1)
            if len(found) > MAX_TERRAINS:
                break
    if not found:
        return EMPTY
    return _parse_lines(found, path, offsets)


def _parse_lines(lines: Iterable[tuple[int, str]], path: str,
                 offsets: Mapping[int, int] | None = None) -> Terrain:
    """The table of these ``(number, line)`` pairs; ``offsets``: where a line's text starts
    in the file's line (a comment table's), for the columns."""
    costs: dict[str, float | None] = {}
    where: dict[str, tuple[str, int, int]] = {}
    for number, raw in lines:
        line = raw.rstrip()
        shift = (offsets or {}).get(number, 0)
        if not line.strip() or line.lstrip().startswith(";"):
            continue
        words = line.split()
        col = shift + line.index(words[0]) + 1
        if len(words) != 2:
            raise MapError(path, f"expected 'CHAR COST' or 'CHAR blocked', found {quoted(line)}",
                           number, col)
        char, value = words
        if len(char) != 1 or not char.isprintable():
            raise MapError(path, f"a terrain names one character, not {quoted(char)}", number,
                           col)
        if char in costs:
            first = where[char][1]
            raise MapError(path, f"{char!r} is given twice (first at line {first})", number, col)
        if len(costs) == MAX_TERRAINS:
            raise MapError(path, f"more than {MAX_TERRAINS} terrains in one table", number, col)
        value_col = shift + line.index(value, line.index(char) + 1) + 1
        costs[char] = _cost(value, path, number, value_col)
        where[char] = (path, number, col)
    return Terrain(costs, where)


def _cost(value: str, path: str, line: int, col: int) -> float | None:
    if value.lower() == "blocked":
        return None
    if not _COST.fullmatch(value):
        raise MapError(path, f"bad cost {quoted(value, 12)}: a positive number (0.5, 19) or "
                       "'blocked'", line, col)
    cost = float(value)
    if not 0 < cost <= MAX_COST or not math.isfinite(cost):
        raise MapError(path, f"bad cost {quoted(value, 12)}: it must be above 0 and at most "
                       f"{MAX_COST:.0e}", line, col)
    if cost < MIN_COST:
        raise MapError(path, f"bad cost {quoted(value, 12)}: at least {MIN_COST} (costs show "
                       "to 2 decimals: it would show as 0.00)", line, col)
    return cost


class Alphabet:
    """A format's characters with a table: which are cells at all, which are blocked, and
    each row's costs -- what the parsers read rows with."""

    def __init__(self, chars: dict[str, float | None]) -> None:
        self.chars = chars
        self.bad = re.compile("[^" + re.escape("".join(chars)) + "]")
        self.block = block_table("".join(c for c, v in chars.items() if v is None and c.isascii()))
        dear = "".join(c for c, v in chars.items() if v is not None and v != 1.0)
        self.costed = re.compile("[" + re.escape(dear) + "]") if dear else None

    def add_row(self, line: str, blocked: bytearray, costs: "array[float] | None"
                ) -> "array[float] | None":
        """Append row ``line`` (valid: no character :attr:`bad` finds) to ``blocked`` and its
        costs to ``costs``, which is None until a row has a cell costing other than 1 (then
        made, with 1 for the rows before): a map of plain rows keeps no costs."""
        before = len(blocked)
        if line.isascii():
            blocked += line.encode("ascii").translate(self.block)
        else:  # a table's non-ASCII letter
            blocked += bytes(1 if self.chars[c] is None else 0 for c in line)
        if costs is None and (self.costed is None or not self.costed.search(line)):
            return None
        if costs is None:
            costs = array("d", [1.0]) * before
        chars = self.chars
        costs.extend(1.0 if chars[c] is None else chars[c] for c in line)  # type: ignore[misc]
        return costs


    def whole(self, flat: str) -> "tuple[bytearray, array[float] | None]":
        """The cells of ``flat``, every row of a map one after the other (ASCII, and no
        character :attr:`bad` finds): which are blocked, and their costs (None: all 1)."""
        blocked = bytearray(flat.encode("ascii").translate(self.block))
        if self.costed is None or not self.costed.search(flat):
            return blocked, None
        cost_of = {c: 1.0 if v is None else v for c, v in self.chars.items()}
        return blocked, array("d", map(cost_of.__getitem__, flat))


def text_costs(table: Terrain) -> dict[str, float | None]:
    """Every character of a text map with this table: its own and the table's."""
    return {**TEXT_OWN, **table.costs}


def char_for(cost: float, chars: Mapping[str, float | None], endpoints: str = "SG"
             ) -> str | None:
    """A character of ``chars`` (a format's, with its table) for a free cell of ``cost``:
    ``.`` for 1, a digit for a whole cost of 2 to 9 (text maps), else a letter of that cost
    other than ``endpoints`` (the text format's ``S`` and ``G``); None when there is none."""
    if cost == 1.0:
        return "."
    if cost.is_integer() and chars.get(str(int(cost))) == cost:
        return str(int(cost))
    for char, value in chars.items():
        if value == cost and char not in endpoints:
            return char
    return None


def write_row(blocked: bytes, costs: Iterable[float], old: str | None,
              chars: Mapping[str, float | None], wall: str, endpoints: str = "SG") -> str:
    """A row's characters: each of ``old``'s kept where it still means the cell (blocked,
    or free at the same cost; never one of ``endpoints``, written apart), else ``wall`` for an
    obstacle and :func:`char_for` its cost for a free cell (``.`` when no character has that
    cost: :func:`lost_costs` says so)."""
    out = []
    for x, (wall_here, cost) in enumerate(zip(blocked, costs, strict=True)):
        meaning = None if wall_here else cost
        was = old[x] if old is not None else None
        if was is not None and was not in endpoints and was in chars and chars[was] == meaning:
            out.append(was)
        else:
            out.append(wall if wall_here else char_for(cost, chars, endpoints) or ".")
    return "".join(out)


def lost_costs(costs: Iterable[float], chars: Mapping[str, float | None], endpoints: str = "SG"
               ) -> list[float]:
    """The costs, among ``costs``, that no character of ``chars`` writes (a save writes them
    as 1), lowest first."""
    return sorted({c for c in set(costs) if char_for(c, chars, endpoints) is None})

"""MovingAI ``.map`` files (https://movingai.com/benchmarks/formats.html): reading one into
a grid, and the grid's rows written as MovingAI cells.

A MovingAI map has a header (``type octile``, ``height``, ``width``, ``map``) and rows of
``.``, ``G``, ``S`` (passable) and ``@``, ``O``, ``T``, ``W`` (blocked); it has no start or
goal.
"""

from __future__ import annotations

import re

from tui_search.engine.grid import Grid
from tui_search.engine.mapread import (
    MAX_DIGITS,
    NUMBER,
    MapError,
    block_table,
    first_bad,
    quoted,
    split_lines,
)
from tui_search.engine.mapsource import MOVINGAI, MapSource

__all__ = ["movingai_rows", "parse_movingai_map"]

_MAI_BAD = re.compile(r"[^.GS@OTW]")
_MAI_BLOCK = block_table("@OTW")


def parse_movingai_map(text: str, path: str = "<map>") -> Grid:
    """Parse a MovingAI map: ``.``, ``G``, ``S`` passable; ``@``, ``O``, ``T``, ``W`` blocked.

    MovingAI maps carry no start or goal, so both are None.
    """
    bom, split = split_lines(text)
    raw = tuple(split)  # kept in the grid's source: one copy of the lines, not two
    del split
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
            if len(words) != 2 or not NUMBER.fullmatch(words[1]):
                raise MapError(path, f"expected '{key} N', found {quoted(line)}", number)
            if len(words[1].lstrip("0")) > MAX_DIGITS:
                raise MapError(path, f"{key} is too large: {quoted(words[1], 12)}", number)
            value = int(words[1])
            if value < 1:
                raise MapError(path, f"{key} must be at least 1", number)
            header[key] = (value, number)
            continue
        raise MapError(path, f"expected 'height', 'width' or 'map', found {quoted(line)}", number)
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
    blocked = bytearray()  # compact, as a big map has millions of rows
    for k in range(i, last):
        number, line = k + 1, lines[k]
        if k - i == height:
            raise MapError(path, f"more rows than the height ({height}) in the header", number)
        if not line:
            raise MapError(path, "blank line inside the map", number)
        bad = first_bad(line, _MAI_BAD)
        if bad >= 0:
            raise MapError(path, f"unknown cell character {line[bad]!r}", number, bad + 1)
        if len(line) != width:
            raise MapError(path, f"row has {len(line)} cells, expected {width}", number)
        blocked += line.encode("ascii").translate(_MAI_BLOCK)
    if last - i < height:
        found = f"{last - i} row" + ("" if last - i == 1 else "s")
        raise MapError(
            path, f"the header says height {height} but the map has {found}", height_line
        )
    source = MapSource(MOVINGAI, raw, range(i, last), width, bom)
    return Grid(width, height, blocked, source=source)


def movingai_rows(grid: Grid, old_rows: list[str] | None = None) -> list[str]:
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

"""Where each map cell is on screen: the one geometry the map's drawing, its mouse hit-testing,
its scrolling and its overview share (no Textual here, so it is tested on its own).

A layout is data, not a mode: a cell covers ``cell_width`` x ``cell_height`` characters, and a
character covers ``across`` x ``down`` cells, drawn in ``halves`` stacked parts.  Every method
below is one formula over those five numbers; which numbers is decided once, when the geometry
is made from a cell size (``level``) or an overview ``block``:

* **cells** -- a cell is ``2 * level`` x ``level`` characters, kept roughly square on screen
  (a character is about twice as tall as wide): 2x1, 4x2, 6x3 ... (:data:`MAX_LEVEL` levels);
  a character covers one cell;
* **overview** -- ``block`` > 0: a cell is one character, and a character covers ``block`` map
  columns and ``2 * block`` map rows, drawn as two half blocks (``▀``) of ``block`` x
  ``block`` cells each, so a 512x512 map fits a 140x45 terminal.

All positions are *virtual*: in the map's whole drawing, before scrolling.
"""

from __future__ import annotations

from math import ceil, floor

from tui_search.engine.maps.grid import Cell
from tui_search.engine.util.frozen import Frozen

#: The largest cell: 2 * MAX_LEVEL characters wide, MAX_LEVEL lines tall.
MAX_LEVEL = 12


def _ceil_div(a: int, b: int) -> int:
    return -(-a // b)


class Geometry(Frozen):
    """A ``columns`` x ``rows`` map laid out at cell size ``level`` (``2 * level`` x ``level``
    characters), or, with ``block`` > 0, as an overview of blocks of cells.  A
    :class:`~tui_search.engine.util.frozen.Frozen` value (not a frozen dataclass, which every
    start would pay for: benchmarks/README.md, "startup"), compared, hashed and shown by those
    four numbers."""

    __slots__ = ("across", "block", "cell_height", "cell_width", "columns", "down", "halves",
                 "level", "rows")
    _FIELDS = ("columns", "rows", "level", "block")

    columns: int
    rows: int
    level: int
    block: int
    #: Characters a cell spans across (1 in the overview: a character per block).
    cell_width: int
    #: Lines a cell spans (1 in the overview: a line per two blocks).
    cell_height: int
    #: Map columns a character covers (1, or the overview's block).
    across: int
    #: Map rows a line covers (1, or the overview's two blocks).
    down: int
    #: Stacked parts a character draws its ``down`` rows in (1, or 2: the half blocks ``▀``).
    halves: int

    def __init__(self, columns: int, rows: int, level: int = 1, block: int = 0) -> None:
        # The one place the kind of layout is chosen: from here on, only its numbers.
        if block > 0:
            cell_width, cell_height, across, down, halves = 1, 1, block, 2 * block, 2
        else:
            cell_width, cell_height, across, down, halves = 2 * level, level, 1, 1, 1
        self._assign(columns=columns, rows=rows, level=level, block=block, cell_width=cell_width,
                  cell_height=cell_height, across=across, down=down, halves=halves)

    # -- construction --------------------------------------------------------------------
    @classmethod
    def fit(cls, columns: int, rows: int, width: int, height: int) -> Geometry:
        """The largest cell size at which the whole map fits ``width`` x ``height``
        characters (2x1 when even that does not fit: the map scrolls)."""
        level = min(width // (2 * max(1, columns)), height // max(1, rows), MAX_LEVEL)
        return cls(columns, rows, max(1, level))

    @classmethod
    def overview_fit(cls, columns: int, rows: int, width: int, height: int) -> Geometry:
        """The smallest block at which every column and row of the map shows in ``width`` x
        ``height`` characters (a block of 1: a character per column, two rows per line)."""
        width, height = max(1, width), max(1, height)
        block = max(1, _ceil_div(columns, width), _ceil_div(rows, 2 * height))
        return cls(columns, rows, 1, block)

    def zoomed(self, steps: int) -> Geometry:
        """The cell size ``steps`` levels bigger (smaller when negative), within 1..MAX_LEVEL.
        Sizes go by cell width, 2 characters a level, so the overview's cells (a character,
        less than the smallest's two) are below level 1: any step from it gives level 1."""
        level = max(1, min(MAX_LEVEL, self.cell_width // 2 + steps))
        return Geometry(self.columns, self.rows, level)

    # -- sizes ---------------------------------------------------------------------------
    @property
    def overview(self) -> bool:
        return self.block > 0

    @property
    def size(self) -> tuple[int, int]:
        """The whole map's drawing, in characters and lines."""
        return (_ceil_div(self.columns, self.across) * self.cell_width,
                _ceil_div(self.rows, self.down) * self.cell_height)

    def rows_in(self, lines: int) -> int:
        """How many map rows ``lines`` lines show (whole cells only)."""
        return lines // self.cell_height * self.down

    # -- cell <-> screen -----------------------------------------------------------------
    def cell_region(self, cell: Cell) -> tuple[int, int, int, int]:
        """``(x, y, width, height)`` of the characters that draw ``cell``."""
        x, y = cell
        w, h = self.cell_width, self.cell_height
        return x // self.across * w, y // self.down * h, w, h

    def lines_of(self, cell: Cell) -> range:
        """The lines that draw ``cell`` (what a change of the cell repaints)."""
        _, y, _, h = self.cell_region(cell)
        return range(y, y + h)

    def cell_at(self, x: int, y: int) -> Cell | None:
        """The cell drawn at character ``x`` of line ``y`` (in the overview, the top-left cell
        of the block there); None off the map."""
        if x < 0 or y < 0:
            return None
        cell = (x // self.cell_width * self.across, y // self.cell_height * self.down)
        return cell if cell[0] < self.columns and cell[1] < self.rows else None

    def line_rows(self, line: int) -> tuple[range, range]:
        """The map rows line ``line`` draws, as the rows of its upper and of its lower half:
        cells, one row (and an empty lower half); the overview, a block's rows each."""
        top = line // self.cell_height * self.down
        middle = top + self.down // self.halves
        end = self.rows
        return (range(min(top, end), min(middle, end)),
                range(min(middle, end), min(top + self.down, end)))

    def visible_columns(self, scroll_x: int, width: int) -> range:
        """The map columns with at least one character in ``width`` characters from
        ``scroll_x`` (in the overview, every column of the blocks shown)."""
        w, n = self.cell_width, self.columns
        return range(min(scroll_x // w * self.across, n),
                     min(n, _ceil_div(scroll_x + width, w) * self.across))

    # -- scrolling -----------------------------------------------------------------------
    def snap(self, x: int, y: int) -> tuple[int, int]:
        """The scroll offset at or before ``(x, y)`` that starts at a whole cell."""
        w, h = self.cell_width, self.cell_height
        return max(0, x) // w * w, max(0, y) // h * h

    def scroll_room(self, view_width: int, view_height: int) -> tuple[int, int]:
        """How far the drawing must reach so that the last scroll offset also starts at a
        whole cell: the map's size, grown by the part of a cell the view leaves over."""
        width, height = self.size
        w, h = self.cell_width, self.cell_height
        if width > view_width:
            width += (-(width - view_width)) % w
        if height > view_height:
            height += (-(height - view_height)) % h
        return width, height

    def follow(self, cell: Cell, scroll: tuple[int, int], view: tuple[int, int],
               margin: tuple[int, int] = (2, 1)) -> tuple[int, int]:
        """The scroll offset that shows ``cell`` in a ``view``-sized window: ``scroll`` when it
        is already in view with ``margin`` cells around it, else one that centres it (whole
        cells either way)."""
        x0, y0, w, h = self.cell_region(cell)
        sx, sy = scroll
        width, height = view
        mx = min(margin[0] * w, max(0, (width - w) // 2))
        my = min(margin[1] * h, max(0, (height - h) // 2))
        if x0 - mx < sx or x0 + w + mx > sx + width:
            sx = x0 - (width - w) // 2
        if y0 - my < sy or y0 + h + my > sy + height:
            sy = y0 - (height - h) // 2
        sx, sy = self.snap(sx, sy)
        # rounded down to a whole cell, the cell may end past the view: a cell further on
        if x0 + w > sx + width:
            sx += self.cell_width
        if y0 + h > sy + height:
            sy += self.cell_height
        return sx, sy


__all__ = ["MAX_LEVEL", "Geometry"]


def snapped(value: float, old: float, step: int, maximum: float) -> float:
    """``value`` moved to a whole ``step`` in the direction it moves from ``old`` (so a wheel
    turn of one line still moves a tall cell), within ``maximum``."""
    if step == 1 or value == old:
        return value
    whole = ceil(value / step) if value > old else floor(value / step)
    return min(float(whole * step), maximum)

"""How each map cell looks: its drawing code (a search state, or what the grid says), its glyph
and style, and its terrain -- a cell that costs more than 1 is shaded by a ramp of
:data:`RAMP_LEVELS` steps (the themes' ``$map-cost-1`` ... variables: light to dark, so the
ramp reads in every theme and in monochrome) and carries its cost's digit beside its glyph.

The grid view draws with these; the legend shows the same looks.  No widget here: the styles
come from the view's component classes through ``style_of``, so a theme change restyles both.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from rich.segment import Segment
from rich.style import Style

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run
from tui_search.tui.view.cell_codes import (
    BY_RANK,
    COMPONENTS,
    CURSOR_MARK,
    FREE,
    GLYPHS,
    GOAL,
    RANK,
    START,
    WALL,
)
from tui_search.tui.view.cell_labels import cell_line, number_text
from tui_search.tui.view.two_way.cells import two_way_codes

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun

#: The ramp's steps: costs up to 3, 5, 7, and above (a cost of 1 or less is not shaded).
RAMP_LEVELS = 4
#: What each step of the ramp stands for, as the legend says it.
RAMP_NAMES = ("2-3", "4-5", "6-7", "8+")
#: The component classes of the ramp's steps (``grid-view--cost-1`` ...).
RAMP_COMPONENTS = tuple(f"cost-{n}" for n in range(1, RAMP_LEVELS + 1))


def cost_level(cost: float) -> int:
    """The ramp's step for ``cost`` (0: not shaded, a cost of 1 or less)."""
    if cost <= 1.0:
        return 0
    return min(RAMP_LEVELS, math.ceil((cost - 1.0) / 2))


def cost_mark(cost: float) -> str:
    """The character beside a 2-wide cell's glyph: the cost's digit for 2 to 9, else blank
    (1, a fraction, or more than one digit: bigger cells write those)."""
    if cost != 1.0 and cost.is_integer() and 0 < cost < 10:
        return str(int(cost))
    return " "


def cost_text(cost: float, width: int) -> str | None:
    """A big cell's cost, written at its bottom left (None: a cost of 1, or no room)."""
    if cost == 1.0:
        return None
    return number_text(cost, 1 if width < 6 else width // 3)


def row_codes(grid: Grid, run: Run | BiRun | None, y: int, x0: int, x1: int) -> list[int]:
    """Drawing codes of cells ``x0 .. x1-1`` of map row ``y``."""
    if run is None:
        codes = [FREE] * (x1 - x0)
    elif isinstance(run, Run):
        codes = run.now.row_states(y, x0, x1)
    else:
        codes = two_way_codes(run, y, x0, x1)
    blocked = grid.blocked
    base = y * grid.width
    if blocked.find(1, base + x0, base + x1) >= 0:
        for i in range(x1 - x0):
            if blocked[base + x0 + i]:
                codes[i] = WALL
    for cell, code in ((grid.start, START), (grid.goal, GOAL)):
        if cell is not None and cell[1] == y and x0 <= cell[0] < x1:
            codes[cell[0] - x0] = code
    return codes


def row_costs(grid: Grid, y: int, x0: int, x1: int) -> Sequence[float] | None:
    """The costs of cells ``x0 .. x1-1`` of row ``y`` (None: the map has no terrain)."""
    costs = grid.costs
    if costs is None:
        return None
    base = y * grid.width
    return costs[base + x0: base + x1]


#: What a drawing code adds to say the cell is under the cursor, or marked (a replay's first
#: difference: ``grid-view--marked``), or both.
CURSOR, MARKED = len(COMPONENTS), 2 * len(COMPONENTS)


def under_cursor(code: int) -> bool:
    """Is a drawing code (cursor and mark added) one of a cell under the cursor?"""
    return code // CURSOR in (1, 3)


class CellLooks:
    """The glyph and style of each drawing code, and each step of the ramp: plain, under
    the cursor (``code + CURSOR``), marked (``code + MARKED``) and both.

    Under the cursor a cell keeps its colours: its glyph gets the cursor's mark beside it
    (:data:`~tui_search.tui.view.cell_codes.CURSOR_MARK`), bold in the cell's own text colour
    (made to read on its fill in every theme); a free cell's, which is dim, in
    ``grid-view--cursor``'s; a big cell has a bar along its last line too."""

    def __init__(self, style_of: Callable[[str], Style]) -> None:
        cursor, marked = style_of("grid-view--cursor"), style_of("grid-view--marked")
        # the mark's own fill and colour over the cell's (its glyph says its state)
        marked = Style(color=marked.color, bgcolor=marked.bgcolor, bold=marked.bold,
                       underline=marked.underline)
        bold = Style(bold=True)
        n = len(COMPONENTS)
        styles = [style_of(f"grid-view--{name}") for name in COMPONENTS]

        def look(style: Style, k: int, free: bool) -> Style:
            """``style`` as drawing codes of the ``k``-th kind (plain, cursor, marked, both)."""
            if k >= 2:
                style += marked
            return style + (cursor if free and k == 1 else bold) if k % 2 else style

        self.codes: list[tuple[str, Style]] = [
            (GLYPHS[i][0] + CURSOR_MARK if k % 2 else GLYPHS[i], look(styles[i], k, i == FREE))
            for k in range(4) for i in range(n)]
        ramp = [styles[FREE]] + [style_of(f"grid-view--{name}") for name in RAMP_COMPONENTS]
        self.ramp: list[Style] = [look(style, k, level == 0) for k in range(4)
                                  for level, style in enumerate(ramp)]

    def terrain(self, code: int, cost: float) -> tuple[str, Style]:
        """A cell of ``code`` (cursor included) that costs ``cost``: a free cell shaded by
        the ramp, any cell but an obstacle with its cost's digit beside its glyph (under the
        cursor, the cursor's mark: the readout says the cost)."""
        glyph, style = self.codes[code]
        base = code % len(COMPONENTS)
        if base == FREE:
            style = self.ramp[cost_level(cost) + (RAMP_LEVELS + 1) * (code // CURSOR)]
        if base == WALL or under_cursor(code):
            return glyph, style
        return glyph[0] + cost_mark(cost), style

    def big_cells(self, run: Run | BiRun | None, row: int, columns: range, codes: list[int],
                  costs: Sequence[float] | None, width: int, height: int, sub: int,
                  labels: str) -> list[Segment]:
        """Line ``sub`` of the cells ``columns`` of map row ``row``, each ``width`` x
        ``height`` characters: glyph, label (:func:`cell_line`) and terrain cost; under the
        cursor, its mark beside the glyph and a bar along the last line."""
        out = []
        for i, (x, code) in enumerate(zip(columns, codes, strict=True)):
            base = code % len(COMPONENTS)
            style = self.codes[code][1]
            cost = None
            if costs is not None:
                style = self.terrain(code, costs[i])[1]
                cost = cost_text(costs[i], width)
            text = cell_line(run, (x, row), width, height, sub, labels, GLYPHS[base][0],
                             base == WALL, cost, under_cursor(code))
            out.append(Segment(text, style))
        return out


def swatches(style_of: Callable[[str], Style], base: Style) -> list[Style]:
    """The one colour each kind of cell has in the overview (and in the legend): its fill,
    an obstacle's glyph colour, a free cell the background; then the ramp's steps, their
    fill (a free block with terrain: :func:`shaded`)."""
    out = []
    for i, name in enumerate(COMPONENTS):
        style = style_of(f"grid-view--{name}")
        colour = style.bgcolor
        if i in (FREE, WALL) or colour is None or colour == base.bgcolor:
            colour = style.color if i == WALL else (colour or base.bgcolor)
        out.append(Style(color=colour))
    return out + [Style(color=style_of(f"grid-view--{name}").bgcolor)
                  for name in RAMP_COMPONENTS]


def block_codes(grid: Grid, run: Run | BiRun | None, rows: range, x0: int, x1: int, across: int
                ) -> list[int] | None:
    """For each block of ``across`` of the overview's columns ``x0 .. x1-1`` over map rows
    ``rows``: the code of highest rank in it (None for no rows: a half below the map)."""
    if not rows:
        return None
    best: list[int] | None = None
    for y in rows:
        ranks = [RANK[code] for code in row_codes(grid, run, y, x0, x1)]
        if across > 1:
            ranks = [max(ranks[i : i + across]) for i in range(0, len(ranks), across)]
        best = ranks if best is None else list(map(max, best, ranks))
    assert best is not None
    return [BY_RANK[rank] for rank in best]


def block_costs(grid: Grid, rows: range, x0: int, x1: int, across: int) -> list[float] | None:
    """For each block of ``across`` of the overview's columns ``x0 .. x1-1`` over map rows
    ``rows``: the highest cost of a free cell in it (None: no terrain, or no rows).

    The highest, not the mean: as a block shows its most important state (:data:`RANK`), it
    shows its dearest cell, so a band of mud one cell wide across a 512x512 map stays seen
    (a mean would wash it out among the cheap cells of its blocks)."""
    costs = grid.costs
    if costs is None or not rows:
        return None
    blocked, width = grid.blocked, grid.width
    best: list[float] | None = None
    for y in rows:
        a, b = y * width + x0, y * width + x1
        row: Sequence[float] = costs[a:b]
        if blocked.find(1, a, b) >= 0:  # an obstacle's cost is never paid: not shown
            row = [0.0 if wall else cost for cost, wall in zip(row, blocked[a:b], strict=True)]
        if across > 1:
            row = [max(row[i : i + across]) for i in range(0, len(row), across)]
        best = list(row) if best is None else list(map(max, best, row))
    return best


def shaded(codes: list[int], costs: list[float] | None) -> list[int]:
    """The overview's swatch (:func:`swatches`) of each block of ``codes``: its code, or, for
    a free block with terrain, the ramp's step of its dearest cell (``costs``:
    :func:`block_costs`)."""
    if costs is None:
        return codes
    ramp = len(COMPONENTS) - 1
    return [ramp + level if code == FREE and (level := cost_level(cost)) else code
            for code, cost in zip(codes, costs, strict=True)]


__all__ = [
    "CURSOR",
    "MARKED",
    "RAMP_COMPONENTS",
    "RAMP_LEVELS",
    "RAMP_NAMES",
    "CellLooks",
    "block_codes",
    "block_costs",
    "cost_level",
    "cost_mark",
    "cost_text",
    "row_codes",
    "row_costs",
    "shaded",
    "swatches",
    "under_cursor",
]

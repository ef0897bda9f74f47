"""The map's lines: what :meth:`GridView.render_line <tui_search.tui.widgets.grid_view.GridView.
render_line>` draws on each terminal row, from the view's grid, run, cursor and
:class:`~tui_search.tui.view.geometry.Geometry` -- never a widget per cell, so a 512x512 map costs
what the visible part costs.

* **cells** -- each map cell is 2x1, 4x2, 6x3 ... characters and carries a glyph as well as a
  colour, so the picture reads without colour too (see
  :data:`~tui_search.tui.view.cell_codes.GLYPHS`, which the legend shows).  Cells at least 4 wide
  also carry a label (:mod:`~tui_search.tui.view.cell_labels`): the arrow of the move that reached
  the cell and, where there is room, its depth or its costs;
* **overview** -- half blocks (``▀`` with a foreground and a background colour), each half
  standing for a block of cells drawn by the state that matters most in it (see
  :data:`~tui_search.tui.view.cell_codes.RANK`), so every row and column of a 512x512 map shows in a
  140x45 terminal; a free block on a map with terrain takes the ramp's colour of its dearest
  cell (:func:`~tui_search.tui.widgets.cell_style.block_costs`).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from itertools import groupby
from typing import TYPE_CHECKING

from rich.color import Color
from rich.segment import Segment
from rich.style import Style
from textual.strip import Strip

from tui_search.tui.view.cell_codes import UPPER_HALF
from tui_search.tui.widgets.cell_style import (
    CURSOR,
    MARKED,
    block_codes,
    block_costs,
    row_codes,
    row_costs,
    shaded,
)
from tui_search.tui.widgets.line_panel import window_strip

if TYPE_CHECKING:
    from typing import Protocol

    from textual.geometry import Offset, Region

    from tui_search.engine.maps.grid import Cell, Grid
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.run.recorded import Run
    from tui_search.tui.view.geometry import Geometry
    from tui_search.tui.widgets.cell_style import CellLooks

    class MapView(Protocol):
        """What the lines are drawn from: a :class:`~tui_search.tui.widgets.grid_view.GridView`
        (named so for the type checker only: the view imports this module)."""

        @property
        def grid(self) -> Grid: ...
        @property
        def run(self) -> Run | BiRun | None: ...
        @property
        def cursor(self) -> Cell: ...
        @property
        def marks(self) -> frozenset[Cell]: ...
        @property
        def geometry(self) -> Geometry: ...
        @property
        def labels(self) -> str: ...
        @property
        def pad_x(self) -> int: ...
        @property
        def scroll_offset(self) -> Offset: ...
        @property
        def scrollable_content_region(self) -> Region: ...
        def cached_style(self, component: str | None = None) -> Style: ...
        def cell_looks(self) -> CellLooks: ...
        def swatch(self, code: int) -> Style: ...
        def get_component_rich_style(self, *names: str, partial: bool = False,
                                     default: Style | None = None) -> Style: ...


def map_line(view: MapView, y: int) -> Strip:
    """Row ``y`` of ``view`` at its scroll offset: cells, or the overview's half blocks."""
    sx, sy = view.scroll_offset
    width = view.scrollable_content_region.width
    line = sy + y
    geo = view.geometry
    if geo.overview:
        return overview_line(view, line, sx, width)
    background = view.cached_style()
    rows, _ = geo.line_rows(line)
    if not rows:
        return Strip.blank(width, background)
    row = rows[0]
    columns = geo.visible_columns(sx, width)
    x0, x1 = columns.start, columns.stop
    grid, run = view.grid, view.run
    codes = row_codes(grid, run, row, x0, x1)
    cx, cy = view.cursor
    if cy == row and x0 <= cx < x1:
        codes[cx - x0] += CURSOR
    for mx, my in view.marks:
        if my == row and x0 <= mx < x1:
            codes[mx - x0] += MARKED
    looks = view.cell_looks()
    costs = row_costs(grid, row, x0, x1)
    segments = [Segment(" " * view.pad_x, background)]  # the padding that centres the map
    if geo.cell_width == 2 and costs is None:  # one segment per run of like cells
        for code, like in groupby(codes):
            glyph, style = looks.codes[code]
            segments.append(Segment(glyph * len(list(like)), style))
    elif geo.cell_width == 2:
        for (text, look), alike in groupby(map(looks.terrain, codes, costs or ())):
            segments.append(Segment(text * len(list(alike)), look))
    else:
        segments += looks.big_cells(run, row, columns, codes, costs, geo.cell_width,
                                    geo.cell_height, line - row * geo.cell_height, view.labels)
    return window_strip(segments, sx - x0 * geo.cell_width, width, background)


def block_swatches(grid: Grid, run: Run | BiRun | None, rows: range, x0: int, x1: int,
                   across: int) -> list[int] | None:
    """The swatch of each block of the overview's columns ``x0 .. x1-1`` over map rows
    ``rows``: the code of highest rank in it (:func:`block_codes`), a free block shaded by its
    dearest cell (None for no rows: a half below the map)."""
    codes = block_codes(grid, run, rows, x0, x1, across)
    costs = block_costs(grid, rows, x0, x1, across)
    return None if codes is None else shaded(codes, costs)


def overview_line(view: MapView, line: int, sx: int, width: int) -> Strip:
    """Line ``line`` of the overview, from column ``sx``: two map rows of blocks a row."""
    background = view.cached_style()
    geo = view.geometry
    upper_rows, lower_rows = geo.line_rows(line)
    if not upper_rows:
        return Strip.blank(width, background)
    columns = geo.visible_columns(sx, width)
    grid, run, across = view.grid, view.run, geo.across
    upper = block_swatches(grid, run, upper_rows, columns.start, columns.stop, across)
    assert upper is not None
    lower = block_swatches(grid, run, lower_rows, columns.start, columns.stop, across)
    x, y, _, _ = geo.cell_region(view.cursor)  # the cursor's character
    cursor_x = x - sx if y == line else -1
    cursor_upper = view.cursor[1] in upper_rows
    cursor_colour = view.get_component_rich_style("grid-view--cursor").color or (
        background.color
    )
    swatch = view.swatch
    colours = []
    for i in range(len(upper)):
        a = swatch(upper[i]).color
        b = swatch(lower[i]).color if lower is not None else background.bgcolor
        if i == cursor_x:
            if cursor_upper:
                a = cursor_colour
            else:
                b = cursor_colour
        colours.append((a, b))
    return window_strip([Segment(" " * view.pad_x, background), *half_blocks(colours)], 0,
                        width, background)


def half_blocks(colours: Iterable[tuple[Color | None, Color | None]]) -> Iterator[Segment]:
    """The overview's characters for ``(upper, lower)`` colour pairs: a half block each, one
    segment a run of equal pairs."""
    styles: dict[tuple[Color | None, Color | None], Style] = {}
    for pair, like in groupby(colours):
        style = styles.get(pair)
        if style is None:
            style = styles[pair] = Style(color=pair[0], bgcolor=pair[1])
        yield Segment(UPPER_HALF * len(list(like)), style)

"""The graph's lines: what :meth:`GraphView.render_line <tui_search.tui.widgets.graph_view.
GraphView.render_line>` draws on each terminal row, from the tiles of
:mod:`~tui_search.tui.view.graph_layout.raster` (what is where, worked out once a zoom) and the
search's state, asked of each node shown as the row is drawn (so a step redraws, and works
out, nothing else).

A node is a chip: its mark (:data:`MARKS`: ``•`` unseen, ``○`` frontier, ``●`` expanded,
``◉`` being expanded, ``◆`` on the path, ``▶`` start, ``★`` goal, ``█`` closed; a
bidirectional search's backward half ``□ ■ ▣``, a node both reached ``◐``, the best meeting
``✦``) and its name,
in its state's colours, as the grid fills a cell.  Under the cursor the chip keeps its
colours, turns bold and has the cursor's mark (``◀``) after it.  A road is drawn in the
path's colour when both its ends are on the path.  In the overview each cell of dots takes
the colour of its most telling node (:data:`~tui_search.tui.view.cell_codes.RANK`).
"""

from __future__ import annotations

from collections.abc import Callable

from rich.segment import Segment
from rich.style import Style
from textual.strip import Strip

from tui_search.engine.run.position import CellState
from tui_search.tui.view.cell_codes import (
    BY_RANK,
    COMPONENTS,
    CURSOR_MARK,
    FREE,
    RANK,
    WALL,
)
from tui_search.tui.view.graph_layout.raster import ARROW, COST, DOTS, MARK, NAME, ROAD, Tiles
from tui_search.tui.widgets.line_panel import window_strip

PATH = int(CellState.PATH)
#: A node's mark by its drawing code: the grid's glyphs for the search's states (a bullet for
#: an unseen node, which the grid's dot would hide), an obstacle's block for a closed node, and
#: for the start and the goal marks that are no letters (teaching graphs name nodes S and G).
MARKS = "•○●◉◆█▶★□■▣◐✦"
#: The component classes of the drawing beside the states' (``graph-view--free`` ...).
PARTS = ("road", "road-path", "cost", "arrow", "cursor")


class GraphLooks:
    """The styles the graph is drawn in, read once a restyle from the view's component
    classes through ``style_of`` (so a theme is a CSS change)."""

    def __init__(self, style_of: Callable[[str], Style], background: Style) -> None:
        states = [style_of(f"graph-view--{name}") for name in COMPONENTS]
        bold = Style(bold=True)
        self.mark = [(MARKS[code], style) for code, style in enumerate(states)]
        self.chip = states
        self.chip_cursor = [style + bold for style in states]
        self.road, self.road_path, self.cost, self.arrow, self.cursor = (
            style_of(f"graph-view--{name}") for name in PARTS)
        self.background = background
        # the overview's colour of each state: its fill, a free node's or a closed one's text
        self.swatch = []
        for code, style in enumerate(states):
            colour = style.bgcolor
            if code in (FREE, WALL) or colour is None or colour == background.bgcolor:
                colour = style.color
            self.swatch.append(Style(color=colour, bgcolor=background.bgcolor))


class Shown:
    """What a row is drawn from: the tiles, the looks, each node's drawing code, whether a road
    is on the path, and the cursor (its node, its mark's cell, where its ``◀`` goes)."""

    def __init__(self, tiles: Tiles, looks: GraphLooks, code_of: Callable[[int], int],
                 lit: Callable[[int], bool], cursor: int, cursor_at: tuple[int, int]) -> None:
        self.tiles, self.looks, self.code_of, self.lit = tiles, looks, code_of, lit
        self.cursor, self.cursor_at = cursor, cursor_at


def graph_line(shown: Shown, row: int, sx: int, width: int) -> list[tuple[int, str, Style]]:
    """Row ``row`` of the drawing from column ``sx``, ``width`` wide: pieces ``(column, text,
    style)`` by column, blanks left out."""
    looks, code_of, lit = shown.looks, shown.code_of, shown.lit
    cursor = shown.cursor
    pieces: list[tuple[int, str, Style]] = []
    for col, text, kind, what in shown.tiles.row_items(row, sx, sx + width):
        if kind == ROAD:
            assert isinstance(what, tuple)
            if len(what) == 1:  # a run of one road's cells: one colour
                style = looks.road_path if lit(what[0]) else looks.road
                pieces.append((col, text, style))
            else:
                style = looks.road_path if any(map(lit, what)) else looks.road
                pieces.append((col, text, style))
        elif kind == MARK:
            assert isinstance(what, int)
            code = code_of(what)
            glyph, style = looks.mark[code]
            pieces.append((col, glyph, looks.chip_cursor[code] if what == cursor else style))
        elif kind == NAME:
            assert isinstance(what, int)
            code = code_of(what)
            pieces.append((col, text, (looks.chip_cursor if what == cursor else looks.chip)[code]))
        elif kind == COST:
            pieces.append((col, text, looks.cost))
        elif kind == ARROW:
            assert isinstance(what, int)
            pieces.append((col, text, looks.road_path if lit(what) else looks.arrow))
        elif kind == DOTS:
            assert isinstance(what, tuple)
            if cursor in what:
                pieces.append((col, text, looks.cursor))
            else:
                best = max(RANK[code_of(v)] for v in what)
                pieces.append((col, text, looks.swatch[BY_RANK[best]]))
    cx, cy = shown.cursor_at
    if cy == row and sx <= cx < sx + width:
        pieces = overlay(pieces, cx, CURSOR_MARK, looks.cursor)
    return pieces


def overlay(pieces: list[tuple[int, str, Style]], col: int, text: str, style: Style
            ) -> list[tuple[int, str, Style]]:
    """``pieces`` with one cell, ``col``, drawn as ``text`` in ``style``."""
    out = []
    for at, piece, look in pieces:
        end = at + len(piece)
        if at <= col < end:
            if at < col:
                out.append((at, piece[: col - at], look))
            if col + 1 < end:
                out.append((col + 1, piece[col - at + 1:], look))
        else:
            out.append((at, piece, look))
    out.append((col, text, style))
    out.sort(key=lambda p: p[0])
    return out


def line_strip(pieces: list[tuple[int, str, Style]], sx: int, width: int,
               background: Style) -> Strip:
    """The pieces as a line from column ``sx``, blanks between them, cut to ``width``."""
    start = min(sx, pieces[0][0]) if pieces else sx
    segments = []
    at = start
    for col, text, style in pieces:
        if col > at:
            segments.append(Segment(" " * (col - at), background))
        segments.append(Segment(text, style))
        at = col + len(text)
    return window_strip(segments, sx - start, width, background)


__all__ = ["MARKS", "PARTS", "GraphLooks", "Shown", "graph_line", "line_strip", "overlay"]

"""A graph fitted into a box of terminal cells, at a zoom: where each node's mark is, how big
the drawing is, and how it is cut into tiles (which
:mod:`~tui_search.tui.view.graph_layout.raster` draws).

A terminal cell is about twice as tall as it is wide, so a graph whose file gives places keeps
its proportions with half as many rows as columns per unit; a graph laid out here
(:mod:`~tui_search.tui.view.graph_layout.places`) has no proportions to keep and is stretched
to the box, up to a readable spacing.  Level 0 is the whole graph in the box (room kept at the
sides for the names); each level up is about half again as big, and the drawing scrolls.

When two nodes fall in one cell the drawing is an overview: every node a braille dot (eight
to a cell), no names, the roads only when there are few.  Otherwise each node is a mark with
its name beside it, each road a braille line, its cost at its middle.

Every position here is in the whole drawing's cells (column, row from the top), before
scrolling.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from tui_search.tui.view.graph_layout.places import Placement

#: The zoom of each level, over the fit of level 0.
ZOOMS = (1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0, 24.0, 32.0, 48.0, 64.0, 96.0, 128.0,
         192.0, 256.0)
#: The longest side of a drawing, in cells (a level that would be bigger is not offered).
MAX_SIDE = 1 << 16
#: A laid-out graph (no places of its own) is never spread wider than this between two nodes
#: of a layer, nor taller between two layers, at level 0.
MAX_GAP_X, MAX_GAP_Y = 20.0, 6.0
#: The spacing (in columns) a big graph's deepest level gives its nodes, on average.
SPACING = 12.0
#: Names are cut to this many characters for the room kept at the sides.
NAME_ROOM = 12
#: Above this many nodes, level 0 keeps no room for names (it is an overview).
NAMED_UP_TO = 5000
#: An overview draws the roads only up to this many (beyond, they would fill it).
OVERVIEW_ROADS = 5000
#: A drawing of at most this many cells is one tile; a bigger one is cut into TILE-sized ones.
ONE_TILE = 120_000
TILE = (160, 80)


class Canvas:
    """``placement``'s graph in ``width`` x ``height`` cells at zoom ``level``: ``cols`` x
    ``rows`` cells in all (at least the box), each node's mark at ``cell(i)``."""

    def __init__(self, placement: Placement, width: int, height: int, level: int = 0,
                 longest_name: int = 0) -> None:
        self.placement = placement
        p = placement
        n = len(p)
        self.box = (max(1, width), max(1, height))
        width, height = self.box
        named = n <= NAMED_UP_TO
        room = min(NAME_ROOM, longest_name) + 1 if named else 0
        # Room at the sides for a name left or right of the outermost marks (half a name:
        # the outermost names can also go above or below), and a row above and below.
        self.margin_x = min((room + 1) // 2, max(0, (width - 4) // 6))
        self.margin_y = 1 if named and height >= 6 else 0
        use_x = max(1, width - 2 * self.margin_x)
        use_y = max(1, height - 2 * self.margin_y)
        w, h = p.x1 - p.x0, p.y1 - p.y0
        kx = (use_x - 1) / w if w > 0 else math.inf
        ky = (use_y - 1) / h if h > 0 else math.inf
        if p.given:  # keep the proportions: a row is two columns tall
            kx = min(kx, 2 * ky)
            ky = kx / 2
        else:
            kx, ky = min(kx, MAX_GAP_X), min(ky, MAX_GAP_Y)
        if math.isinf(kx):
            kx = 1.0
        if math.isinf(ky):
            ky = kx / 2
        self.levels = self._levels(w * kx, h * ky, n)
        self.level = max(0, min(level, self.levels - 1))
        zoom = ZOOMS[self.level]
        self.kx, self.ky = kx * zoom, ky * zoom
        self.cols = max(width, math.ceil(w * self.kx) + 2 * self.margin_x + 1)
        self.rows = max(height, math.ceil(h * self.ky) + 2 * self.margin_y + 1)
        # continuous positions: cell (c, r) spans [c, c + 1) x [r, r + 1)
        self.ox = (self.cols - w * self.kx) / 2
        self.oy = (self.rows - h * self.ky) / 2
        x0, y1, kx, ky, ox, oy = p.x0, p.y1, self.kx, self.ky, self.ox, self.oy
        self.fx = [ox + (x - x0) * kx for x in p.xs]
        self.fy = [oy + (y1 - y) * ky for y in p.ys]
        cols = self.cols
        self.cell_key = [int(fy) * cols + int(fx) for fx, fy in zip(self.fx, self.fy,
                                                                     strict=True)]
        #: An overview: two nodes (or more) share a cell; every node is a dot.
        self.overview = len(set(self.cell_key)) < n
        self.roads_drawn = not self.overview or len(p.graph.data.road_a) <= OVERVIEW_ROADS
        if cols * self.rows <= ONE_TILE:
            self.tile_size = (cols, self.rows)
        else:
            self.tile_size = TILE

    @staticmethod
    def _levels(span_x: float, span_y: float, n: int) -> int:
        """How many levels there are: zooms up to 8, or, for a graph with more nodes, until
        they are about SPACING columns apart on average; never a side over MAX_SIDE."""
        spacing = math.sqrt((span_x + 1) * (span_y + 1) * 2 / max(1, n))  # at level 0
        most = max(8.0, SPACING / spacing)
        count = 1
        while (count < len(ZOOMS) and ZOOMS[count] <= most
               and max(span_x, span_y) * ZOOMS[count] <= MAX_SIDE):
            count += 1
        return count

    def __repr__(self) -> str:
        return (f"Canvas({self.cols}x{self.rows}, level {self.level}/{self.levels - 1}, "
                f"{'overview' if self.overview else 'marks'})")

    # -- nodes ---------------------------------------------------------------------------
    def cell(self, i: int) -> tuple[int, int]:
        """Node ``i``'s mark: (column, row)."""
        return int(self.fx[i]), int(self.fy[i])

    def to_place(self, col: float, row: float) -> tuple[float, float]:
        """The graph's point drawn at a continuous position of the drawing."""
        p = self.placement
        return p.x0 + (col - self.ox) / self.kx, p.y1 - (row - self.oy) / self.ky

    def nodes_in(self, c0: int, r0: int, c1: int, r1: int) -> list[int]:
        """The nodes whose marks are in columns ``c0 .. c1-1`` and rows ``r0 .. r1-1``."""
        if c0 <= 0 and r0 <= 0 and c1 >= self.cols and r1 >= self.rows:
            return list(range(len(self.fx)))
        xa, yb = self.to_place(c0, r0)
        xb, ya = self.to_place(c1, r1)
        pad_x, pad_y = 1 / self.kx, 1 / self.ky  # a cell's worth: rounding at the border
        fx, fy = self.fx, self.fy
        return [i for i in self.placement.nodes_in(xa - pad_x, xb + pad_x, ya - pad_y,
                                                   yb + pad_y)
                if c0 <= fx[i] < c1 and r0 <= fy[i] < r1]

    def roads_in(self, c0: int, r0: int, c1: int, r1: int) -> list[int]:
        """The roads that may cross columns ``c0 .. c1-1``, rows ``r0 .. r1-1`` (a few more)."""
        if c0 <= 0 and r0 <= 0 and c1 >= self.cols and r1 >= self.rows:
            return list(range(len(self.placement.graph.data.road_a)))
        xa, yb = self.to_place(c0, r0)
        xb, ya = self.to_place(c1, r1)
        return self.placement.roads_near(xa, xb, ya, yb)

    # -- tiles ---------------------------------------------------------------------------
    def tiles_across(self, c0: int, c1: int, row: int) -> Iterator[tuple[int, int]]:
        """The tiles (by their place in the tiling) holding row ``row``'s columns
        ``c0 .. c1-1``."""
        tw, th = self.tile_size
        if not 0 <= row < self.rows:
            return
        ty = row // th
        for tx in range(max(0, c0) // tw, (min(c1, self.cols) - 1) // tw + 1):
            yield tx, ty


__all__ = ["MAX_SIDE", "ZOOMS", "Canvas"]

"""A tile of the drawing, worked out once: each row as a few items, ``(column, text, kind,
what)`` -- a node's mark, its name, a run of road cells, a cost, an arrow, or the overview's
dots -- which the view colours by the search's state as it draws (so a step changes no tile).

Roads are braille lines, eight dots to a cell (2 across, 4 down), from mark to mark; a mark, a
name or a cost is drawn over them.  An arc (a one-way road) has an arrow in the first cell of
its line outside the node it enters.  In the overview each node is one dot, and a cell's
colour is its nodes' most telling state.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from collections.abc import Iterator, Sequence

from tui_search.tui.view.graph_layout.canvas import Canvas
from tui_search.tui.view.graph_layout.labels import Board, place_cost, place_names

Cell = tuple[int, int]
#: What an item is.
ROAD, MARK, NAME, COST, ARROW, DOTS = range(6)
#: An item of a row: its first column, its text (a character a cell; a mark's is a blank,
#: its glyph being the node's state's), its kind, and what it stands for -- a node (MARK,
#: NAME), a road (COST, ARROW), the roads of each cell (ROAD: a tuple of road numbers) or the
#: nodes of its cell (DOTS: a tuple of node numbers).
Item = tuple[int, str, int, object]
BRAILLE = 0x2800
#: The bit of the braille dot at (across, down) in its cell.
DOT = ((0x01, 0x08), (0x02, 0x10), (0x04, 0x20), (0x40, 0x80))
#: An arc's arrow by the direction it goes, counter-clockwise from east in eighths.
ARROWS = "→↗↑↖←↙↓↘"


def road_dots(ax: int, ay: int, bx: int, by: int, box: tuple[int, int, int, int]
              ) -> Iterator[tuple[int, int]]:
    """The dots of the line from dot ``(ax, ay)`` to ``(bx, by)`` that are in ``box``
    (``[x0, x1) x [y0, y1)`` in dots), from the first end: a step a dot along the longer axis,
    rounded (Bresenham's line), clipped first (Liang and Barsky) so that a long road costs
    only its part in the box."""
    dx, dy = bx - ax, by - ay
    steps = max(abs(dx), abs(dy))
    if steps == 0:
        if box[0] <= ax < box[2] and box[1] <= ay < box[3]:
            yield ax, ay
        return
    t0, t1 = 0.0, 1.0
    # clipped to the box and a dot around it: a dot rounded into the box may come from a
    # point of the line just outside it
    for p, q in ((-dx, ax - box[0] + 1), (dx, box[2] - ax), (-dy, ay - box[1] + 1),
                 (dy, box[3] - ay)):
        if p == 0:
            if q < 0:
                return
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    if t0 > t1:
        return
    for i in range(max(0, math.floor(t0 * steps)), min(steps, math.ceil(t1 * steps)) + 1):
        x = ax + (2 * dx * i + steps) // (2 * steps)
        y = ay + (2 * dy * i + steps) // (2 * steps)
        if box[0] <= x < box[2] and box[1] <= y < box[3]:
            yield x, y


def arrow(dx: float, dy: float) -> str:
    """The arrow of a direction on screen (``dy`` down, in column widths)."""
    eighth = round(math.atan2(-dy, dx) / (math.pi / 4)) % 8
    return ARROWS[eighth]


def cost_text(cost: float) -> str:
    """A road's cost as its label says it: ``75``, ``2.5``."""
    return str(int(cost)) if float(cost).is_integer() else f"{cost:.4g}"


class Tile:
    """Columns ``x0 .. x0+width-1`` and rows ``y0 .. y0+height-1`` of a drawing: ``rows``
    (each a list of items, by column), ``names`` (node -> column, row, text, of the names
    placed here), ``owner`` (cell -> node, for marks and names) and ``dots`` (cell -> nodes,
    in the overview)."""

    def __init__(self, canvas: Canvas, x0: int, y0: int, width: int, height: int,
                 names: Sequence[str], need: Sequence[int], costs: bool) -> None:
        self.x0, self.y0, self.width, self.height = x0, y0, width, height
        x1, y1 = x0 + width, y0 + height
        self.names: dict[int, tuple[int, int, str]] = {}
        self.owner: dict[Cell, int] = {}
        self.dots: dict[Cell, tuple[int, ...]] = {}
        cells: dict[Cell, tuple[int, object, str]] = {}  # cell -> kind, what, character
        nodes = canvas.nodes_in(x0, y0, x1, y1)
        marks = {canvas.cell(v): v for v in nodes} if not canvas.overview else {}
        d = canvas.placement.graph.data
        bits, roads, along = self._roads(canvas, marks, x0, y0, x1, y1)
        if canvas.overview:
            for v in nodes:
                fx, fy = canvas.fx[v], canvas.fy[v]
                cell = (int(fx), int(fy))
                bits[cell] = bits.get(cell, 0) | DOT[int(4 * fy) & 3][int(2 * fx) & 1]
                self.dots[cell] = (*self.dots.get(cell, ()), v)
            for cell, held in self.dots.items():
                cells[cell] = (DOTS, held, chr(BRAILLE + bits[cell]))
        else:
            board = Board(marks, roads, (x0, y0, x1, y1), (d.road_a, d.road_b))
            placed = place_names(board, nodes, {v: c for c, v in marks.items()}, names, need)
            self.names = placed
            for v, (col, row, text) in placed.items():
                for i, ch in enumerate(text):
                    cells[(col + i, row)] = (NAME, v, ch)
                    self.owner[(col + i, row)] = v
            if costs:
                self._costs(canvas, board, along, cells)
            self._arrows(canvas, board, along, cells)
            for cell, v in marks.items():
                cells[cell] = (MARK, v, " ")
                self.owner[cell] = v
        for cell, mask in bits.items():
            if cell not in cells:
                cells[cell] = (ROAD, tuple(roads[cell]), chr(BRAILLE + mask))
        self.rows = self._rows(cells)

    @staticmethod
    def _roads(canvas: Canvas, marks: dict[Cell, int], x0: int, y0: int, x1: int, y1: int
               ) -> tuple[dict[Cell, int], dict[Cell, list[int]], dict[int, list[Cell]]]:
        """The roads' braille in the tile: each cell's dots, each cell's roads, and each
        road's cells in order from its first end (none where the overview has no roads)."""
        bits: dict[Cell, int] = {}
        roads: dict[Cell, list[int]] = {}
        along: dict[int, list[Cell]] = {}
        if not canvas.roads_drawn:
            return bits, roads, along
        d = canvas.placement.graph.data
        box = (2 * x0, 4 * y0, 2 * x1, 4 * y1)
        for e in canvas.roads_in(x0, y0, x1, y1):
            a, b = d.road_a[e], d.road_b[e]
            if a == b:
                continue
            (ca, ra), (cb, rb) = canvas.cell(a), canvas.cell(b)
            line: list[Cell] = []
            for x, y in road_dots(2 * ca, 4 * ra + 1, 2 * cb, 4 * rb + 1, box):
                cell = (x >> 1, y >> 2)
                if cell in marks:
                    continue
                bits[cell] = bits.get(cell, 0) | DOT[y & 3][x & 1]
                if not line or line[-1] != cell:
                    line.append(cell)
                    on = roads.setdefault(cell, [])
                    if e not in on:
                        on.append(e)
            if line:
                along[e] = line
        return bits, roads, along

    def _costs(self, canvas: Canvas, board: Board, along: dict[int, list[Cell]],
               cells: dict[Cell, tuple[int, object, str]]) -> None:
        """Each road's cost on the road near its middle, when its middle is in this tile."""
        d = canvas.placement.graph.data
        for e, line in along.items():
            (ca, ra), (cb, rb) = canvas.cell(d.road_a[e]), canvas.cell(d.road_b[e])
            mc, mr = (ca + cb) // 2, (ra + rb) // 2
            if not board.inside(mc, mr):
                continue
            text = cost_text(d.road_cost[e])
            near = sorted(line, key=lambda c: abs(c[0] - mc) + 2 * abs(c[1] - mr))
            at = place_cost(board, e, text, near)
            if at is not None:
                for i, ch in enumerate(text):
                    cells[(at[0] + i, at[1])] = (COST, e, ch)

    def _arrows(self, canvas: Canvas, board: Board, along: dict[int, list[Cell]],
                cells: dict[Cell, tuple[int, object, str]]) -> None:
        """Each arc's arrow, in the last free cell of its line before the node it enters."""
        d = canvas.placement.graph.data
        for e, line in along.items():
            if not d.road_directed[e]:
                continue
            a, b = d.road_a[e], d.road_b[e]
            if not board.inside(*canvas.cell(b)):
                continue
            glyph = arrow(canvas.fx[b] - canvas.fx[a], 2 * (canvas.fy[b] - canvas.fy[a]))
            for cell in reversed(line):
                if cell not in board.taken:
                    cells[cell] = (ARROW, e, glyph)
                    break

    def _rows(self, cells: dict[Cell, tuple[int, object, str]]) -> list[list[Item]]:
        """The cells as items, row by row: a run of like cells is one item."""
        rows: list[list[Item]] = [[] for _ in range(self.height)]
        for (c, r) in sorted(cells, key=lambda cell: (cell[1], cell[0])):
            kind, what, ch = cells[(c, r)]
            row = rows[r - self.y0]
            if row and kind != MARK and row[-1][2] == kind and row[-1][3] == what and (
                    row[-1][0] + len(row[-1][1]) == c):
                last = row[-1]
                row[-1] = (last[0], last[1] + ch, kind, what)
            else:
                row.append((c, ch, kind, what))
        return rows

    def cursor_cell(self, node: int, mark: Cell) -> Cell:
        """Where the cursor's mark goes for ``node``: after its name when the name is right
        of its mark, else right of the mark."""
        placed = self.names.get(node)
        if placed is not None and placed[1] == mark[1] and placed[0] == mark[0] + 1:
            return placed[0] + len(placed[2]), mark[1]
        return mark[0] + 1, mark[1]


class Tiles:
    """The tiles of one drawing, each drawn when first asked for; the latest few kept."""

    KEPT = 48

    def __init__(self, canvas: Canvas, names: Sequence[str], need: Sequence[int],
                 costs: bool) -> None:
        self.canvas, self.names, self.need, self.costs = canvas, names, need, costs
        self.kept: OrderedDict[tuple[int, int], Tile] = OrderedDict()

    def at(self, tx: int, ty: int) -> Tile:
        key = (tx, ty)
        tile = self.kept.get(key)
        if tile is not None:
            self.kept.move_to_end(key)
            return tile
        canvas = self.canvas
        tw, th = canvas.tile_size
        x0, y0 = tx * tw, ty * th
        tile = Tile(canvas, x0, y0, min(tw, canvas.cols - x0), min(th, canvas.rows - y0),
                    self.names, self.need, self.costs)
        self.kept[key] = tile
        if len(self.kept) > self.KEPT:
            self.kept.popitem(last=False)
        return tile

    def of_cell(self, col: int, row: int) -> Tile | None:
        """The tile holding a cell of the drawing (None: outside it)."""
        canvas = self.canvas
        if not (0 <= col < canvas.cols and 0 <= row < canvas.rows):
            return None
        tw, th = canvas.tile_size
        return self.at(col // tw, row // th)

    def row_items(self, row: int, c0: int, c1: int) -> Iterator[Item]:
        """The items of row ``row`` that reach into columns ``c0 .. c1-1``, by column."""
        canvas = self.canvas
        for tx, ty in canvas.tiles_across(c0, c1, row):
            tile = self.at(tx, ty)
            for item in tile.rows[row - tile.y0]:
                if item[0] < c1 and item[0] + len(item[1]) > c0:
                    yield item


__all__ = ["ARROW", "COST", "DOTS", "MARK", "NAME", "ROAD", "Item", "Tile", "Tiles",
           "arrow", "cost_text", "road_dots"]

"""Finding nodes on the drawing: the node at a cell (its mark, its name, or the nearest of
an overview cell's dots), the node nearest a point, the nearest node in a direction (the
arrow keys), and the order Tab goes in.

Distances are as the eye sees them on screen: a row counts as two columns.  "In a direction"
is within 45 degrees of it (a cone); when the cone holds no node, within 90 (the half-plane
that way).  The nearest wins, and of two as near, the lower number -- deterministic, whatever
the order the nodes were found in.
"""

from __future__ import annotations

import math

from tui_search.tui.view.graph_layout.canvas import Canvas
from tui_search.tui.view.graph_layout.raster import Tiles

#: The arrow keys' directions on screen (x right, y down).
DIRECTIONS = {"left": (-1, 0), "right": (1, 0), "up": (0, -1), "down": (0, 1)}
#: A click this far (in columns) from every node picks none.
REACH = 3.0


def node_at(tiles: Tiles, col: int, row: int) -> int | None:
    """The node drawn at cell ``(col, row)`` of the drawing: its mark or a letter of its name;
    in the overview, the dot of the cell's nodes nearest the cell's middle; else the node
    nearest the cell's middle, if one is within :data:`REACH`."""
    tile = tiles.of_cell(col, row)
    if tile is None:
        return None
    owner = tile.owner.get((col, row))
    if owner is not None:
        return owner
    canvas = tiles.canvas
    held = tile.dots.get((col, row))
    if held:
        return min(held, key=lambda v: (_seen_distance(canvas, v, col + 0.5, row + 0.5), v))
    return nearest(canvas, col + 0.5, row + 0.5, REACH)


def _seen_distance(canvas: Canvas, v: int, col: float, row: float) -> float:
    return math.hypot(canvas.fx[v] - col, 2 * (canvas.fy[v] - row))


def nearest(canvas: Canvas, col: float, row: float, reach: float = math.inf) -> int | None:
    """The node whose mark is nearest the point ``(col, row)`` of the drawing, within
    ``reach`` columns (None: none is)."""
    p = canvas.placement
    x, y = canvas.to_place(col, row)
    # a bucket's smallest side, in columns on screen
    step = min(p.bw * canvas.kx, 2 * p.bh * canvas.ky)
    best: tuple[float, int] | None = None
    for ring, found in p.rings(x, y):
        if best is not None and (ring - 1) * step > best[0]:
            break
        if (ring - 1) * step > reach:
            break
        for v in found:
            dist = _seen_distance(canvas, v, col, row)
            if dist <= reach and (best is None or (dist, v) < best):
                best = (dist, v)
    return None if best is None else best[1]


def toward(canvas: Canvas, node: int, direction: str) -> int | None:
    """The nearest node from ``node`` in ``direction`` (``left``, ``right``, ``up``,
    ``down``): within 45 degrees of it, else within 90; None when there is none that way."""
    ux, uy = DIRECTIONS[direction]
    fx, fy = canvas.fx, canvas.fy
    x0, y0 = fx[node], fy[node]
    p = canvas.placement
    step = min(p.bw * canvas.kx, 2 * p.bh * canvas.ky)
    best_cone: tuple[float, int] | None = None
    best_half: tuple[float, int] | None = None
    for ring, found in p.rings(p.xs[node], p.ys[node]):
        # every node in a later ring is at least this far away
        if best_cone is not None and (ring - 1) * step > best_cone[0]:
            break
        for v in found:
            if v == node:
                continue
            dx, dy = fx[v] - x0, 2 * (fy[v] - y0)
            along = dx * ux + dy * uy
            if along <= 0:
                continue
            across = abs(dx * uy - dy * ux)
            key = (math.hypot(dx, dy), v)
            if across <= along:
                if best_cone is None or key < best_cone:
                    best_cone = key
            elif best_half is None or key < best_half:
                best_half = key
    best = best_cone or best_half
    return None if best is None else best[1]


def tab_next(count: int, node: int, step: int = 1) -> int:
    """The node Tab (``step`` 1) or Shift+Tab (-1) goes to from ``node``: the next or the
    previous by number (the file's order), round the end."""
    return (node + step) % count


__all__ = ["DIRECTIONS", "REACH", "nearest", "node_at", "tab_next", "toward"]

"""Where each node of a graph is, in the graph's own units (x to the right, y up): the places
its file gives, or, for a graph without, a layered drawing worked out here -- and a grid of
buckets over them, so that the nodes in a region, or near a point, are found without looking
at every node (a graph may have 100,000).

The layered drawing (Sugiyama's, reduced to what reads well on a board): the start on top, each
node one layer below the nearest node that reaches it (a breadth-first search from the start,
roads taken both ways), each layer in the order the breadth-first search met its nodes (a
node's successors in the file's order, so ``edge S B`` before ``edge S A`` puts B left of A),
then, for a graph small enough, a few sweeps that sort each layer by the mean place of its
neighbours in the layer above (or below), which removes most crossings.  Every step is
deterministic; a part of the graph the start does not reach is drawn beside it, from its
lowest-numbered node.
"""

from __future__ import annotations

import math
from array import array
from collections.abc import Iterator

from tui_search.engine.maps.graph import Graph

#: Graphs up to this many nodes get the barycentric sweeps (each costs a pass over the roads).
SWEPT = 2000
SWEEPS = 4
#: About this many nodes a bucket, on average.
PER_BUCKET = 4


def neighbours(graph: Graph) -> list[list[int]]:
    """Each node's neighbours by any road, either way, in the file's order."""
    d = graph.data
    out: list[list[int]] = [[] for _ in range(len(graph))]
    for a, b in zip(d.road_a, d.road_b, strict=True):
        out[a].append(b)
        out[b].append(a)
    return out


def layered(graph: Graph) -> tuple[array[float], array[float]]:
    """A place for every node of a graph that has none: x across its layer (one unit between
    neighbours in a layer, each layer centred), y = minus its layer (the start's is 0)."""
    n = len(graph)
    near = neighbours(graph)
    xs, ys = array("d", [0.0]) * n, array("d", [0.0]) * n
    seen = bytearray(n)
    roots: Iterator[int] = iter(range(n))
    first = graph.index.get(graph.start, -1) if graph.start is not None else -1
    left = 0.0
    while True:
        root = first if first >= 0 else next((i for i in roots if not seen[i]), -1)
        first = -1
        if root < 0:
            break
        layers = _bfs_layers(root, near, seen)
        if sum(map(len, layers)) <= SWEPT:
            _sweep(layers, near)
        width = max(map(len, layers))
        for depth, layer in enumerate(layers):
            shift = left + (width - len(layer)) / 2
            for i, v in enumerate(layer):
                xs[v] = shift + i
                ys[v] = -float(depth)
        left += width + 1
    return xs, ys


def _bfs_layers(root: int, near: list[list[int]], seen: bytearray) -> list[list[int]]:
    """The nodes ``root`` reaches, by their number of roads from it, each layer in the order
    the search met them."""
    seen[root] = 1
    layers = [[root]]
    while True:
        nxt = []
        for v in layers[-1]:
            for u in near[v]:
                if not seen[u]:
                    seen[u] = 1
                    nxt.append(u)
        if not nxt:
            return layers
        layers.append(nxt)


def _sweep(layers: list[list[int]], near: list[list[int]]) -> None:
    """Sort each layer by the mean place of its neighbours in the layer before it (down, then
    up, and again): the barycentre heuristic.  Stable: ties keep their order."""
    depth = {v: d for d, layer in enumerate(layers) for v in layer}
    place = {v: i - (len(layer) - 1) / 2 for layer in layers for i, v in enumerate(layer)}
    for sweep in range(SWEEPS):
        down = sweep % 2 == 0
        order = range(1, len(layers)) if down else range(len(layers) - 2, -1, -1)
        for d in order:
            ref = d - 1 if down else d + 1
            layer = layers[d]
            keys = {}
            for v in layer:
                xs = [place[u] for u in near[v] if depth[u] == ref]
                keys[v] = sum(xs) / len(xs) if xs else place[v]
            layer.sort(key=keys.__getitem__)
            for i, v in enumerate(layer):
                place[v] = i - (len(layer) - 1) / 2


class Placement:
    """Every node's place (``xs``, ``ys``), their bounds, whether the file gave them
    (``given``: then a drawing keeps their proportions), and buckets to find nodes by place."""

    def __init__(self, graph: Graph) -> None:
        self.graph = graph
        self.given = graph.has_places
        if self.given:
            self.xs, self.ys = array("d", graph.data.x), array("d", graph.data.y)
        else:
            self.xs, self.ys = layered(graph)
        xs, ys = self.xs, self.ys
        self.x0, self.x1, self.y0, self.y1 = min(xs), max(xs), min(ys), max(ys)
        n = len(xs)
        # Buckets about square in the graph's units, PER_BUCKET nodes each on average.
        w, h = self.x1 - self.x0, self.y1 - self.y0
        count = max(1, n // PER_BUCKET)
        if w <= 0 and h <= 0:
            across = down = 1
        elif h <= 0:
            across, down = count, 1
        elif w <= 0:
            across, down = 1, count
        else:
            across = max(1, round(math.sqrt(count * w / h)))
            down = max(1, round(count / across))
        self.across, self.down = min(across, 4096), min(down, 4096)
        self.bw = (w / self.across) or 1.0
        self.bh = (h / self.down) or 1.0
        buckets: list[list[int]] = [[] for _ in range(self.across * self.down)]
        for i in range(n):
            buckets[self.bucket(xs[i], ys[i])].append(i)
        self.buckets = buckets
        self._road_buckets: tuple[list[list[int]], list[int]] | None = None

    def __len__(self) -> int:
        return len(self.xs)

    def column(self, x: float) -> int:
        return min(self.across - 1, max(0, int((x - self.x0) / self.bw)))

    def row(self, y: float) -> int:
        return min(self.down - 1, max(0, int((y - self.y0) / self.bh)))

    def bucket(self, x: float, y: float) -> int:
        return self.row(y) * self.across + self.column(x)

    def nodes_in(self, xa: float, xb: float, ya: float, yb: float) -> list[int]:
        """The nodes whose places are in ``[xa, xb] x [ya, yb]``, by number."""
        if len(self.buckets) == 1:
            found = self.buckets[0]
        else:
            found = []
            for by in range(self.row(ya), self.row(yb) + 1):
                base = by * self.across
                for bx in range(self.column(xa), self.column(xb) + 1):
                    found.extend(self.buckets[base + bx])
        xs, ys = self.xs, self.ys
        return sorted(i for i in found if xa <= xs[i] <= xb and ya <= ys[i] <= yb)

    def roads_near(self, xa: float, xb: float, ya: float, yb: float) -> list[int]:
        """The roads that may cross ``[xa, xb] x [ya, yb]`` (a few more), by number."""
        if self._road_buckets is None:
            self._road_buckets = self._bucket_roads()
        inside, long = self._road_buckets
        found = set(long)
        for by in range(max(0, self.row(ya) - 1), min(self.down, self.row(yb) + 2)):
            base = by * self.across
            for bx in range(max(0, self.column(xa) - 1), min(self.across, self.column(xb) + 2)):
                found.update(inside[base + bx])
        return sorted(found)

    def _bucket_roads(self) -> tuple[list[list[int]], list[int]]:
        """Each road no longer than a bucket, in its first end's bucket; the longer ones."""
        d = self.graph.data
        xs, ys, bw, bh = self.xs, self.ys, self.bw, self.bh
        inside: list[list[int]] = [[] for _ in self.buckets]
        long = []
        for e, (a, b) in enumerate(zip(d.road_a, d.road_b, strict=True)):
            if abs(xs[a] - xs[b]) <= bw and abs(ys[a] - ys[b]) <= bh:
                inside[self.bucket(xs[a], ys[a])].append(e)
            else:
                long.append(e)
        return inside, long

    def rings(self, x: float, y: float) -> Iterator[tuple[int, list[int]]]:
        """The nodes in the buckets around ``(x, y)``, ring by ring: ring ``r`` holds the
        buckets ``r`` steps away (in either direction) from the point's, so every node of a
        later ring is at least ``r`` buckets' width or height from the point."""
        cx, cy = self.column(x), self.row(y)
        reach = max(cx, self.across - 1 - cx, cy, self.down - 1 - cy)
        for r in range(reach + 1):
            found: list[int] = []
            for by in range(max(0, cy - r), min(self.down, cy + r + 1)):
                edge = by in (cy - r, cy + r)
                step = 1 if edge else 2 * r
                for bx in range(cx - r, cx + r + 1, max(1, step)):
                    if 0 <= bx < self.across:
                        found.extend(self.buckets[by * self.across + bx])
            yield r, found


__all__ = ["Placement", "layered", "neighbours"]

"""The generators' algorithms: each fills a ``width`` x ``height`` bytearray of obstacles
(1 blocked, 0 free, row-major) from a :class:`~tui_search.engine.util.prng.SplitMix64`.

The mazes are drawn on *nodes*, the cells with both coordinates even; the cell between two
neighbouring nodes is their passage, and every cell with both coordinates odd is a wall.  A
``W`` x ``H`` map has ``(W + 1) // 2`` x ``(H + 1) // 2`` nodes: an even width or height leaves
its last column or row all wall.  Each maze algorithm opens the nodes and the passages of a
spanning tree of them, so the open cells form a tree under the four moves N, E, S, W (a
*perfect* maze: one way between any two cells).  Every loop here is iterative (no recursion
limit on a big map), and every choice is a draw from the generator in a fixed order, so the
same seed gives the same map everywhere.
"""

from __future__ import annotations

from collections import deque

from tui_search.engine.util.prng import SplitMix64

__all__ = ["backtracker", "divide", "kruskal", "node_size", "prim", "random_fill"]

Node = tuple[int, int]
_STEPS = ((0, -1), (1, 0), (0, 1), (-1, 0))  # N, E, S, W: the order every loop tries


def node_size(width: int, height: int) -> tuple[int, int]:
    """How many nodes a map of this size has across and down."""
    return (width + 1) // 2, (height + 1) // 2


class _Carving:
    """An all-wall map whose nodes and passages are opened one by one."""

    def __init__(self, width: int, height: int) -> None:
        self.width = width
        self.cw, self.ch = node_size(width, height)
        self.blocked = bytearray(b"\x01" * (width * height))
        self.open_node((0, 0))

    def open_node(self, node: Node) -> None:
        self.blocked[2 * node[1] * self.width + 2 * node[0]] = 0

    def join(self, a: Node, b: Node) -> None:
        """Open node ``b`` and the passage from ``a`` to it."""
        self.open_node(b)
        self.blocked[(a[1] + b[1]) * self.width + a[0] + b[0]] = 0

    def neighbours(self, node: Node) -> list[Node]:
        x, y = node
        return [(x + dx, y + dy) for dx, dy in _STEPS
                if 0 <= x + dx < self.cw and 0 <= y + dy < self.ch]


def backtracker(width: int, height: int, rng: SplitMix64) -> bytearray:
    """The recursive backtracker -- a randomised depth-first search: from the node on top of
    the stack, carve to a random unvisited neighbour and push it; with none, pop."""
    maze = _Carving(width, height)
    seen = {(0, 0)}
    stack = [(0, 0)]
    while stack:
        node = stack[-1]
        fresh = [n for n in maze.neighbours(node) if n not in seen]
        if not fresh:
            stack.pop()
            continue
        nxt = rng.choice(fresh)
        maze.join(node, nxt)
        seen.add(nxt)
        stack.append(nxt)
    return maze.blocked


def prim(width: int, height: int, rng: SplitMix64) -> bytearray:
    """Randomised Prim: take a random node next to the tree, join it to a random tree
    neighbour of it, and add its own outside neighbours to the candidates."""
    maze = _Carving(width, height)
    tree = {(0, 0)}
    frontier = maze.neighbours((0, 0))
    waiting = set(frontier)
    while frontier:
        i = rng.below(len(frontier))
        frontier[i], frontier[-1] = frontier[-1], frontier[i]
        node = frontier.pop()
        maze.join(rng.choice([n for n in maze.neighbours(node) if n in tree]), node)
        tree.add(node)
        for n in maze.neighbours(node):
            if n not in tree and n not in waiting:
                waiting.add(n)
                frontier.append(n)
    return maze.blocked


def kruskal(width: int, height: int, rng: SplitMix64) -> bytearray:
    """Randomised Kruskal: every passage in a shuffled order, opened when it joins two nodes
    not yet connected (a union-find forest says which)."""
    maze = _Carving(width, height)
    cw, ch = maze.cw, maze.ch
    edges = [((x, y), (x + 1, y)) for y in range(ch) for x in range(cw - 1)]
    edges += [((x, y), (x, y + 1)) for y in range(ch - 1) for x in range(cw)]
    rng.shuffle(edges)
    parent = list(range(cw * ch))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in edges:
        ra, rb = root(a[1] * cw + a[0]), root(b[1] * cw + b[0])
        if ra != rb:
            parent[ra] = rb
            maze.open_node(a)
            maze.join(a, b)
    return maze.blocked


def divide(width: int, height: int, rng: SplitMix64, room: int = 1) -> bytearray:
    """Recursive division: the nodes' area starts open; a chamber more than ``room`` nodes
    across or down is split by a wall between two rows (or columns) of nodes with one gap --
    a door -- at a random node, and each half is divided in turn.  With ``room`` 1 the result
    is a perfect maze; larger, open rooms joined by one door per wall (one way between any two
    rooms).  A chamber is split across its longer side (either, at random, when square)."""
    cw, ch = node_size(width, height)
    blocked = bytearray(b"\x01" * (width * height))
    for y in range(2 * ch - 1):
        blocked[y * width : y * width + 2 * cw - 1] = bytes(2 * cw - 1)
    chambers = [(0, 0, cw - 1, ch - 1)]  # x0, y0, x1, y1 in nodes, inclusive
    while chambers:
        x0, y0, x1, y1 = chambers.pop()
        across, down = x1 - x0 + 1, y1 - y0 + 1
        if across <= room and down <= room or across == 1 and down == 1:
            continue
        if down <= room or (across > room and across > down):
            vertical = True
        elif across <= room or down > across:
            vertical = False
        else:
            vertical = rng.below(2) == 0
        if vertical:
            k = x0 + rng.below(across - 1)
            door = y0 + rng.below(down)
            for y in range(2 * y0, 2 * y1 + 1):
                blocked[y * width + 2 * k + 1] = y != 2 * door
            chambers += [(x0, y0, k, y1), (k + 1, y0, x1, y1)]
        else:
            k = y0 + rng.below(down - 1)
            door = x0 + rng.below(across)
            row = (2 * k + 1) * width
            for x in range(2 * x0, 2 * x1 + 1):
                blocked[row + x] = x != 2 * door
            chambers += [(x0, y0, x1, k), (x0, k + 1, x1, y1)]
    return blocked


def random_fill(width: int, height: int, rng: SplitMix64, percent_num: int,
                percent_den: int) -> bytearray:
    """Each cell, in row order, an obstacle with probability ``percent_num / percent_den``
    percent (a draw ``z`` from the generator: blocked when ``z * 100 * den < num * 2**64``);
    then the top-left and bottom-right cells are freed, and when they are not connected under
    the four moves, the fewest obstacles that connect them are cleared (a 0-1 breadth-first
    search, moves tried N, E, S, W)."""
    limit = percent_num << 64
    scale = 100 * percent_den
    blocked = bytearray(rng.next() * scale < limit for _ in range(width * height))
    start, goal = 0, width * height - 1
    blocked[start] = blocked[goal] = 0
    cost = [-1] * (width * height)
    came = [-1] * (width * height)
    cost[start] = 0
    todo = deque([start])
    while todo:
        i = todo.popleft()
        x, y = i % width, i // width
        for dx, dy in _STEPS:
            if 0 <= x + dx < width and 0 <= y + dy < height:
                j = i + dy * width + dx
                c = cost[i] + blocked[j]
                if cost[j] < 0 or c < cost[j]:
                    cost[j], came[j] = c, i
                    if blocked[j]:
                        todo.append(j)
                    else:
                        todo.appendleft(j)
    i = goal
    while i != start:
        blocked[i] = 0
        i = came[i]
    return blocked

"""Other packages' BFS on the same map (optional: ``pip install -e .[bench]``): each function
returns a solver to time, or None when its package is not installed."""

from __future__ import annotations

import time
from collections.abc import Callable

from benchmarks.baselines import pad
from tui_search.engine.maps.grid import Grid


def pathfinding_bfs(grid: Grid) -> Callable[[], object] | None:
    try:
        from pathfinding.core.diagonal_movement import DiagonalMovement
        from pathfinding.core.grid import Grid as PFGrid
        from pathfinding.finder.breadth_first import BreadthFirstFinder
    except ImportError:
        return None
    w = grid.width
    matrix = [[0 if grid.blocked[y * w + x] else 1 for x in range(w)] for y in range(grid.height)]

    def solve():  # grid construction included: pathfinding keeps search state on its nodes
        pf = PFGrid(matrix=matrix)
        finder = BreadthFirstFinder(diagonal_movement=DiagonalMovement.always)
        path, _ = finder.find_path(pf.node(*grid.start), pf.node(*grid.goal), pf)
        return len(path) - 1

    return solve


def edges(grid: Grid):
    """Directed edges between free padded cells, one array per neighbour offset (numpy)."""
    import numpy as np

    walls, _, _, _, offs = pad(grid)
    free = np.frombuffer(bytes(walls), dtype=np.uint8) == 0
    n = len(walls)
    src, dst = [], []
    idx = np.flatnonzero(free).astype(np.int32)
    for off in offs:
        ok = free[idx + off]  # the border keeps idx + off in range
        src.append(idx[ok])
        dst.append(idx[ok] + off)
    return n, np.concatenate(src), np.concatenate(dst)


def scipy_bfs(grid: Grid) -> Callable[[], object] | None:
    try:
        import numpy as np
        from scipy.sparse import csr_matrix
        from scipy.sparse.csgraph import breadth_first_order
    except ImportError:
        return None
    _, _, start, goal, _ = pad(grid)

    def solve():
        n, src, dst = edges(grid)
        graph = csr_matrix((np.ones(len(src), dtype=np.int8), (src, dst)), shape=(n, n))
        t = time.perf_counter()
        _, pred = breadth_first_order(graph, start, directed=True, return_predecessors=True)
        solve.bfs_only.append(time.perf_counter() - t)
        moves, v = 0, goal
        while v != start:
            v = pred[v]
            moves += 1
        return moves

    solve.bfs_only = []
    return solve


def networkx_bfs(grid: Grid) -> Callable[[], object] | None:
    try:
        import networkx as nx
    except ImportError:
        return None
    walls, _, start, goal, offs = pad(grid)
    half = [o for o in offs if o > 0]  # undirected: each edge once

    def solve():
        g = nx.Graph()
        g.add_edges_from(
            (p, p + o) for p in range(len(walls)) if not walls[p] for o in half if not walls[p + o]
        )
        return len(nx.shortest_path(g, start, goal)) - 1

    return solve

"""The bare searches the engine is measured against: the fastest plain-Python BFS (and DFS) we
could write, with the engine's semantics, so they find paths of the same length."""

from __future__ import annotations

from collections import deque

from tui_search.engine.grid import DEFAULT_ORDER, DELTAS, Grid


def pad(grid: Grid) -> tuple[bytearray, int, int, int, tuple[int, ...]]:
    """The engine's technique, written out: walls with a one-cell wall border, flat indices,
    the eight neighbour offsets in the default order."""
    w, h = grid.width, grid.height
    stride = w + 2
    walls = bytearray(b"\x01") * (stride * (h + 2))
    for y in range(h):
        row = (y + 1) * stride + 1
        walls[row : row + w] = grid.blocked[y * w : (y + 1) * w]
    start = (grid.start[1] + 1) * stride + grid.start[0] + 1
    goal = (grid.goal[1] + 1) * stride + grid.goal[0] + 1
    offs = tuple(DELTAS[d][1] * stride + DELTAS[d][0] for d in DEFAULT_ORDER)
    return walls, stride, start, goal, offs


def bare_search(grid: Grid, lifo: bool = False) -> list[int]:
    """The fastest plain-Python BFS we could write: a deque, a closed bytearray (the padded
    walls themselves), a parent list; no recording.  Same semantics as the engine (mark and
    goal-test on generation, neighbours in the default order), so the same path.  With
    ``lifo`` the deque is a stack: the engine's DFS, same path again."""
    closed, _, start, goal, offs = pad(grid)
    parent = [-1] * len(closed)
    if start == goal:
        return parent
    q = deque([start])
    closed[start] = 1
    pop, push = (q.pop if lifo else q.popleft), q.append
    while q:
        n = pop()
        for off in offs:
            m = n + off
            if closed[m]:
                continue
            closed[m] = 1
            parent[m] = n
            if m == goal:
                return parent
            push(m)
    return parent


def bare_search_visit_on_expand(grid: Grid, lifo: bool = False) -> list[int]:
    """The floor of "visit on expand": the same bare loop, but a cell is closed when popped,
    so it is pushed once per neighbour that reaches it first (several times the work of
    :func:`bare_search`); popping a closed cell is skipped.  The parent is the entry popped
    first: for FIFO the first push of the cell (kept), for LIFO its last (overwritten).  The
    goal is tested when pushed, as in the engine's loop for this choice."""
    closed, _, start, goal, offs = pad(grid)
    parent = [-1] * len(closed)
    if start == goal:
        return parent
    q = deque([start])
    pop, push = (q.pop if lifo else q.popleft), q.append
    while q:
        n = pop()
        if closed[n]:
            continue
        closed[n] = 1
        for off in offs:
            m = n + off
            if closed[m]:
                continue
            if lifo or parent[m] < 0:
                parent[m] = n
            if m == goal:
                return parent
            push(m)
    return parent


def walled_in(grid: Grid) -> Grid:
    """A copy with every free neighbour of the goal blocked: no search finds the goal, so a
    BFS or DFS traverses everything it can reach (the "full traversal" rows)."""
    out = grid.copy()
    gx, gy = out.goal
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            cell = (gx + dx, gy + dy)
            if (dx or dy) and out.is_free(cell) and cell != out.start:
                out.set_blocked(cell, True)
    return out


def bare_bfs(grid: Grid) -> list[int]:
    return bare_search(grid)


def bare_dfs(grid: Grid) -> list[int]:
    return bare_search(grid, lifo=True)


def bare_path_len(grid: Grid, parent: list[int]) -> int:
    _, _, start, goal, _ = pad(grid)
    n, moves = goal, 0
    while n != start:
        n = parent[n]
        if n < 0:
            return -1
        moves += 1
    return moves

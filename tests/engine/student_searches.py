"""Small searches written the way students write them (no tui_search), each returning its trace
text: the diagnosis tests' inputs."""

from __future__ import annotations

import json
from collections import deque

MOVES = {"N": (0, -1), "E": (1, 0), "S": (0, 1), "W": (-1, 0)}


def _search(rows: list[str], order: str, take, visit_on_expand: bool = False) -> str:
    """The loop every one of them shares: ``take(frontier, steps_so_far)`` takes the next
    cell off the frontier (a deque); cells are marked visited when added, or with
    ``visit_on_expand`` when taken off (pops of cells already done are left out)."""
    cells = {(x, y): ch for y, row in enumerate(rows) for x, ch in enumerate(row)}
    start = next(c for c, ch in cells.items() if ch == "S")
    goal = next(c for c, ch in cells.items() if ch == "G")
    frontier, seen, out = deque([start]), set() if visit_on_expand else {start}, []
    while frontier:
        node = take(frontier, len(out))
        if visit_on_expand:
            if node in seen:
                continue
            seen.add(node)
        added = []
        for d in order.split(","):
            nxt = (node[0] + MOVES[d][0], node[1] + MOVES[d][1])
            if cells.get(nxt, "#") != "#" and nxt not in seen:
                if not visit_on_expand:
                    seen.add(nxt)
                frontier.append(nxt)
                added.append(nxt)
                if nxt == goal:
                    break
        out.append(json.dumps({"node": list(node), "successors": [list(c) for c in added]}))
        if goal in added:
            break
    return "\n".join(out) + "\n"


def bfs(rows: list[str], order: str, bug_at: int | None = None) -> str:
    """BFS marking cells visited when added; ``bug_at``: at that step it takes the newest
    entry instead of the oldest (once)."""
    return _search(rows, order, lambda q, n: q.pop() if n + 1 == bug_at else q.popleft())


def bfs_visit_on_expand(rows: list[str], order: str) -> str:
    """BFS marking cells visited when taken off."""
    return _search(rows, order, lambda q, n: q.popleft(), visit_on_expand=True)


def dfs_stack(rows: list[str], order: str) -> str:
    """DFS with a stack, marking cells visited when pushed."""
    return _search(rows, order, lambda q, n: q.pop())


def astar_ties_on_h(rows: list[str], order: str) -> str:
    """A* with the Manhattan distance that breaks ties of f on the lower h (the app's takes
    the oldest entry); a cell taken off again after a cheaper push is left out."""
    import heapq

    cells = {(x, y): ch for y, row in enumerate(rows) for x, ch in enumerate(row)}
    start = next(c for c, ch in cells.items() if ch == "S")
    goal = next(c for c, ch in cells.items() if ch == "G")

    def h(c: tuple) -> int:
        return abs(c[0] - goal[0]) + abs(c[1] - goal[1])

    heap, best, done, out, n = [(h(start), h(start), 0, start)], {start: 0}, set(), [], 0
    while heap:
        _, _, _, node = heapq.heappop(heap)
        if node in done:
            continue
        done.add(node)
        added = []
        for d in order.split(",") if node != goal else []:
            nxt = (node[0] + MOVES[d][0], node[1] + MOVES[d][1])
            if cells.get(nxt, "#") != "#" and best[node] + 1 < best.get(nxt, 1 << 30):
                best[nxt], n = best[node] + 1, n + 1
                heapq.heappush(heap, (best[nxt] + h(nxt), h(nxt), n, nxt))
                added.append(nxt)
        out.append(json.dumps({"node": list(node), "successors": [list(c) for c in added]}))
        if node == goal:
            break
    return "\n".join(out) + "\n"


def dfs_recursive(rows: list[str], order: str) -> str:
    """DFS by recursion: a cell is visited when entered, and its line lists the neighbours
    not yet visited then (some are visited deeper down before the loop comes to them)."""
    cells = {(x, y): ch for y, row in enumerate(rows) for x, ch in enumerate(row)}
    start = next(c for c, ch in cells.items() if ch == "S")
    goal = next(c for c, ch in cells.items() if ch == "G")
    visited, out = set(), []

    def visit(node: tuple) -> bool:
        visited.add(node)
        around = [(node[0] + MOVES[d][0], node[1] + MOVES[d][1]) for d in order.split(",")]
        todo = [] if node == goal else [
            c for c in around if cells.get(c, "#") != "#" and c not in visited]
        out.append(json.dumps({"node": list(node), "successors": [list(c) for c in todo]}))
        return node == goal or any(visit(c) for c in todo if c not in visited)

    visit(start)
    return "\n".join(out) + "\n"

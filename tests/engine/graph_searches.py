"""The six searches on a graph, written again from docs/08-semantics.md with no tui_search:
plain dictionaries and lists, as a student would write them.  The tests hold the app's runs
equal to these, step by step (tests/engine/test_graph_search.py).

A graph here is ``{node: [(successor, cost), ...]}`` with each node's roads in the order they
are tried.  A search returns its steps: ``(node taken off, successors added in order,
discarded)``, and the path found (None: none)."""

from __future__ import annotations

import heapq
from collections.abc import Callable

Roads = dict[str, list[tuple[str, float]]]
Steps = list[tuple[str, tuple[str, ...], bool]]
#: Costs equal but for the floats' rounding are no cheaper path.
CHEAPER_BY = 1e-9


def path_to(parents: dict[int, int | None], names: list[str], entry: int) -> list[str]:
    path = []
    at: int | None = entry
    while at is not None:
        path.append(names[at])
        at = parents[at]
    return path[::-1]


def queue_search(roads: Roads, start: str, goals: set[str], lifo: bool, visit: str,
                 goal_test: str, tree: bool, limit: int) -> tuple[Steps, list[str] | None]:
    """BFS (a queue) or DFS (a stack); ``visit``: generate or expand; ``tree``: no visited set,
    a successor on the node's own path skipped."""
    names, parents = [start], {0: None}  # entries: their node, their parent entry
    if goal_test == "generate" and start in goals:
        return [], [start]
    frontier, reached, expanded = [0], {start}, set()
    steps: Steps = []
    while frontier and len(steps) < limit:
        e = frontier.pop() if lifo else frontier.pop(0)
        node = names[e]
        if visit == "expand" and not tree:
            if node in expanded:
                steps.append((node, (), True))
                continue
            expanded.add(node)
        if goal_test == "expand" and node in goals:
            steps.append((node, (), False))
            return steps, path_to(parents, names, e)
        on_path = set(path_to(parents, names, e)) if tree else set()
        added = []
        for succ, _ in roads[node]:
            if tree:
                if succ in on_path:
                    continue
            elif (succ in expanded) if visit == "expand" else (succ in reached):
                continue
            reached.add(succ)
            names.append(succ)
            parents[len(names) - 1] = e
            frontier.append(len(names) - 1)
            added.append(succ)
            if goal_test == "generate" and succ in goals:
                steps.append((node, tuple(added), False))
                return steps, path_to(parents, names, len(names) - 1)
        steps.append((node, tuple(added), False))
    return steps, None


def priority_search(roads: Roads, start: str, goals: set[str], priority: str,
                    h: Callable[[str], float], goal_test: str, tree: bool, limit: int,
                    ties: str = "fifo", reopen: bool = True, mark_start: bool = True
                    ) -> tuple[Steps, list[str] | None]:
    """Uniform-cost (``g``), greedy (``h``) or A* (``g+h``): the lowest first; of equal
    priorities (``ties``) the oldest, the newest, the smallest name, the lower or higher h,
    the lower or higher g, then the oldest; a node pushed again when reached cheaper; a stale
    entry discarded.  ``reopen=False``: a closed set: a node expanded is never pushed again,
    an entry of it taken off later discarded, and a node's first entry taken off expanded at
    its best g so far.  ``mark_start=False``: the start's g is not kept, so a road back to it
    pushes it again (as library code that marks nothing before its loop)."""
    def tie(n: int, node: str, g: float) -> object:
        return {"fifo": 0, "lifo": -n, "node": node, "low-h": h(node), "high-h": -h(node),
                "low-g": g, "high-g": -g}[ties]
    def key(g: float, node: str) -> float:
        return {"g": g, "h": h(node), "g+h": g + h(node)}[priority]

    names, parents, gs = [start], {0: None}, [0.0]
    if goal_test == "generate" and start in goals:
        return [], [start]
    best = {start: 0.0} if mark_start else {}
    heap: list[tuple[float, object, int]] = [(key(0.0, start), tie(0, start, 0.0), 0)]
    closed: set[str] = set()
    steps: Steps = []
    while heap and len(steps) < limit:
        _, _, e = heapq.heappop(heap)
        node, g = names[e], gs[e]
        if not tree and not reopen:
            if node in closed:
                steps.append((node, (), True))
                continue
            closed.add(node)
            g = best.get(node, g)  # (the start has no best g when it was not marked)
        elif not tree and g > best.get(node, g) + CHEAPER_BY:
            steps.append((node, (), True))
            continue
        if goal_test == "expand" and node in goals:
            steps.append((node, (), False))
            return steps, path_to(parents, names, e)
        on_path = set(path_to(parents, names, e)) if tree else set()
        added = []
        for succ, cost in roads[node]:
            g2 = g + cost
            if tree:
                if succ in on_path:
                    continue
            elif succ in closed or (succ in best and not g2 < best[succ] - CHEAPER_BY):
                continue
            best[succ] = g2
            names.append(succ)
            gs.append(g2)
            parents[len(names) - 1] = e
            n = len(names) - 1
            heapq.heappush(heap, (key(g2, succ), tie(n, succ, g2), n))
            added.append(succ)
            if goal_test == "generate" and succ in goals:
                steps.append((node, tuple(added), False))
                return steps, path_to(parents, names, len(names) - 1)
        steps.append((node, tuple(added), False))
    return steps, None


def iterative_deepening(roads: Roads, start: str, goals: set[str], limit: int
                        ) -> tuple[Steps, list[str] | None]:
    """Depth-limited DFS with limits 0, 1, 2, ...: a node pushed again within an iteration
    only when reached at a smaller depth; a node at the limit expanded with no successors;
    the goal tested on generate.  (Only for graphs where the goal is reached: the tests make
    sure of it.)"""
    if start in goals:
        return [], [start]
    steps: Steps = []
    depth_limit = 0
    while len(steps) < limit:
        names, parents, depths = [start], {0: None}, [0]
        stack, best = [0], {start: 0}
        while stack and len(steps) < limit:
            e = stack.pop()
            node, d = names[e], depths[e]
            if d == depth_limit:
                steps.append((node, (), False))
                continue
            added = []
            for succ, _ in roads[node]:
                if succ in best and not d + 1 < best[succ]:
                    continue
                best[succ] = d + 1
                names.append(succ)
                depths.append(d + 1)
                parents[len(names) - 1] = e
                stack.append(len(names) - 1)
                added.append(succ)
                if succ in goals:
                    steps.append((node, tuple(added), False))
                    return steps, path_to(parents, names, len(names) - 1)
            steps.append((node, tuple(added), False))
        depth_limit += 1
    return steps, None

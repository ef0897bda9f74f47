"""Is a graph's estimate admissible and consistent?  A* finds the cheapest path when its
estimate never says more than the true cost to the nearest goal (admissible); it never
re-opens a node when, along every road, the estimate drops by at most the road's cost
(consistent).  A table in a file is someone's claim: :func:`estimate_faults` checks it
against the graph and says where it fails, by name and figures, so the app and the command
line can warn before a search trusts it."""

from __future__ import annotations

from heapq import heappop, heappush

from tui_search.engine.maps.graph import Graph
from tui_search.engine.search.space import graph_estimate

#: Slack for the floats of a file's figures (a table written to one decimal place).
SLACK = 1e-9


def true_costs(graph: Graph) -> list[float]:
    """Every node's cheapest cost to the nearest goal (``inf``: none reaches one): Dijkstra
    from the goals backwards along the roads (closed nodes left out, as the search does)."""
    n = len(graph)
    into: list[list[tuple[int, float]]] = [[] for _ in range(n)]
    for a in range(n):
        for b, cost, _ in graph.roads_out(a):
            into[b].append((a, cost))
    closed = {graph.index[name] for name in graph.closed}
    best = [float("inf")] * n
    heap: list[tuple[float, int]] = []
    for goal in graph.goals:
        g = graph.index[goal]
        if g not in closed:
            best[g] = 0.0
            heap.append((0.0, g))
    while heap:
        cost, b = heappop(heap)
        if cost > best[b]:
            continue
        for a, road in into[b]:
            if a not in closed and cost + road < best[a]:
                best[a] = cost + road
                heappush(heap, (cost + road, a))
    return best


def estimate_faults(graph: Graph, name: str) -> list[str]:
    """What is wrong with the estimate ``name`` (``table``, ``euclidean``, ``zero``) on
    ``graph``: at most one sentence on admissibility (the node where it overestimates the
    most) and one on consistency (the road where it drops the most beyond its cost).  Empty
    when it is both."""
    h = graph_estimate(graph, name)
    names = graph.names
    faults: list[str] = []
    best = true_costs(graph)
    over = [(h(names[i]) - best[i], i) for i in range(len(graph)) if best[i] < float("inf")]
    worst = max(over, default=(0.0, -1))
    if worst[0] > SLACK:
        i = worst[1]
        faults.append(f"the {name} estimate is not admissible: h({names[i]}) = "
                      f"{_figure(h(names[i]))} but the cheapest way to a goal costs "
                      f"{_figure(best[i])} (A* may miss the cheapest path)")
    drop = (0.0, -1, -1, 0.0)
    for a in range(len(graph)):
        ha = h(names[a])
        for b, cost, _ in graph.roads_out(a):
            excess = ha - h(names[b]) - cost
            if excess > drop[0]:
                drop = (excess, a, b, cost)
    if drop[0] > SLACK:
        _, a, b, cost = drop
        faults.append(f"the {name} estimate is not consistent: h({names[a]}) = "
                      f"{_figure(h(names[a]))} is more than the road to {names[b]} "
                      f"({_figure(cost)}) plus h({names[b]}) = {_figure(h(names[b]))} "
                      "(A* may expand a node again)")
    return faults


def _figure(x: float) -> str:
    return f"{x:g}" if x == int(x) else f"{x:.3f}".rstrip("0")

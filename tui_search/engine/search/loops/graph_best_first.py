"""The recorded loop of uniform-cost search, greedy best-first search and A* on a graph, graph
search under the plain choices (:attr:`~tui_search.engine.search.choices.Semantics.plain`):
node numbers, the graph's compressed rows and flat arrays, where the reference loop
(:mod:`~tui_search.engine.search.loops.published`) walks names and node objects.

It records what the reference does on a graph (:class:`~tui_search.engine.search.space.
GraphSpace` under :class:`~tui_search.engine.search.rules.Cheapest`): a heap of
``(priority, event, node, g)``, ties to the oldest entry; a node pushed again when reached
with a g lower than its best by more than
:data:`~tui_search.engine.search.heuristics.CHEAPER_BY`, even after it was expanded; an entry
taken off with a g above its node's best is stale, a discarded step.  A node's successors are
its roads in the file's order (or by the names they reach, then the road's number), closed
nodes left out; a road costs its cost.  A hypothesis test in ``tests/engine`` holds it equal
to the reference, array for array.
"""

from __future__ import annotations

import heapq
from array import array
from collections.abc import Callable, Iterator

from tui_search.engine.search.graph_problem import GraphProblem
from tui_search.engine.search.heuristics import CHEAPER_BY
from tui_search.engine.search.loops.best_first import _flush
from tui_search.engine.search.record import CHUNK, Record
from tui_search.engine.search.space import GraphSpace

INF = float("inf")


def _by_name(problem: GraphProblem) -> Callable[[int], list[int]]:
    """A node's rows (indices into the graph's rows) by the names they reach, then by their
    road's number, as :meth:`~tui_search.engine.maps.graph.Graph.successors` sorts them."""
    graph = problem.graph
    starts, roads, nodes = graph.data.rows()
    names = graph.names

    def rows(n: int) -> list[int]:
        return sorted(range(starts[n], starts[n + 1]),
                      key=lambda j: (names[nodes[j]], roads[j] >> 1))

    return rows


def graph_best_first(problem: GraphProblem, rec: Record, chunk: int = CHUNK,
                     priority: str = "g") -> Iterator[int]:
    """Graph search on ``problem``'s graph in order of ``priority`` ("g", "h" or "g+h")."""
    graph, space = problem.graph, problem.space
    assert isinstance(space, GraphSpace)
    data = graph.data
    starts, _, nodes = data.rows()
    costs = data.row_costs()
    n_nodes = len(graph)
    open_ = bytearray(b"\x01") * n_nodes  # 0: a closed node, which no search enters
    for name in graph.closed:
        open_[graph.index[name]] = 0
    goal = bytearray(n_nodes)
    for g_node in problem.goals:
        goal[g_node] = 1
    on_push = problem.goal_test == "generate"
    use_h, use_g = "h" in priority, "g" in priority
    h = space.estimate_by_number() if use_h else None
    by_name = _by_name(problem) if space.by_name else None
    best = array("d", [INF]) * n_nodes
    start = problem.start
    rec.gen_node.append(start)
    rec.step_exp = step_exp = array("i", [-1])
    rec.step_g = step_g = array("d", [0.0])
    best[start] = 0.0
    if on_push and goal[start]:
        rec.goal_gen, rec.done = 0, True
        return
    f0 = 0.0 if h is None else (0.0 + h(start) if use_g else h(start))
    heap: list[tuple[float, int, int, float]] = [(f0, 0, start, 0.0)]
    pop, push = heapq.heappop, heapq.heappush
    new: list[int] = []
    gs: list[float] = []
    ends: list[int] = []
    exps: list[int] = []
    discarded: list[int] = []
    buffers = ((rec.gen_node, new, "i"), (step_g, gs, "d"), (rec.step_end, ends, "i"),
               (step_exp, exps, "i"), (rec.discarded, discarded, "i"))
    count = 1
    while heap:
        first = rec.steps + 1
        for step in range(first, first + chunk):  # the step's number, with no counter
            try:
                _, e, n, g = pop(heap)
            except IndexError:
                break
            exps.append(e)
            gs.append(g)
            if g > best[n]:  # stale: the node was pushed with a lower g since
                ends.append(count)
                discarded.append(step)
                continue
            if not on_push and goal[n]:
                ends.append(count)
                _flush(buffers)
                rec.goal_gen, rec.done = e, True
                return
            for j in (range(starts[n], starts[n + 1]) if by_name is None else by_name(n)):
                m = nodes[j]
                if not open_[m]:
                    continue
                ng = g + costs[j]
                if ng + CHEAPER_BY >= best[m]:
                    continue
                best[m] = ng
                if h is None:
                    push(heap, (ng, count, m, ng))
                else:
                    push(heap, (ng + h(m) if use_g else h(m), count, m, ng))
                new.append(m)
                count += 1
                if on_push and goal[m]:
                    ends.append(count)
                    _flush(buffers)
                    rec.goal_gen, rec.done = count - 1, True
                    return
            ends.append(count)
        _flush(buffers)
        if heap:
            yield rec.steps
    rec.done = True


__all__ = ["graph_best_first"]

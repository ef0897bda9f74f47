"""The best-first family: the recorded loops of uniform-cost search, greedy best-first search
and A*, a priority queue's.

One loop serves the three: they differ only in the priority an entry is pushed with (``g``,
``h`` or ``g + h``, weighted A*'s ``g + W·h``;
:func:`~tui_search.engine.search.heuristics.priority_of`).  The definition is
the reference loop (:class:`tui_search.engine.search.reference.ReferenceSearch`), and a hypothesis
test in ``tests/engine`` holds these equal to it, array for array.

The queue is a binary heap of ``(priority, event, cell, g)``: the event number breaks ties, so
equal priorities come out in the order they were pushed (as in the frontier model the app
shows, :class:`~tui_search.engine.run.frontier.PriorityFrontier`).  A cell is pushed again when
reached with a lower g than its best so far (by more than
:data:`~tui_search.engine.search.heuristics.CHEAPER_BY`: float noise), and an entry taken off with a
g above its cell's best is stale: a discarded step ("lazy deletion": nothing is removed from the
heap early).

Besides the arrays every loop records, these record ``step_g``: the g of the entry each step
took off.  An event's g is its generating step's plus its move's cost (its length, 1 or
sqrt(2) from :func:`_costed_moves`, times the cost of the cell it enters on a map with terrain,
``problem.terrain``): the very float sum ``g + cost`` the loop pushed, so nothing is stored per
event but its cell (a search that pushes five entries an expansion, as A* on an open map, keeps
36 bytes an expansion where a g an event made it 68).  From it the app shows g, h and f and
orders its frontier (:meth:`~tui_search.engine.run.queries.EventTree.gen_g`).
"""

from __future__ import annotations

import heapq
from array import array
from collections.abc import Iterator
from struct import pack

from tui_search.engine.maps.grid import DELTAS, SQRT2
from tui_search.engine.search import heuristics
from tui_search.engine.search.heuristics import CHEAPER_BY, Heuristic, heuristic_for
from tui_search.engine.search.loops.tree import Path
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import CHUNK, Record

INF = float("inf")

# What made the graph-search loop cheaper, counted in instructions against the bare heapq
# search (benchmarks/README.md, "informed"): closing expanded cells under a consistent
# heuristic, so most neighbours fail a byte test before any float is made; the corner test
# before the float test; the record's lists appended as methods and the step numbers taken
# from the chunk's ``range``.  Tried and dropped: ``(priority, event, cell)`` entries with
# each cell's latest event for the stale test (no fewer instructions: the test and the g then
# cost a lookup each).


def _costed_moves(problem: Problem) -> tuple[tuple[int, float, int, int], ...]:
    """The order's moves as ``(offset, cost, side_a, side_b)``: the cost 1 straight and
    sqrt(2) diagonally; for a diagonal under a corner rule the offsets of its two side cells
    (0 otherwise).  The loops test the corner rule themselves, on the few cells they expand,
    rather than ask for the problem's corner masks (a pass over the whole map)."""
    rule = problem.semantics.corners
    out = []
    for name, off in zip(problem.semantics.order, problem.offsets, strict=True):
        dx, dy = DELTAS[name]
        diagonal = bool(dx and dy)
        sides = (dx, dy * problem.stride) if diagonal and rule != "always" else (0, 0)
        out.append((off, SQRT2 if diagonal else 1.0, *sides))
    return tuple(out)


def move_costs(problem: Problem) -> dict[int, float]:
    """Each move's cost by its offset, the same floats the loops add (:func:`_costed_moves`):
    an event's g is its generating step's ``step_g`` plus the cost of the offset from the
    expanded cell to its own."""
    return {off: cost for off, cost, _, _ in _costed_moves(problem)}


def _blocked_sides_refused(problem: Problem) -> int:
    """How many blocked side cells refuse a diagonal: 1 under ``never`` (either), 2 under
    ``one`` (both); the loops test ``walls[n + a] + walls[n + b] >= this``."""
    return 1 if problem.semantics.corners == "never" else 2


def _start_heap(problem: Problem, rec: Record, best: array[float], goal_on_push: int,
                heuristic: Heuristic, priority: str) -> list[tuple[float, int, int, float]]:
    """Record the start's event and make the heap of its entry: empty when the start is the
    goal tested on push (the run is then done)."""
    start, stride = problem.start, problem.stride
    rec.gen_node.append(start)
    best[start] = 0.0
    if start == goal_on_push:
        rec.goal_gen, rec.done = 0, True
        return []
    if "h" in priority:
        sy, sx = divmod(start, stride)
        gy, gx = divmod(problem.goal, stride)
        h0 = heuristic(abs(sx - gx), abs(sy - gy))
        f0 = 0.0 + h0 if "g" in priority else h0
    else:
        f0 = 0.0
    return [(f0, 0, start, 0.0)]


def _flush(buffers: tuple[tuple[array[int] | array[float], list[int] | list[float], str], ...]
           ) -> None:
    """Append each list to its record array (``(array, list, typecode)``) and empty it."""
    for arr, buf, code in buffers:
        if buf:
            arr.frombytes(pack(f"{len(buf)}{code}", *buf))
            buf.clear()


def best_first(problem: Problem, rec: Record, chunk: int = CHUNK, priority: str = "g+h"
               ) -> Iterator[int]:
    """Graph search in order of ``priority`` (the algorithm's: "g", "h" or "g+h")."""
    moves = [(off, cost, cost + CHEAPER_BY, a, b) for off, cost, a, b in _costed_moves(problem)]
    walls, stride = problem.walls, problem.stride
    refused = _blocked_sides_refused(problem)
    goal = problem.goal
    goal_on_push = goal if problem.goal_test == "generate" else -1
    goal_on_pop = -1 if problem.goal_test == "generate" else goal
    use_h, use_g = "h" in priority, "g" in priority
    weight = problem.semantics.weight if use_g and use_h else 1.0  # weighted A*: g + W·h
    heuristic = heuristics.weighted(
        heuristic_for(problem.semantics.heuristic, problem.lowest), weight)
    terrain = problem.terrain  # None: every cell costs 1, a move its length
    octile, extra = heuristic is heuristics.octile, heuristics.DIAGONAL_EXTRA
    gy, gx = divmod(goal, stride)
    astar_octile = use_g and use_h and octile  # the default, with its heuristic inlined
    best = array("d", [INF]) * len(walls)  # the lowest g each cell was pushed with
    # Under a consistent heuristic (the priority g, or g + h with any heuristic but manhattan
    # beside diagonals, not weighted) no cell is reached cheaper once expanded, so an
    # expanded cell is closed and tested like a wall, before the float test it would fail
    # anyway.
    closed = bytearray(walls)
    close = 1 if use_g and (not use_h or heuristics.consistent_order(
        problem.semantics.heuristic, problem.semantics.order, weight)) else 0
    rec.step_exp = step_exp = array("i", [-1])
    rec.step_g = step_g = array("d", [0.0])  # index 0: before any step
    heap = _start_heap(problem, rec, best, goal_on_push, heuristic, priority)  # []: found
    pop, push = heapq.heappop, heapq.heappush
    nodes: list[int] = []
    gs: list[float] = []  # each step's g
    ends: list[int] = []
    exps: list[int] = []
    discarded: list[int] = []
    buffers = ((rec.gen_node, nodes, "i"), (step_g, gs, "d"), (rec.step_end, ends, "i"),
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
            if g > best[n]:  # stale: the cell was pushed with a lower g since
                ends.append(count)
                discarded.append(step)
                continue
            if n == goal_on_pop:
                ends.append(count)
                _flush(buffers)
                rec.goal_gen, rec.done = e, True
                return
            closed[n] = close
            for off, cost, margin, side_a, side_b in moves:
                m = n + off
                # cheapest tests first: most neighbours are walls or expanded already, and
                # the corner rule refuses most diagonals of a maze
                if closed[m] or side_a and walls[n + side_a] + walls[n + side_b] >= refused:
                    continue
                if terrain is None:
                    if g + margin >= best[m]:
                        continue
                    ng = g + cost
                else:
                    ng = g + cost * terrain[m]
                    if ng + CHEAPER_BY >= best[m]:
                        continue
                best[m] = ng
                if astar_octile:  # inlined: the same float as ng + heuristics.octile(dx, dy)
                    y, x = divmod(m, stride)
                    dx, dy = abs(x - gx), abs(y - gy)
                    push(heap, (ng + (dx + extra * dy if dx >= dy else dy + extra * dx),
                                count, m, ng))
                elif use_h:
                    y, x = divmod(m, stride)
                    h = heuristic(abs(x - gx), abs(y - gy))
                    push(heap, (ng + h if use_g else h, count, m, ng))
                else:
                    push(heap, (ng, count, m, ng))
                nodes.append(m)
                count += 1
                if m == goal_on_push:
                    ends.append(count)
                    _flush(buffers)
                    rec.goal_gen, rec.done = count - 1, True
                    return
            ends.append(count)
        _flush(buffers)
        if heap:
            yield rec.steps
    rec.done = True


def best_first_tree(problem: Problem, rec: Record, chunk: int = CHUNK, priority: str = "g+h"
                    ) -> Iterator[int]:
    """Tree search in order of ``priority``: no best g, a successor on the node's own path is
    skipped, nothing is stale.  Exponential by nature (a run stops at its step limit), so
    written plainly, as :func:`~tui_search.engine.search.loops.tree.tree` is."""
    moves, walls, stride = _costed_moves(problem), problem.walls, problem.stride
    refused = _blocked_sides_refused(problem)
    goal, start = problem.goal, problem.start
    test_on_push = problem.goal_test == "generate"
    use_h, use_g = "h" in priority, "g" in priority
    weight = problem.semantics.weight if use_g and use_h else 1.0  # weighted A*: g + W·h
    heuristic = heuristics.weighted(
        heuristic_for(problem.semantics.heuristic, problem.lowest), weight)
    terrain = problem.terrain
    gy, gx = divmod(goal, stride)

    def key(g: float, p: int) -> float:
        if not use_h:
            return g
        y, x = divmod(p, stride)
        h = heuristic(abs(x - gx), abs(y - gy))
        return g + h if use_g else h

    gen_node, step_end = rec.gen_node, rec.step_end
    rec.step_exp = step_exp = array("i", [-1])
    rec.step_g = step_g = array("d", [0.0])
    path = Path(len(walls), gen_node)  # the node's own path, for "on the path"
    path.add(-1)
    gen_node.append(start)
    if test_on_push and start == goal:
        rec.goal_gen, rec.done = 0, True
        return
    heap = [(key(0.0, start), 0, start, 0.0)]
    steps = 0
    while heap:
        _, e, n, g = heapq.heappop(heap)
        step_exp.append(e)
        step_g.append(g)
        steps += 1
        if not test_on_push and n == goal:
            step_end.append(len(gen_node))
            rec.goal_gen, rec.done = e, True
            return
        on_path = path.move_to(e)
        for off, cost, side_a, side_b in moves:
            m = n + off
            if walls[m] or side_a and walls[n + side_a] + walls[n + side_b] >= refused:
                continue
            if on_path[m]:
                continue
            ng = g + (cost if terrain is None else cost * terrain[m])
            heapq.heappush(heap, (key(ng, m), len(gen_node), m, ng))
            gen_node.append(m)
            path.add(e)
            if test_on_push and m == goal:
                step_end.append(len(gen_node))
                rec.goal_gen, rec.done = len(gen_node) - 1, True
                return
        step_end.append(len(gen_node))
        if steps % chunk == 0 and heap:
            yield steps
    rec.done = True


__all__ = ["best_first", "best_first_tree", "move_costs"]

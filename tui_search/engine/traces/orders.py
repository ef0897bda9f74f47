"""The move orders a trace allows: inferred from the order in which its steps added their
successors, or, for a trace of expansions only (no successors to infer them from), the orders
a search is tried with -- every order of the four straight moves, and the common orders of all
eight -- and what the trace leaves open about them.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace
from itertools import permutations

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import DEFAULT_ORDER, DELTAS, Grid
from tui_search.engine.search.state import State, as_cell
from tui_search.engine.traces.read import Trace, TraceStep

#: A graph's orders, both tried: a trace's successors in the file's order or by name.
GRAPH_ORDERS: list[tuple[str, ...]] = [("file",), ("name",)]

#: The most move orders tried when the trace leaves their order open.
MAX_ORDERS = 24

#: The orders of all eight moves an expansions-only trace is tried with: the app's, and
#: clockwise and counterclockwise from N and from E.
EIGHT_MOVE_ORDERS: tuple[tuple[str, ...], ...] = (
    DEFAULT_ORDER,
    ("N", "NE", "E", "SE", "S", "SW", "W", "NW"),
    ("N", "E", "S", "W", "NE", "SE", "SW", "NW"),
    ("E", "SE", "S", "SW", "W", "NW", "N", "NE"),
    ("N", "S", "E", "W", "NE", "NW", "SE", "SW"),
)


def expansion_orders(trace: Trace) -> list[tuple[str, ...]]:
    """The orders an expansions-only trace is tried with: every order of N, E, S, W (the
    4-connected grid courses use; CS188's N, S, E, W among them), then the eight-move ones --
    unless every cell it expands but the first is a straight move from one it expanded before
    (then a search with diagonal moves would have expanded one a diagonal away, all but
    surely: the four-move orders alone)."""
    if on_graph(trace):
        return list(GRAPH_ORDERS)
    fours = [tuple(p) for p in permutations(("N", "S", "E", "W"))]
    seen: set[State] = set()
    for step in trace.steps:
        x, y = as_cell(step.node)
        if seen and not seen & {(x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1), (x, y)}:
            return fours + list(EIGHT_MOVE_ORDERS)
        seen.add(step.node)
    return fours


def on_graph(trace: Trace) -> bool:
    """Is it a graph's trace (its nodes named, not cells)?"""
    return bool(trace.steps) and isinstance(trace.steps[0].node, str)


def _move(node: State, cell: State) -> str | None:
    node, cell = as_cell(node), as_cell(cell)
    delta = (cell[0] - node[0], cell[1] - node[1])
    return next((d for d, v in DELTAS.items() if v == delta), None)


def inferred_orders(trace: Trace, goal: State | None = None, grid: Grid | None = None
                    ) -> list[tuple[str, ...]]:
    """The move orders consistent with the order in which each step added its successors:
    the moves the trace used, ordered every way the trace allows (at most
    :data:`MAX_ORDERS`; the order first seen first).  When the trace contradicts itself (E
    before N in one step, N before E in another), the order first seen alone.

    A step that stops at the ``goal`` (its last successor) says nothing of the moves after
    the goal's, so the goal's move is put before every move that step did not add, wherever
    no other step says otherwise: the search then stops there too.  A trace that adds nothing
    at all: the moves that lead nowhere from any cell it expands (on ``grid``).  A graph's
    trace may follow the file's order or the names': both."""
    if on_graph(trace):
        return list(GRAPH_ORDERS)
    used: list[str] = []
    after: dict[str, set[str]] = {}
    goal_steps: list[list[str]] = []
    for step in trace.steps:
        moves = [m for m in (_move(step.node, c) for c in step.successors) if m is not None]
        for m in moves:
            if m not in used:
                used.append(m)
                after[m] = set()
        for i, a in enumerate(moves):
            after[a].update(b for b in moves[i + 1:] if b != a)
        if moves and step.successors[-1] == goal:
            goal_steps.append(moves)
    for moves in goal_steps:
        for m in used:
            if m not in moves and not _reaches(after, m, moves[-1]):
                after[moves[-1]].add(m)
    if not used:
        return [_never_moves(trace, grid)]
    orders = list(_linear(used, after, ()))
    return orders or [tuple(used)]


def flipped_order(trace: Trace, goal: State | None = None) -> tuple[str, ...] | None:
    """The order a grid's trace follows once its steps on the cells whose x + y is even are
    read reversed (a grid that reverses its moves on every other cell), where its steps read
    so agree on one order and read as they are do not; else None."""
    if on_graph(trace) or agrees(trace, inferred_orders(trace, goal)[0]):
        return None
    flipped = replace(trace, steps=tuple(
        t._replace(successors=t.successors[::-1]) if not sum(as_cell(t.node)) % 2 else t
        for t in trace.steps))
    order = inferred_orders(flipped, goal)[0]
    return order if agrees(flipped, order) else None


def call_first(order: tuple[str, ...], node: State, first: State, instead: State
               ) -> tuple[str, ...] | None:
    """``order`` with the move from ``node`` to ``first`` put just before the move to
    ``instead`` (a recursion's calls: the trace called ``first`` where the search called
    ``instead``, so its move comes earlier); None where either is no move of the order."""
    move, before = _move(node, first), _move(node, instead)
    if move not in order or before not in order or move == before:
        return None
    rest = [m for m in order if m != move]
    at = rest.index(str(before))
    return (*rest[:at], str(move), *rest[at:])


def agrees(trace: Trace, order: tuple[str, ...]) -> bool:
    """Does every step of ``trace`` add its successors in ``order`` (their moves in it, in
    its order)?"""
    rank = {m: i for i, m in enumerate(order)}
    for step in trace.steps:
        places = [rank.get(_move(step.node, c) or "", -1) for c in step.successors]
        if any(i < 0 for i in places) or places != sorted(places):
            return False
    return True


def _never_moves(trace: Trace, grid: Grid | None) -> tuple[str, ...]:
    """The moves blocked (an obstacle, off the map) from every cell ``trace`` expands: what a
    search that added nothing could have tried (N,W,S,E when none is, or no map is given)."""
    if grid is None:
        return ("N", "W", "S", "E")
    nodes = {as_cell(step.node) for step in trace.steps}
    moves = tuple(d for d, (dx, dy) in DELTAS.items()
                  if not any(grid.is_free((x + dx, y + dy)) for x, y in nodes))
    return moves or ("N", "W", "S", "E")


def _reaches(after: dict[str, set[str]], a: str, b: str) -> bool:
    """Must ``a`` come before ``b`` (a chain of ``after`` from one to the other)?"""
    todo, seen = [a], {a}
    while todo:
        m = todo.pop()
        if m == b:
            return True
        todo += [n for n in after[m] if n not in seen]
        seen.update(after[m])
    return False


def _linear(used: list[str], after: dict[str, set[str]],
            done: tuple[str, ...]) -> Iterator[tuple[str, ...]]:
    """Every order of ``used`` that keeps each ``a`` before everything in ``after[a]`` (the
    first :data:`MAX_ORDERS` of them)."""
    if len(done) == len(used):
        yield done
        return
    count = 0
    for m in used:
        if m in done or any(m in after[o] for o in used if o not in done and o != m):
            continue
        for order in _linear(used, after, (*done, m)):
            yield order
            count += 1
            if count >= MAX_ORDERS:
                return


def order_notes(orders: list[tuple[str, ...]]) -> list[str]:
    """What the inferred order leaves open: moves the trace never made, and other orders the
    trace allows as well."""
    if orders[0] in GRAPH_ORDERS:
        return []
    used = set(orders[0])
    straight = ("N", "E", "S", "W")
    moves = straight if used <= set(straight) else tuple(DELTAS)
    notes = []
    never = [m for m in moves if m not in used]
    if never:
        notes.append(f"the trace never moves {', '.join(never)}: where in the order, or "
                     "whether at all, cannot be told")
    if len(orders) > 1:
        more = " or more" if len(orders) >= MAX_ORDERS else ""
        others = " or ".join(",".join(o) for o in orders[1:4])
        notes.append(f"{len(orders)}{more} orders of its moves fit the order it added them "
                     f"in: {','.join(orders[0])} or {others}"
                     + (" or ..." if len(orders) > 4 else ""))
    return notes


def bidirectional_orders(trace: Trace, board: Grid | Graph) -> list[tuple[str, ...]]:
    """The move orders the trace's steps allow (a graph's: the file's and the names'), read
    from the steps whose search the two trees tell apart (a cell only the forward tree
    holds, or only the backward one), a backward step's successors mirrored through its
    node; a step that stops at the cell it last added says nothing of the moves after it.
    The app's order (all of it, then of the moves the trace made) first where the steps allow
    it."""
    if on_graph(trace) or not isinstance(board, Grid):
        return inferred_orders(trace)
    forward: set[State] = {board.start} if board.start is not None else set()
    backward: set[State] = {board.goal} if board.goal is not None else set()
    steps: list[TraceStep] = []
    for t in trace.steps:
        ahead, behind = t.node in forward, t.node in backward
        if ahead and not behind:
            steps.append(t)
        elif behind and not ahead:
            x, y = as_cell(t.node)
            steps.append(t._replace(successors=tuple(
                (2 * x - px, 2 * y - py) for px, py in map(as_cell, t.successors))))
        if ahead or not behind:
            forward.update(t.successors)
        if behind or not ahead:
            backward.update(t.successors)
    view = replace(trace, steps=tuple(steps))
    last = steps[-1] if steps and steps[-1].line == trace.steps[-1].line else None
    met = last.successors[-1] if last is not None and last.successors else None
    orders = inferred_orders(view, met, board)
    default = tuple(m for m in DEFAULT_ORDER if m in orders[0])
    if agrees(view, default):
        orders = [default, *(o for o in orders if o != default)]
    # the app's whole order too: a step the trees do not tell apart (the goal taken off
    # after the forward search reached it) may use moves no step told apart shows
    full = tuple(DEFAULT_ORDER)
    if full not in orders and agrees(view, full):
        orders = [full, *orders]
    return orders


__all__ = ["MAX_ORDERS", "agrees", "bidirectional_orders", "call_first", "expansion_orders",
           "flipped_order", "inferred_orders", "order_notes"]

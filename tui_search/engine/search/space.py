"""What a search runs on: a *space* -- a start, a goal test, each state's successors in order
with what reaching them costs, and an estimate of the cost to the goal.  The same reference
loop (:mod:`tui_search.engine.search.reference`) searches a grid's cells (:class:`GridSpace`)
and a graph's nodes (:class:`GraphSpace`), as aima-python's ``best_first_graph_search`` takes
any ``Problem``: a graph is another space, not another search.

A grid's state is its cell ``(x, y)`` and a move's name its direction (``NE``); a graph's
state is its node's name, and a move's name the node it reaches.  A move costs its length
times the cost of the cell it enters on a grid, its road's cost on a graph -- to the searches
ordered by cost; BFS, DFS and iterative deepening count moves, and their g stays 0.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable
from math import hypot
from typing import Protocol, cast

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import DELTAS, Cell, Grid, move_cost
from tui_search.engine.search.choices import GRAPH_HEURISTICS, GRAPH_ORDERS, TABLE, Semantics
from tui_search.engine.search.heuristics import HEURISTICS, heuristic_for, priority_of
from tui_search.engine.search.state import State

#: The priority of an entry with cost ``g`` at a state (g, h, g + h or weighted A*'s g + W·h).
Priority = Callable[[float, State], float]


class Space(Protocol):
    """What the reference loop asks of the world it searches."""

    @property
    def start(self) -> State: ...

    def is_goal(self, state: State) -> bool: ...

    def successors(self, state: State) -> list[tuple[str, State, float]]:
        """The moves from ``state``, in order: each one's name, the state it reaches and
        what it costs (0.0 where the search counts moves, not costs)."""
        ...

    def estimate(self) -> Callable[[State], float]:
        """The heuristic in force: a state's estimated cost to the goal."""
        ...

    def priority(self, kind: str) -> Priority:
        """The priority ``kind`` (``g``, ``h`` or ``f``) of an entry."""
        ...

    def path_cost(self, path: list[State] | None) -> float | None: ...


class GridSpace:
    """A grid's cells under the choices' moves, their order and the corner rule."""

    def __init__(self, grid: Grid, semantics: Semantics, weighted: bool) -> None:
        if grid.start is None or grid.goal is None:
            raise ValueError("the map needs a start and a goal")
        if semantics.order[0] in GRAPH_ORDERS:
            raise ValueError(f"the order {semantics.order[0]!r} is a graph's: a grid's moves "
                             "are directions")
        if semantics.heuristic == TABLE:
            raise ValueError("a table of estimates is a graph's: a grid's heuristics are "
                             + ", ".join(HEURISTICS))
        self.grid, self.semantics = grid, semantics
        self._start: Cell = grid.start
        self.goal: Cell = grid.goal
        # Per cell, a bit per move of the order that is legal from it (-1: not worked out
        # yet): the moves never change during a search, and two bytes a cell keep it small.
        self._legal_bits = array("h", [-1]) * (grid.width * grid.height)
        self._order = [(move, DELTAS[move], move_cost(move) if weighted else 0.0)
                       for move in semantics.order]
        self._heuristic = heuristic_for(semantics.heuristic, grid.lowest_cost())

    @property
    def start(self) -> State:
        return self._start

    def is_goal(self, state: State) -> bool:
        return state == self.goal

    def successors(self, state: State) -> list[tuple[str, State, float]]:
        """The legal moves from the cell (``Grid.neighbours``), in order (reversed where x + y
        is even, under ``flip_even``), with their cells and costs (the move's length times the
        cost of the cell it enters)."""
        x, y = cast(Cell, state)  # a grid's state is its cell
        i = y * self.grid.width + x
        bits = self._legal_bits[i]
        if bits < 0:
            legal = {move for move, _ in self.grid.neighbours(
                (x, y), self.semantics.order, self.semantics.corners)}
            bits = sum(1 << j for j, (move, _, _) in enumerate(self._order) if move in legal)
            self._legal_bits[i] = bits
        enter = self.grid.cost
        out: list[tuple[str, State, float]] = [
            (move, (x + dx, y + dy), length * enter((x + dx, y + dy)))
            for j, (move, (dx, dy), length) in enumerate(self._order) if bits >> j & 1]
        if self.semantics.flip_even and not (x + y) % 2:  # reversed on every other cell
            out.reverse()
        return out

    def estimate(self) -> Callable[[State], float]:
        heuristic, (gx, gy) = self._heuristic, self.goal

        def h(cell: State) -> float:
            x, y = cast(Cell, cell)
            return heuristic(abs(x - gx), abs(y - gy))

        return h

    def priority(self, kind: str) -> Priority:
        # The grid loops' own function, so that every loop computes the same floats.
        of = priority_of(kind, self._heuristic, self.goal, self.semantics.weight)
        return lambda g, cell: of(g, *cast(Cell, cell))

    def path_cost(self, path: list[State] | None) -> float | None:
        from tui_search.engine.search.outcome import cost_of

        return cost_of(self.grid, cast("list[Cell] | None", path))


class GraphSpace:
    """A graph's open nodes, each node's roads in the file's order or by name; the goal is
    any of the goals."""

    def __init__(self, graph: Graph, semantics: Semantics, weighted: bool) -> None:
        if graph.start is None or not graph.goals:
            raise ValueError("the graph needs a start and a goal")
        order = semantics.order[0] if len(semantics.order) == 1 else ""
        if order not in GRAPH_ORDERS:
            raise ValueError("a graph's order is file (the roads as listed) or name, not "
                             f"{','.join(semantics.order)}")
        self.graph, self.semantics = graph, semantics
        self._start: str = graph.start
        self._by_name = order == "name"
        self._weighted = weighted
        self._estimate: Callable[[State], float] | None = None

    @property
    def _h(self) -> Callable[[State], float]:
        """The heuristic, checked when a search first asks for it (a search that uses none
        runs under any)."""
        if self._estimate is None:
            graph, name = self.graph, self.semantics.heuristic
            if name not in GRAPH_HEURISTICS:
                raise ValueError(f"the heuristic {name!r} is a grid's: a graph's are "
                                 f"{', '.join(GRAPH_HEURISTICS)}")
            if name == TABLE and not graph.has_table:
                raise ValueError("the graph has no h table: use euclidean (with places) or "
                                 "zero")
            if name == "euclidean" and not graph.has_places:
                raise ValueError("the graph's nodes have no places: euclidean needs them")
            self._estimate = graph_estimate(graph, name)
        return self._estimate

    def estimate_by_number(self) -> Callable[[int], float]:
        """The heuristic (checked as :meth:`estimate`'s) of a node given by its number."""
        self._h  # noqa: B018 -- checks the heuristic applies
        return estimate_by_number(self.graph, self.semantics.heuristic)

    @property
    def start(self) -> State:
        return self._start

    @property
    def by_name(self) -> bool:
        """Are a node's successors ordered by their names (else as the file lists them)?"""
        return self._by_name

    def is_goal(self, state: State) -> bool:
        return state in self.graph.goals

    def successors(self, state: State) -> list[tuple[str, State, float]]:
        weighted = self._weighted
        return [(name, name, cost if weighted else 0.0)
                for name, cost, _ in self.graph.successors(str(state), self._by_name)]

    def estimate(self) -> Callable[[State], float]:
        return self._h

    def priority(self, kind: str) -> Priority:
        if kind == "g":
            return lambda g, node: g
        h = self._h
        if kind == "h":
            return lambda g, node: h(node)
        weight = self.semantics.weight
        if weight != 1.0:  # weighted A*
            return lambda g, node: g + weight * h(node)
        return lambda g, node: g + h(node)

    def path_cost(self, path: list[State] | None) -> float | None:
        return None if path is None else self.graph.path_cost([str(n) for n in path])


def graph_estimate(graph: Graph, name: str) -> Callable[[State], float]:
    """A node's estimated cost to the nearest goal: the file's table; the straight line to
    the nearest goal's place, scaled by the least cost a unit of road's length (so that no
    road costs less than its estimate says: the estimate stays admissible); or 0."""
    index = graph.index
    of = estimate_by_number(graph, name)
    return lambda node: of(index[str(node)])


def estimate_by_number(graph: Graph, name: str) -> Callable[[int], float]:
    """:func:`graph_estimate` of a node given by its number (the very same floats)."""
    if name == TABLE:
        return graph.data.h.__getitem__
    if name == "zero":
        return lambda i: 0.0
    scale = euclidean_scale(graph)
    goals = [graph.place(graph.index[g]) for g in graph.goals]

    def straight(i: int) -> float:
        x, y = graph.place(i)
        return scale * min(hypot(x - gx, y - gy) for gx, gy in goals)

    return straight


def euclidean_scale(graph: Graph) -> float:
    """The largest factor by which the straight line never exceeds a road's cost: the least
    of each road's cost over its length (places in any unit: a path costs at least this
    times its length, which is at least the straight line's).  1 when no road has a length."""
    d = graph.data
    ratios = [cost / length for a, b, cost in zip(d.road_a, d.road_b, d.road_cost, strict=True)
              if (length := hypot(d.x[a] - d.x[b], d.y[a] - d.y[b])) > 0]
    return min(ratios, default=1.0)


def space_of(board: Grid | Graph, semantics: Semantics, weighted: bool) -> Space:
    """The space of a grid or a graph (``weighted``: the search orders by cost)."""
    if isinstance(board, Graph):
        return GraphSpace(board, semantics, weighted)
    return GridSpace(board, semantics, weighted)


__all__ = ["GRAPH_HEURISTICS", "GraphSpace", "GridSpace", "Priority", "Space", "State",
           "estimate_by_number", "euclidean_scale", "graph_estimate", "space_of"]

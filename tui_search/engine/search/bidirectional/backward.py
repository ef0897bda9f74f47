"""The backward search's space: the same world with its moves reversed, searched from the goal
to the start (a bidirectional search's second half,
:mod:`~tui_search.engine.search.bidirectional.loop`).

A state's successors backward are its *predecessors* forward: the states from which one move
reaches it, each with what that move costs forward (on a grid, its length times the cost of the
cell it enters -- the state searched from; on a graph, the road's cost, a one-way road taken
against its way).  A move keeps its forward name (a graph's: the node it reaches forward):
the backward node reached from ``c`` by ``NE`` is the cell from which ``NE`` reaches ``c``,
so the path's moves read the same from either end.  The estimate is the heuristic's to the start.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable
from math import hypot
from typing import cast

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import DELTAS, Cell, Grid, move_cost
from tui_search.engine.search.choices import TABLE, Semantics, corner_allowed
from tui_search.engine.search.heuristics import heuristic_for, priority_of
from tui_search.engine.search.space import (
    GraphSpace,
    GridSpace,
    Priority,
    Space,
    euclidean_scale,
    space_of,
)
from tui_search.engine.search.state import State


class BackwardGridSpace:
    """A grid searched from its goal to its start: a cell's predecessors, in the order of the
    moves that reach it."""

    def __init__(self, forward: GridSpace, weighted: bool) -> None:
        self.forward = forward
        grid: Grid = forward.grid
        self.grid = grid
        self._start: Cell = forward.goal
        self.goal: Cell = cast(Cell, forward.start)
        self._heuristic = heuristic_for(forward.semantics.heuristic, grid.lowest_cost())
        # As the forward space's: per cell, a bit per move of the order that reaches it
        # legally (-1: not worked out yet).
        self._legal_bits = array("h", [-1]) * (grid.width * grid.height)
        self._order = [(move, DELTAS[move], move_cost(move) if weighted else 0.0)
                       for move in forward.semantics.order]

    @property
    def start(self) -> State:
        return self._start

    def is_goal(self, state: State) -> bool:
        return state == self.goal

    def successors(self, state: State) -> list[tuple[str, State, float]]:
        """The cells one move of the order reaches ``state`` from (free, and the corner
        rule's side cells -- the same two either way -- as forward), each with the forward
        move's name and cost (its length times the cost of ``state``, the cell it enters)."""
        x, y = cast(Cell, state)
        grid = self.grid
        i = y * grid.width + x
        bits = self._legal_bits[i]
        if bits < 0:
            corners, free = self.forward.semantics.corners, grid.is_free
            bits = 0
            for j, (_, (dx, dy), _) in enumerate(self._order):
                px, py = x - dx, y - dy
                if free((px, py)) and (not (dx and dy) or corner_allowed(
                        corners, free((px + dx, py)), free((px, py + dy)))):
                    bits |= 1 << j
            self._legal_bits[i] = bits
        enter = grid.cost(cast(Cell, state))
        return [(move, (x - dx, y - dy), length * enter)
                for j, (move, (dx, dy), length) in enumerate(self._order) if bits >> j & 1]

    def estimate(self) -> Callable[[State], float]:
        heuristic, (sx, sy) = self._heuristic, self.goal

        def h(cell: State) -> float:
            x, y = cast(Cell, cell)
            return heuristic(abs(x - sx), abs(y - sy))

        return h

    def priority(self, kind: str) -> Priority:
        of = priority_of(kind, self._heuristic, self.goal)
        return lambda g, cell: of(g, *cast(Cell, cell))

    def path_cost(self, path: list[State] | None) -> float | None:
        return self.forward.path_cost(path)


class BackwardGraphSpace:
    """A graph searched from its goals to its start along its roads taken backwards; each
    node's roads in, as the file lists the nodes they come from (or by their names)."""

    def __init__(self, forward: GraphSpace, weighted: bool) -> None:
        self.forward, self.weighted = forward, weighted
        graph: Graph = forward.graph
        self.graph = graph
        self.goal: str = cast(str, forward.start)
        self.roots: list[State] = list(graph.goals)
        into: dict[str, list[tuple[str, float]]] = {}
        for name in graph.names:
            if name in graph.closed:
                continue
            for after, cost, _ in graph.successors(name):
                into.setdefault(after, []).append((name, cost))
        if forward.by_name:
            for roads in into.values():
                roads.sort(key=lambda road: road[0])
        self._into: dict[str, list[tuple[str, float]]] = into
        self._estimate: Callable[[State], float] | None = None

    @property
    def start(self) -> State:
        return self.roots[0]

    def is_goal(self, state: State) -> bool:
        return state == self.goal

    def successors(self, state: State) -> list[tuple[str, State, float]]:
        weighted, name = self.weighted, str(state)  # a move is named by the node it reaches
        return [(name, node, cost if weighted else 0.0)
                for node, cost in self._into.get(name, ())]

    def estimate(self) -> Callable[[State], float]:
        if self._estimate is None:
            graph, name = self.graph, self.forward.semantics.heuristic
            self.forward.estimate()  # the forward's checks: the heuristic applies
            if name == TABLE:
                raise ValueError("the graph's h table estimates the cost to the goal; the "
                                 "backward search needs one to the start: use euclidean "
                                 "(with places) or zero")
            if name == "zero":
                self._estimate = lambda node: 0.0
            else:
                scale, index = euclidean_scale(graph), graph.index
                sx, sy = graph.place(index[self.goal])

                def straight(node: State) -> float:
                    x, y = graph.place(index[str(node)])
                    return scale * hypot(x - sx, y - sy)

                self._estimate = straight
        return self._estimate

    def priority(self, kind: str) -> Priority:
        if kind == "g":
            return lambda g, node: g
        h = self.estimate()
        if kind == "h":
            return lambda g, node: h(node)
        return lambda g, node: g + h(node)

    def path_cost(self, path: list[State] | None) -> float | None:
        return self.forward.path_cost(path)


def both_ways(board: Grid | Graph, semantics: Semantics, weighted: bool
              ) -> tuple[Space, Space, list[State]]:
    """The forward space of ``board``, its backward one, and the backward search's roots
    (the goal; a graph's goals)."""
    forward = space_of(board, semantics, weighted)
    if isinstance(forward, GraphSpace):
        graph_back = BackwardGraphSpace(forward, weighted)
        return forward, graph_back, graph_back.roots
    assert isinstance(forward, GridSpace)
    grid_back = BackwardGridSpace(forward, weighted)
    return forward, grid_back, [grid_back.start]


__all__ = ["BackwardGraphSpace", "BackwardGridSpace", "both_ways"]

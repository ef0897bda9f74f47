"""A graph prepared for a recorded run: its nodes numbered, the start and the goals by number,
and what a run's queries ask of a move -- its name (the node it reaches), its cost (the
road's) and a node's estimate -- the graph's answers where a grid's
:class:`~tui_search.engine.search.problem.Problem` does arithmetic on padded cells.

A graph is searched by a plain Python loop, no compiled core needed: the priority queue's
under the plain choices by :mod:`~tui_search.engine.search.loops.graph_best_first` (node
numbers and flat arrays), every other by the loop that records the reference
(:mod:`~tui_search.engine.search.loops.published`).
"""

from __future__ import annotations

from collections.abc import Callable

from tui_search.engine.maps.graph import Graph
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.space import GraphSpace
from tui_search.engine.search.state import State


class GraphProblem:
    """``graph`` under ``semantics``: nodes are numbered as the graph numbers them."""

    def __init__(self, graph: Graph, semantics: Semantics, goal_test: str | None = None,
                 weighted: bool = True) -> None:
        self.space = GraphSpace(graph, semantics, weighted)  # checks start, goals, choices
        self.graph = graph
        self.board = graph
        self.semantics = semantics
        self.goal_test = goal_test or semantics.goal_test or "generate"
        self.max_steps: int | None = None
        assert graph.start is not None  # the space checked it
        self.start = graph.index[graph.start]
        self.goals = frozenset(graph.index[g] for g in graph.goals)
        self.goal = min(self.goals)
        self.size = len(graph)
        self.lowest = graph.lowest_cost()
        # The road between two nodes, by their numbers: one a pair and direction (the graph
        # file refuses a second), so a move's parent and child say which road it took.  Made
        # when a move's cost is first asked (a pass over every road): a headless run never
        # asks.
        self._roads: dict[tuple[int, int], float] | None = None

    def pad(self, state: State) -> int:
        return self.graph.index[str(state)]

    def unpad(self, i: int) -> State:
        return self.graph.names[i]

    def is_goal(self, i: int) -> bool:
        return i in self.goals

    def move_name(self, parent: int, child: int) -> str:
        """What a move is called: the node it reaches."""
        return self.graph.names[child]

    def step_cost(self, parent: int, child: int) -> float:
        """The road's cost from ``parent`` to ``child``."""
        if self._roads is None:
            starts, _, nodes = self.graph.data.rows()
            costs = self.graph.data.row_costs()
            self._roads = {(a, nodes[j]): costs[j] for a in range(self.size)
                           for j in range(starts[a], starts[a + 1])}
        return self._roads[parent, child]

    def estimate(self, i: int) -> float:
        return float(self.space.estimate()(self.graph.names[i]))

    def priority(self, kind: str) -> Callable[[float, int], float]:
        """The priority ``kind`` of an entry with cost ``g`` at node ``i``: the space's (the
        very floats the loop pushed with)."""
        of = self.space.priority(kind)
        names = self.graph.names
        return lambda g, i: of(g, names[i])

    def path_cost(self, path: list[State] | None) -> float | None:
        return self.space.path_cost(path)


__all__ = ["GraphProblem"]

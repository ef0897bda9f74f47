"""What the app searches on, a *board*: a grid or a graph (no Textual).  The rules a graph's
searches run under (its orders and estimates are not a grid's), and the endpoints a board
has or lacks."""

from __future__ import annotations

from typing import TYPE_CHECKING, TypeGuard

from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import GRAPH_ORDERS, TABLE, Semantics
from tui_search.engine.search.state import State

if TYPE_CHECKING:  # a grid's app never imports the graph's modules (the first frame)
    from tui_search.engine.maps.graph import Graph

def is_graph(board: Grid | Graph) -> TypeGuard[Graph]:
    """Is the board a graph (told apart without importing the graph's module)?"""
    return not isinstance(board, Grid)
#: A graph's estimates (:data:`~tui_search.engine.search.space.GRAPH_HEURISTICS`, here
#: without importing the searches' module on the first frame).
GRAPH_HEURISTICS: tuple[str, ...] = (TABLE, "euclidean", "zero")


def graph_heuristics(graph: Graph) -> list[str]:
    """The estimates ``graph`` offers: its table, the straight line (with places), zero."""
    return [h for h in GRAPH_HEURISTICS
            if (h != TABLE or graph.has_table) and (h != "euclidean" or graph.has_places)]


def semantics_for(board: Grid | Graph, semantics: Semantics) -> Semantics:
    """``semantics`` as ``board`` can take them: on a graph, a grid's moves become the file's
    order and a grid's heuristic the graph's first (its table, else the straight line, else
    zero); on a grid, a graph's order and table the grid's defaults."""
    from tui_search.engine.search.choices import DEFAULT_SEMANTICS

    order, heuristic = semantics.order, semantics.heuristic
    if isinstance(board, Grid):
        if order[0] in GRAPH_ORDERS:
            order = DEFAULT_SEMANTICS.order
        if heuristic in GRAPH_HEURISTICS and heuristic != "zero":
            heuristic = DEFAULT_SEMANTICS.heuristic
    else:
        if len(order) != 1 or order[0] not in GRAPH_ORDERS:
            order = GRAPH_ORDERS[:1]
        offered = graph_heuristics(board)
        if heuristic not in offered:
            heuristic = offered[0]
    if (order, heuristic) == (semantics.order, semantics.heuristic):
        return semantics
    return semantics.replace(order=order, heuristic=heuristic)


def has_endpoints(board: Grid | Graph) -> bool:
    """A start and a goal to search between."""
    if isinstance(board, Grid):
        return board.start is not None and board.goal is not None
    return board.start is not None and bool(board.goals)


def start_of(board: Grid | Graph) -> State:
    """Where the cursor starts: the start (else the first cell or node)."""
    if isinstance(board, Grid):
        return board.start or (0, 0)
    return board.start if board.start is not None else board.names[0]


def goal_of(board: Grid | Graph) -> State | None:
    """The goal (a graph's first)."""
    if isinstance(board, Grid):
        return board.goal
    return board.goals[0] if board.goals else None


def holds(board: Grid | Graph, state: State) -> bool:
    """Is ``state`` a cell of the grid, a node of the graph?"""
    if isinstance(board, Grid):
        return isinstance(state, tuple) and board.in_bounds(state)
    return isinstance(state, str) and state in board


__all__ = ["GRAPH_HEURISTICS", "is_graph", "goal_of", "graph_heuristics", "has_endpoints",
           "holds", "semantics_for", "start_of"]

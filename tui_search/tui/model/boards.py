"""What the app searches on, a *board*: a grid or a graph (no Textual).  The rules a graph's
searches run under (its orders and estimates are not a grid's), and the endpoints a board
has or lacks."""

from __future__ import annotations

from typing import TYPE_CHECKING, TypeGuard

from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import (
    GRAPH_HEURISTICS,
    GRAPH_ORDERS,
    Semantics,
    graph_heuristics,
)
from tui_search.engine.search.state import State

if TYPE_CHECKING:  # a grid's app never imports the graph's modules (the first frame)
    from tui_search.engine.maps.graph import Graph


#: The most cells the app opens a map of: a run keeps counters a cell (benchmarks/README.md,
#: "big_map"), so a bigger map would take over ten times its file; it is searched headless
#: instead.  Every MovingAI map fits.
APP_MAX_CELLS = 1 << 24


def too_big_for_the_app(grid: Grid) -> str:
    """Why the app does not open ``grid`` ("" when it does): more cells than
    :data:`APP_MAX_CELLS`."""
    cells = grid.width * grid.height
    if cells <= APP_MAX_CELLS:
        return ""
    return (f"{grid.width:,}x{grid.height:,} is {cells:,} cells: the app opens maps of at most "
            f"{APP_MAX_CELLS:,} (it keeps counters a cell); search it with --headless")


def is_graph(board: Grid | Graph) -> TypeGuard[Graph]:
    """Is the board a graph (told apart without importing the graph's module)?"""
    return not isinstance(board, Grid)


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


__all__ = ["APP_MAX_CELLS", "GRAPH_HEURISTICS", "goal_of", "graph_heuristics", "has_endpoints",
           "holds", "is_graph", "semantics_for", "start_of", "too_big_for_the_app"]

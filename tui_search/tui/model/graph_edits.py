"""The session's edits of a graph: its start, its goal and its closed nodes, and undo.

The graph's counterpart of :class:`~tui_search.tui.model.map_edits.MapEdits` (no Textual):
``s`` puts the start on a node, ``g`` makes a node the goal (the only one: a file's other
goals go), ``o`` closes a node or opens it again (a closed node is never reached, as an
obstacle is never entered).  Each edit is recorded in the same
:class:`~tui_search.tui.model.history.History` as a grid's, undone and redone the same way.
"""

from __future__ import annotations

from collections.abc import Callable

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Cell
from tui_search.engine.search.state import State
from tui_search.tui.model.history import History

#: What the graph's edits change: its start, its goals and its closed nodes.
Marks = tuple[str | None, tuple[str, ...], frozenset[str]]
#: What a graph has no use for (it has no cells): the brush's answer.
NO_TERRAIN = "A graph has no terrain: its roads' costs are in its file"


def marks_of(graph: Graph) -> Marks:
    return graph.start, graph.goals, graph.closed


class GraphEdit:
    """One edit of a graph: its marks before and after, and the node it was about."""

    # Not a dataclass (start-up time, as history.Edit).
    def __init__(self, before: Marks, after: Marks, node: str) -> None:
        self.before, self.after, self.node = before, after, node
        self.walls: list[tuple[Cell, bool, bool]] = []  # a graph's edit paints no cells
        self.costs: list[tuple[Cell, float, float]] = []

    def apply(self, board: object, undo: bool) -> State:
        graph = board
        assert isinstance(graph, Graph), "a graph's edit"
        graph.start, graph.goals, graph.closed = self.before if undo else self.after
        return self.node


class GraphEdits:
    """The edits of one graph at a node: None, or the one-line reason they are refused.
    ``on_edit`` is called after every edit and undo, with the node an undo or a redo puts the
    cursor on (None for an edit, made at the cursor)."""

    def __init__(self, graph: Graph, on_edit: Callable[[State | None], None]) -> None:
        self.board = graph
        self.history = History()
        self.brush: float | None = None  # a graph has no terrain brush
        self._on_edit = on_edit

    @property
    def graph(self) -> Graph:
        return self.board

    def _edit(self, node: str, after: Marks) -> None:
        graph = self.board
        before = marks_of(graph)
        graph.start, graph.goals, graph.closed = after
        self.history.add(GraphEdit(before, after, node))
        self._on_edit(None)

    def place(self, what: str, node: State) -> str | None:
        """The start or the goal (``what``) on ``node``: None, or why not."""
        graph, name = self.board, str(node)
        if name in graph.closed:
            return f"Cannot put the {what} on {name}: it is closed (o opens it)"
        if what == "start":
            if graph.start == name:
                return f"The start is already {name}"
            if name in graph.goals:
                return f"Cannot put the start on the goal {name}"
            self._edit(name, (name, graph.goals, graph.closed))
        else:
            if graph.goals == (name,):
                return f"The goal is already {name}"
            if name == graph.start:
                return f"Cannot put the goal on the start {name}"
            self._edit(name, (graph.start, (name,), graph.closed))
        return None

    def toggle_wall(self, node: State) -> str | None:
        """Close ``node`` (no search reaches it) or open it again: None, or why not."""
        graph, name = self.board, str(node)
        if name in graph.closed:
            self._edit(name, (graph.start, graph.goals, graph.closed - {name}))
            return None
        if name == graph.start or name in graph.goals:
            what = "start" if name == graph.start else "goal"
            return f"Cannot close the {what} {name}"
        self._edit(name, (graph.start, graph.goals, graph.closed | {name}))
        return None

    def paint(self, cell: State, wall: bool) -> bool:
        return False  # no strokes on a graph

    def cycle_brush(self) -> float | None:
        return None

    def paint_cost(self, cell: State) -> str | None:
        return NO_TERRAIN

    def stroke_cost(self, cell: State) -> bool:
        return False

    def undo(self, redo: bool = False) -> str | None:
        """Undo the last edit of the graph (``redo``: make the last one undone again), the
        cursor on its node: None, or why nothing changed."""
        history = self.history
        node = history.redo(self.board) if redo else history.undo(self.board)
        if node is None:
            return "Nothing to redo" if redo else "Nothing to undo"
        self._on_edit(node)
        return None


__all__ = ["NO_TERRAIN", "GraphEdit", "GraphEdits", "Marks", "marks_of"]

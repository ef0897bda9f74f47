"""A tiny app that shows one :class:`~tui_search.tui.widgets.graph_view.GraphView` (the app's
panes will hold one each): a graph, a fake search state (a dictionary of node states), in one
of the app's themes, with the messages the view posts kept for the tests to read."""

from __future__ import annotations

from textual.app import App, ComposeResult
from textual.message import Message

from tui_search.engine.maps.graph import Edge, Graph
from tui_search.engine.run.position import CellState
from tui_search.tui.app import textual_themes
from tui_search.tui.view.themes import map_defaults
from tui_search.tui.widgets.graph_view import GraphView


class GraphApp(App[None]):
    """``graph`` in a bordered view filling the screen; ``states``: node number -> state (the
    rest unseen)."""

    CSS = "GraphView { border: round $primary; height: 1fr; width: 1fr; }"

    def __init__(self, graph: Graph, states: dict[int, CellState] | None = None,
                 theme: str = "dark") -> None:
        super().__init__()
        self.graph = graph
        self.states: dict[int, CellState] = dict(states or {})
        self.heard: list[Message] = []
        for own in textual_themes():
            self.register_theme(own)
        self.theme = theme

    def get_css_variables(self) -> dict[str, str]:
        """The map's own variables, as the app adds them (tui_search/tui/app.py)."""
        variables = super().get_css_variables()
        for name, value in map_defaults(variables).items():
            variables.setdefault(name, value)
        return variables

    def state_of(self, node: int) -> CellState:
        return self.states.get(node, CellState.UNSEEN)

    def compose(self) -> ComposeResult:
        yield GraphView(self.graph, self.state_of)

    def on_mount(self) -> None:
        self.query_one(GraphView).focus()

    def on_graph_view_node_clicked(self, message: GraphView.NodeClicked) -> None:
        self.heard.append(message)

    def on_graph_view_cursor_moved(self, message: GraphView.CursorMoved) -> None:
        self.heard.append(message)


def grid_graph(side: int) -> Graph:
    """A ``side`` x ``side`` grid of nodes (``x3y7``), each joined to its right and lower
    neighbours at cost 1, with its places: 316 a side is the issue's 100,000 nodes."""
    names = [f"x{x}y{y}" for y in range(side) for x in range(side)]
    edges = []
    for y in range(side):
        for x in range(side):
            i = y * side + x
            if x + 1 < side:
                edges.append(Edge(i, i + 1, 1.0))
            if y + 1 < side:
                edges.append(Edge(i, i + side, 1.0))
    places = [(float(x), float(-y)) for y in range(side) for x in range(side)]
    return Graph.of(names, edges, places=places, start=names[0], goals=(names[-1],))


def screen_lines(view: GraphView) -> list[str]:
    """The text of every line the view draws now."""
    return [view.render_line(y).text for y in range(view.scrollable_content_region.height)]

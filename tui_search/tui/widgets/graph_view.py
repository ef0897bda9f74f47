"""A graph, drawn with Textual's line API: nodes as marks with their names, roads as braille
lines with their costs, in the search's colours (:mod:`~tui_search.tui.widgets.graph_lines`
draws a row; :mod:`~tui_search.tui.view.graph_layout` says what is where).

The view is given the graph and a *state source*, ``state_of(node) -> CellState`` (the run's,
in a pane); start, goals and closed nodes come from the graph.  It draws what it is told
(:meth:`GraphView.show_states` after a step, :meth:`GraphView.refresh_graph` after an edit,
:meth:`GraphView.set_graph` for another graph) and moves its own cursor (a node's number) with
the arrow keys (the nearest node that way), Tab and the mouse, saying so with
:class:`GraphView.CursorMoved`; a click also says :class:`GraphView.NodeClicked`, and the
screen decides what it means.  ``]`` and ``[`` zoom: level 0 is the whole graph in the view.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING

from textual import events
from textual.binding import Binding
from textual.geometry import Offset, Size
from textual.message import Message
from textual.reactive import var
from textual.scroll_view import ScrollView
from textual.strip import Strip

from tui_search.engine.maps.graph import Graph
from tui_search.engine.run.position import CellState
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State
from tui_search.tui.view.cell_codes import COMPONENTS, GOAL, START, WALL
from tui_search.tui.view.graph_layout.canvas import Canvas
from tui_search.tui.view.graph_layout.labels import shown, unique_lengths
from tui_search.tui.view.graph_layout.picking import node_at, tab_next, toward
from tui_search.tui.view.graph_layout.places import Placement
from tui_search.tui.view.graph_layout.raster import Tiles
from tui_search.tui.widgets.graph_lines import PARTS, GraphLooks, Shown, graph_line, line_strip
from tui_search.tui.widgets.line_panel import CachedStyles
from tui_search.tui.widgets.scrollbars import QuietScrollbars

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun

StateOf = Callable[[int], "CellState | int"]
PATH = int(CellState.PATH)


def unseen(node: int) -> CellState:
    """The state source of a graph no search has run on."""
    return CellState.UNSEEN


class GraphView(QuietScrollbars, CachedStyles, ScrollView, can_focus=True,
                inherit_bindings=False):
    """A graph and the search's state on it, with a cursor on one node."""

    class NodeClicked(Message):
        """The mouse went down on a node (button 1 left, 3 right)."""

        def __init__(self, node: int, button: int) -> None:
            super().__init__()
            self.node, self.button = node, button

    class CursorMoved(Message):
        """The cursor is on another node."""

        def __init__(self, node: int) -> None:
            super().__init__()
            self.node = node

    BINDINGS = [
        Binding("left", "toward('left')", "Left", show=False),
        Binding("right", "toward('right')", "Right", show=False),
        Binding("up", "toward('up')", "Up", show=False),
        Binding("down", "toward('down')", "Down", show=False),
        Binding("tab", "next_node(1)", "Next node", show=False),
        Binding("shift+tab", "next_node(-1)", "Previous node", show=False),
    ]

    COMPONENT_CLASSES = {f"graph-view--{name}" for name in COMPONENTS + PARTS}

    DEFAULT_CSS = """
    GraphView {
        background: $surface;
        color: $foreground;
        overflow: hidden hidden;
        /* The map's theme variables (tui_search/tui/view/themes.py), as the grid has them:
           a node is filled as a cell of its state is. */
        /* an unseen node a shade dimmer than the blank around it: not yet reached */
        & > .graph-view--free { color: $foreground 85%; }
        & > .graph-view--wall { color: $map-wall; text-style: bold; }
        & > .graph-view--start { background: $map-start; color: $map-start-text;
                                 text-style: bold; }
        & > .graph-view--goal { background: $map-goal; color: $map-goal-text; text-style: bold; }
        & > .graph-view--frontier { background: $map-frontier; color: $map-frontier-text; }
        & > .graph-view--expanded { background: $map-expanded; color: $map-expanded-text; }
        & > .graph-view--current { background: $map-current; color: $map-current-text;
                                   text-style: bold; }
        & > .graph-view--path { background: $map-path; color: $map-path-text; text-style: bold; }
        /* A bidirectional search's backward half, a cell both halves reached, the best
           meeting (tui_search/tui/view/two_way/cells.py). */
        & > .graph-view--back-frontier { background: $map-back-frontier;
                                        color: $map-back-frontier-text; }
        & > .graph-view--back-expanded { background: $map-back-expanded;
                                        color: $map-back-expanded-text; }
        & > .graph-view--back-current { background: $map-back-current;
                                       color: $map-back-current-text;
                                       text-style: bold; }
        & > .graph-view--both { background: $map-both; color: $map-both-text; }
        & > .graph-view--meeting { background: $map-meeting; color: $map-meeting-text;
                                   text-style: bold; }
        & > .graph-view--road { color: $foreground 55%; }
        & > .graph-view--road-path { color: $map-path; text-style: bold; }
        & > .graph-view--arrow { color: $foreground 80%; }
        & > .graph-view--cost { color: $foreground 70%; }
        & > .graph-view--cursor { color: $foreground; text-style: bold; }
    }
    """

    cursor: var[int] = var(0, init=False)

    def __init__(self, graph: Graph, state_of: StateOf = unseen, *, cursor: int | None = None,
                 id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.state_of: StateOf = state_of
        self.level = 0  # the zoom: 0, the whole graph in the view
        self.graph = graph
        self._start_from(graph)
        self._looks: GraphLooks | None = None
        self._box: tuple[int, int] | None = None
        self.canvas: Canvas | None = None
        self.tiles: Tiles | None = None
        start = graph.index.get(graph.start, 0) if graph.start is not None else 0
        self.set_reactive(GraphView.cursor, start if cursor is None else cursor)

    # -- what to show (pushed down by the screen) --------------------------------------------
    def _start_from(self, graph: Graph) -> None:
        """What a graph's drawing needs before it is fitted: its places and its names."""
        self.placement = Placement(graph)
        self.names = [shown(name) for name in graph.names]
        self.need = unique_lengths(self.names)
        self.longest = max(map(len, self.names))
        self.costs = any(cost != 1.0 for cost in graph.data.road_cost)
        self._marked_from(graph)

    def _marked_from(self, graph: Graph) -> None:
        index = graph.index
        self.start = index.get(graph.start, -1) if graph.start is not None else -1
        self.goals = frozenset(index[name] for name in graph.goals if name in index)
        self.closed = frozenset(index[name] for name in graph.closed if name in index)

    def set_graph(self, graph: Graph, state_of: StateOf = unseen) -> None:
        """Show another graph (the zoom back to the whole of it)."""
        self.graph, self.state_of, self.level = graph, state_of, 0
        self._start_from(graph)
        self.set_reactive(GraphView.cursor, max(0, self.start))
        self._refit()

    # -- the pane's calls, named as the grid's (tui/widgets/run_pane.py, tui/screens/) ----
    #: The node under the mouse: a graph's readout follows the cursor only.
    hover: None = None

    def show_run(self, run: Run | BiRun | None, changed: Iterable[State] | None = None
                 ) -> None:
        """Draw ``run`` at its position (None: no search); ``changed`` names the nodes that
        differ from what is shown (None: any may, and the start, goals and closed nodes)."""
        if run is None:
            state_of: StateOf = unseen
        elif not isinstance(run, Run):  # a bidirectional search's two halves, its meeting
            from tui_search.tui.view.two_way.cells import node_code

            two_way, names = run, self.graph.names
            state_of = lambda v: node_code(two_way, names[v])  # noqa: E731
        else:
            cell_state, names = run.now.cell_state, self.graph.names
            state_of = lambda v: cell_state(names[v])  # noqa: E731
        if changed is None:
            self._marked_from(self.graph)
            self.show_states(state_of)
        else:
            index = self.graph.index
            self.show_states(state_of, [index[str(n)] for n in changed if str(n) in index])

    def set_cursor(self, node: State) -> None:
        """The cursor on ``node`` (a name)."""
        v = self.graph.index.get(str(node))
        if v is not None and v != self.cursor:
            self.cursor = v

    def follow_node(self, node: State) -> None:
        v = self.graph.index.get(str(node))
        if v is not None:
            self.follow(v)

    @property
    def whole(self) -> bool:
        """The whole graph shows (zoomed in, a part of it)."""
        return self.level == 0

    @property
    def overview(self) -> bool:
        """The whole graph shows, zoomed out as far as it goes."""
        return self.level == 0

    def set_overview(self, on: bool) -> None:
        self.action_zoom(-self.level if on else 1)

    def zoom(self, steps: int) -> None:
        self.action_zoom(steps)

    def view_state(self) -> int:
        """The zoom, to carry over to another view of the graph (compare mode's panes)."""
        return self.level

    def set_view_state(self, state: object) -> None:
        if isinstance(state, int) and state != self.level:
            self.level = state
            self._refit()

    def refresh_graph(self) -> None:
        """The graph's start, goals or closed nodes changed: draw them anew."""
        self._marked_from(self.graph)
        self.refresh()

    def show_states(self, state_of: StateOf | None = None,
                    changed: Iterable[int] | None = None) -> None:
        """Draw the search's state (``state_of``, if a new source); ``changed`` names the nodes
        that differ from what is shown, None: any may."""
        if state_of is not None:
            self.state_of = state_of
        if changed is None:
            self.refresh()
        else:
            self.refresh_nodes(changed)

    def refresh_nodes(self, nodes: Iterable[int]) -> None:
        """Repaint the lines that show ``nodes`` (their marks, names and cursor marks)."""
        if self.tiles is None:
            return
        lines: set[int] = set()
        for v in nodes:
            lines.update(self._lines_of(v))
        for line in lines:
            self.refresh_line(line)

    def _lines_of(self, v: int) -> set[int]:
        assert self.canvas is not None and self.tiles is not None
        col, row = self.canvas.cell(v)
        tile = self.tiles.of_cell(col, row)
        placed = tile.names.get(v) if tile is not None else None
        return {row} if placed is None else {row, placed[1]}

    # -- the state of a node, as the rows draw it ---------------------------------------------
    def code_of(self, v: int) -> int:
        """Node ``v``'s drawing code (:mod:`~tui_search.tui.view.cell_codes`)."""
        if v in self.closed:
            return WALL
        if v == self.start:
            return START
        if v in self.goals:
            return GOAL
        return int(self.state_of(v))

    def lit(self, road: int) -> bool:
        """Is the road on the path (both its ends are)?"""
        d, state_of = self.graph.data, self.state_of
        return state_of(d.road_a[road]) == PATH and state_of(d.road_b[road]) == PATH

    # -- fitting and zooming ------------------------------------------------------------------
    def on_resize(self) -> None:
        self._refit()

    def on_mount(self) -> None:
        self._refit()

    def _refit(self) -> None:
        """The drawing for the room there is and the zoom: a new canvas, the cursor in view."""
        region = self.content_region
        box = (region.width, region.height)
        if not region.area:
            return
        self._box = box
        self.canvas = Canvas(self.placement, box[0], box[1], self.level, self.longest)
        self.level = self.canvas.level
        self.tiles = Tiles(self.canvas, self.names, self.need, self.costs)
        zoomed = self.level > 0
        self.styles.overflow_x = "auto" if zoomed else "hidden"
        self.styles.overflow_y = "auto" if zoomed else "hidden"
        self.border_subtitle = "part of the graph · [: all of it" if zoomed else ""
        self.virtual_size = Size(self.canvas.cols, self.canvas.rows)
        self.refresh()
        self.call_after_refresh(self.follow, self.cursor)

    def action_zoom(self, steps: int) -> None:
        """Zoom in (``steps`` > 0) or out by levels; the cursor's node stays in view."""
        if self.canvas is None:
            return
        level = max(0, min(self.canvas.levels - 1, self.level + steps))
        if level != self.level:
            self.level = level
            self._refit()

    def follow(self, v: int) -> None:
        """Scroll (without animation) so node ``v``'s chip is in view, a little room around."""
        if self.canvas is None or not self.size.area:
            return
        col, row = self.canvas.cell(v)
        view = self.scrollable_content_region
        x, y = int(self.scroll_x), int(self.scroll_y)
        room_x, room_y = min(12, view.width // 4), min(3, view.height // 4)
        if not x + room_x <= col < x + view.width - room_x:
            x = col - view.width // 2
        if not y + room_y <= row < y + view.height - room_y:
            y = row - view.height // 2
        if (x, y) != (int(self.scroll_x), int(self.scroll_y)):
            self.scroll_to(x, y, animate=False, immediate=True)
        self.call_after_refresh(self.place_terminal_cursor)

    # -- the cursor ----------------------------------------------------------------------------
    def validate_cursor(self, node: int) -> int:
        return max(0, min(len(self.graph) - 1, node))

    def watch_cursor(self, old: int, new: int) -> None:
        if self.tiles is not None:
            self.refresh_nodes((old, new))
            self.follow(new)
        self.post_message(self.CursorMoved(new))

    def action_toward(self, direction: str) -> None:
        if self.canvas is not None:
            node = toward(self.canvas, self.cursor, direction)
            if node is not None:
                self.cursor = node

    def action_next_node(self, step: int) -> None:
        self.cursor = tab_next(len(self.graph), self.cursor, step)

    def cursor_cell(self) -> tuple[int, int]:
        """Where the cursor's mark (``◀``) goes, in the drawing."""
        assert self.canvas is not None and self.tiles is not None
        mark = self.canvas.cell(self.cursor)
        tile = self.tiles.of_cell(*mark)
        return mark if tile is None else tile.cursor_cell(self.cursor, mark)

    def place_terminal_cursor(self) -> None:
        """The terminal's own cursor on the cursor's mark while the view has the focus (a
        braille display and a screen reader's review follow it), as the grid does."""
        if not self.has_focus or self.canvas is None or not self.size.area:
            return
        col, row = self.canvas.cell(self.cursor)
        x, y = col - int(self.scroll_x), row - int(self.scroll_y)
        view = self.scrollable_content_region
        if 0 <= x < view.width and 0 <= y < view.height:
            self.app.cursor_position = Offset(view.x + x, view.y + y)

    def on_focus(self) -> None:
        self.call_after_refresh(self.place_terminal_cursor)

    # -- drawing -------------------------------------------------------------------------------
    def notify_style_update(self) -> None:
        super().notify_style_update()
        self._looks = None

    def looks(self) -> GraphLooks:
        if self._looks is None:
            self._looks = GraphLooks(self.get_component_rich_style, self.cached_style())
        return self._looks

    def render_line(self, y: int) -> Strip:
        width = self.scrollable_content_region.width
        background = self.cached_style()
        if self.tiles is None:
            return Strip.blank(width, background)
        sx, sy = int(self.scroll_x), int(self.scroll_y)
        shown_now = Shown(self.tiles, self.looks(), self.code_of, self.lit, self.cursor,
                          self.cursor_cell())
        return line_strip(graph_line(shown_now, sy + y, sx, width), sx, width, background)

    # -- the mouse: select, and say so ---------------------------------------------------------
    def node_at_offset(self, x: int, y: int) -> int | None:
        """The node at a point of the content area (None: none there)."""
        if self.tiles is None:
            return None
        return node_at(self.tiles, x + int(self.scroll_x), y + int(self.scroll_y))

    def screen_offset(self, v: int) -> tuple[int, int]:
        """Where node ``v``'s mark is in the content area at the scroll offset (tests click
        there; the inverse of :meth:`node_at_offset`)."""
        assert self.canvas is not None
        col, row = self.canvas.cell(v)
        return col - int(self.scroll_x), row - int(self.scroll_y)

    def on_mouse_down(self, event: events.MouseDown) -> None:
        at = event.get_content_offset(self)
        node = None if at is None else self.node_at_offset(at.x, at.y)
        if node is None:
            return
        event.stop()
        self.focus()
        self.cursor = node
        self.post_message(self.NodeClicked(node, event.button))


__all__ = ["GraphView", "StateOf", "unseen"]

"""A search's pane: its counts and narration, its map view, its frontier panel (titled by its
discipline) and its search tree.  Every search shown is a pane, one or four of them.  A
bidirectional search's pane has a frontier panel and a tree for each of its halves (the
backward's made the first time one is shown), and its map draws both.

The screen pushes a run to it (:meth:`RunPane.show`) and tells it how to lay itself out
(:meth:`RunPane.lay_out`, from :func:`~tui_search.tui.view.layout.arrange`); layout beyond that is
``app.tcss``'s.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.app import ComposeResult
from textual.containers import Vertical
from textual.widget import Widget
from textual.widgets import Static

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State, as_cell
from tui_search.tui.model.searches import current_node
from tui_search.tui.view.layout import Arrangement, frontier_lines
from tui_search.tui.view.status_lines import search_status
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.lazy_parts import Later, code_panel, show_part
from tui_search.tui.widgets.search_tree import SearchTreePanel
from tui_search.tui.widgets.stats import Stats

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.tui.widgets.code_panel import CodePanel
    from tui_search.tui.widgets.graph_view import GraphView

#: The map's box is at least this wide where the pane is, so its title (the file's name) shows.
MAP_TITLE_WIDTH = 30
#: A bidirectional search's column beside its map shows its two trees under its two
#: frontiers from this height on; lower, the frontiers take the column (a tree needs a few
#: lines to say anything, a frontier its next entry).
TWO_WAY_TREES_FROM = 26


class RunPane(Vertical):
    """A run's pane: ``label`` names its search.  ``note`` is what the lists' place says
    while there is no run (no start or goal)."""

    def __init__(self, grid: Grid | Graph, label: str, note: str = "") -> None:
        super().__init__(classes="run-pane")
        self.label = label
        self.stats = Stats(classes="pane-stats")
        self.view: GridView | GraphView
        if isinstance(grid, Grid):
            self.view = GridView(grid, classes="pane-map")
        else:  # a graph's view: its modules imported for a graph only
            from tui_search.tui.widgets.graph_view import GraphView

            self.view = GraphView(grid, classes="pane-map -graph")
        self.frontier = FrontierPanel(classes="pane-frontier")
        self.tree_panel = SearchTreePanel(classes="pane-tree")
        # a bidirectional search's backward half's panels, made when first shown
        self._back_frontier: Later[FrontierPanel] = Later(
            lambda: FrontierPanel(classes="pane-frontier -backward"))
        self._back_tree: Later[SearchTreePanel] = Later(
            lambda: SearchTreePanel(classes="pane-tree -backward"))
        self._code: Later[CodePanel] = Later(code_panel)  # made when first shown
        self.side_note = Static(note, classes="pane-note")
        self.map_box = Vertical(classes="pane-map-box")  # the room the map's cells fit
        self.lists = Vertical(classes="pane-lists")
        # the run last shown: the Code panel shows it on unfolding
        self._run: Run | BiRun | None = None
        self._frontier_lines: int | None = None  # set beside the map (None: app.tcss's)

    def compose(self) -> ComposeResult:
        # The parts a layout may leave hidden (the Code panel, the note, the pane's own status
        # lines) are mounted when one first shows them (:meth:`_show_part`): a first frame
        # without them neither composes nor styles them (benchmarks/README.md, "startup").
        with self.lists:  # docked first: beside the map, it spans the pane's whole height
            yield self.frontier
            yield self.tree_panel
        with self.map_box:
            yield self.view

    def _show_part(self, part: Widget, shown: bool) -> None:
        """Mount ``part`` in its place the first time it is ``shown``."""
        if part is self.stats:
            show_part(self, part, shown, [self.lists, self.stats, self.map_box])
        else:
            show_part(self.lists, part, shown,
                      [self.frontier, self._back_frontier.made, self.tree_panel,
                       self._back_tree.made, self._code.made, self.side_note])

    @property
    def code_panel(self) -> CodePanel:
        """The Code panel (made the first time it is asked for)."""
        return self._code.get()

    @property
    def code_shown(self) -> bool:
        """The Code panel is unfolded (so kept up to date)."""
        return self._code.made is not None and not self._code.made.has_class("-folded")

    def lay_out(self, arrangement: Arrangement, code: bool = False,
                restyle: bool = True, level_width: int = 0) -> None:
        """Lay the pane out: its lists beside or under the map, or not at all; its trees and
        its own status lines shown or not; with ``code``, the Code panel in the tree's place
        (where the arrangement has room for it: fewer lines than a tree needs).
        ``restyle=False``: the classes are set and left for the next restyle of the screen;
        ``level_width``: the narrowest pane's width, its status lines take as many rows as
        the tallest's there."""
        self.set_class(arrangement.beside, "-beside", update=restyle)
        self.stats.display = arrangement.pane_stats
        # its lines wrap at another width
        self.stats.set_room(arrangement.lists_width if arrangement.beside else 0, level_width)
        self._show_part(self.stats, arrangement.pane_stats)
        lists = self.lists
        lists.display = arrangement.lists
        if arrangement.beside:
            lists.styles.width = arrangement.lists_width
            lists.styles.height = "1fr"
            self.map_box.styles.height = arrangement.map_height or "1fr"
        else:
            lists.styles.width = "1fr"
            lists.styles.height = arrangement.lists_height or None
            self.map_box.styles.height = arrangement.map_height or "1fr"
        self.view.styles.max_height = arrangement.map_max_height or "100%"
        self.tree_panel.set_class(not arrangement.trees or code, "-folded", update=restyle)
        if self._back_tree.made is not None:
            self._back_tree.made.set_class(not arrangement.trees or code, "-folded",
                                           update=restyle)
        code_there = arrangement.code and code
        if code_there or self._code.made is not None:
            self.code_panel.set_class(not code_there, "-folded", update=restyle)
            self._show_part(self.code_panel, code_there)
        # in lines too few for a tree, the code takes three fifths of the row: its lines are long
        self.set_class(code and arrangement.code and not arrangement.trees, "-code-short",
                       update=restyle)
        if self._run is not None and self.code_shown:
            self.code_panel.show(self._run)  # folded, it was not kept up to date
        # room for the map's title where the pane has it, else the map as narrow as it is
        self.view.styles.min_width = min(MAP_TITLE_WIDTH, max(0, arrangement.pane_width - 2))
        self._split_column()

    def _split_column(self) -> None:
        """In the lists' column beside the map, the frontier's lines: what its entries need
        before the tree or the Code panel under it gets lines
        (:func:`~tui_search.tui.view.layout.frontier_lines`); a bidirectional search's
        trees only where the column has :data:`TWO_WAY_TREES_FROM` lines."""
        cramped = (self.has_class("-two-way") and self.has_class("-beside")
                   and 0 < self.size.height < TWO_WAY_TREES_FROM)
        self.set_class(cramped, "-cramped")
        frontier = self.frontier
        under = not self.tree_panel.has_class("-folded") or self.code_shown
        lines = None
        if self.has_class("-beside") and under and self.size.height and not self.has_class(
                "-two-way"):  # a bidirectional search's four panels share the column
            need = frontier.rows_in_sight() + frontier.styles.gutter.height
            lines = frontier_lines(self.size.height, need)
        if lines != self._frontier_lines:  # a layout only when they change
            self._frontier_lines = frontier.styles.height = lines

    def on_resize(self) -> None:
        self._split_column()

    def show(self, run: Run | BiRun | None, changed: list[State] | None, *,
             follow: bool = True,
             hide_order: bool = False, as_added: bool = False, title: str = "",
             mark: State | None = None, marks: tuple[State, ...] = ()) -> None:
        """Push ``run`` at its position to the map and the panels (``changed``: the cells
        whose look changed, None for all); ``title`` is the map's border title, ``mark`` a
        cell the map marks (``marks``: more of them); ``hide_order`` and ``as_added``: how
        the frontier panel lists its entries (:meth:`FrontierPanel.show`)."""
        view = self.view
        self._run = run
        if isinstance(view, GridView):
            shown = (mark, *marks) if mark is not None else marks
            view.set_marks(tuple(as_cell(c) for c in shown))  # a grid's cells
            view.show_run(run, None if changed is None else [as_cell(c) for c in changed])
        else:
            view.show_run(run, changed)
        self.set_class(run is None, "-no-run")
        self._show_part(self.side_note, run is None)
        self._show_halves(run if run is not None and not isinstance(run, Run) else None,
                          hide_order)
        if run is not None:
            if isinstance(run, Run):
                self.frontier.show(run, hide_order=hide_order, as_added=as_added)
                self.tree_panel.show(run)
            self._split_column()
            if self.code_shown:
                self.code_panel.show(run)
            node = current_node(run)
            if follow and node is not None:
                if isinstance(view, GridView):
                    view.follow(as_cell(node))
                else:
                    view.follow_node(node)
            if self.stats.display:  # its own status lines, where the layout gives it some
                status = search_status(run, self.label, in_pane=True, done=run.at_end,
                                       code=self.code_shown)
                self.stats.show(status.lines, status.max_rows)
        if view.border_title != title:  # setting it repaints the whole view
            view.border_title = title

    def _show_halves(self, run: BiRun | None, hide_order: bool) -> None:
        """A bidirectional search's halves in the frontier panels and trees, forward then
        backward (None: the backward half's panels hidden, where they were made)."""
        back = (self._back_frontier, self._back_tree)
        for later in back:
            if later.made is not None or run is not None:
                later.get().set_class(run is None, "-unused")
        if self.has_class("-two-way") != (run is not None):
            self.set_class(run is not None, "-two-way")
            self._frontier_lines = self.frontier.styles.height = None  # app.tcss's
        if run is None:
            return
        ahead, behind = run.halves
        frontier, tree = self._back_frontier.get(), self._back_tree.get()
        self._show_part(frontier, True)
        self._show_part(tree, True)
        tree.set_class(self.tree_panel.has_class("-folded"), "-folded")
        stepped_back = bool(run.k) and run.direction(run.k) != "forward"
        self.frontier.show(ahead, hide_order=hide_order, direction="forward",
                           idle=stepped_back)
        frontier.show(behind, hide_order=hide_order, direction="backward",
                      idle=not stepped_back)
        self.tree_panel.show(ahead, direction="forward", idle=stepped_back)
        tree.show(behind, direction="backward", idle=not stepped_back)



def own_rows(panes: list[RunPane], width: int) -> int:
    """The lines the panes' own status lines take in a column ``width`` wide: the most of
    any pane's (0 before they say anything)."""
    return max(pane.stats.height_at(width - 2) for pane in panes)

"""One run's pane in compare mode: its counts and narration, its map view, its frontier panel
(titled by its discipline) and its search tree, side by side with the other runs' panes.

The same widgets as the single view, pushed the same way (:func:`show_run`): comparing runs
is more panes, not more special cases.  Layout is the app's (``app.tcss``).
"""

from __future__ import annotations

from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical

from tui_search.engine.grid import Cell, Grid
from tui_search.engine.run import Run
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.search_tree import SearchTreePanel
from tui_search.tui.widgets.stats import Stats


def show_run(view: GridView, frontier: FrontierPanel, tree: SearchTreePanel, run: Run | None,
             changed: list[Cell] | None, follow: bool, hide_order: bool) -> None:
    """Push ``run`` at its position to a map view and its panels (``changed``: the cells
    whose look changed, None for all)."""
    view.show_run(run, changed)
    if run is not None:
        frontier.show(run, hide_order=hide_order)
        tree.show(run)
        node = run.current_node()
        if follow and node is not None:
            view.follow(node)


class RunPane(Vertical):
    """A run of a comparison: ``label`` names its search."""

    def __init__(self, grid: Grid, label: str, *, id: str | None = None) -> None:
        super().__init__(id=id, classes="run-pane")
        self.label = label
        self.stats = Stats(classes="pane-stats")
        self.view = GridView(grid, classes="pane-map")
        self.frontier = FrontierPanel(classes="pane-frontier")
        self.tree_panel = SearchTreePanel(classes="pane-tree")

    def compose(self) -> ComposeResult:
        yield self.stats
        with Vertical(classes="pane-map-box"):  # the room the map's cells are fitted to
            yield self.view
        with Horizontal(classes="pane-lists"):
            yield self.frontier
            yield self.tree_panel

    def show(self, run: Run | None, algorithm: str, changed: list[Cell] | None, *,
             follow: bool = True, hide_order: bool = False, note: str = "",
             done: bool = False) -> None:
        show_run(self.view, self.frontier, self.tree_panel, run, changed, follow, hide_order)
        self.stats.show(run, algorithm, label=self.label, note=note, done=done)

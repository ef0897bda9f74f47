"""Pictures of the frontier and search-tree panels on the tutorial's map (SVG snapshots).

Each test is one behaviour; its docstring says what the picture must show.  Update with
``pytest tests/tui/test_panels_snapshots.py --snapshot-update`` and look at the SVGs before
accepting them.
"""

from __future__ import annotations

from textual.app import App, ComposeResult
from textual.containers import Horizontal

from tests.helpers import TUTORIAL_ROWS, grid_from_rows
from tui_search.engine.run.recorded import Run
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.search_tree import SearchTreePanel


def tutorial_run(algorithm: str, k: int | None) -> Run:
    run = Run(grid_from_rows(TUTORIAL_ROWS), algorithm)
    run.advance()
    run.goto(run.recorded if k is None else k)
    return run


class PanelsApp(App):
    """The frontier panel and/or the tree panel, side by side, shown one run."""

    CSS = """
    FrontierPanel { width: 38; }
    SearchTreePanel { width: 1fr; }
    """

    def __init__(self, run: Run, frontier: bool = True, tree: bool = True) -> None:
        super().__init__()
        self.run_ = run
        self.with_frontier, self.with_tree = frontier, tree

    def compose(self) -> ComposeResult:
        with Horizontal():
            if self.with_frontier:
                yield FrontierPanel()
            if self.with_tree:
                yield SearchTreePanel()

    def on_mount(self) -> None:
        for panel in self.query(FrontierPanel):
            panel.show(self.run_)
        for panel in self.query(SearchTreePanel):
            panel.show(self.run_)


def test_bfs_after_four_steps(snap_compare) -> None:
    """BFS on the tutorial map after 4 steps.  Left, "Queue (FIFO) · 4": ▶ on (0,3) S at the
    front (highlighted), (1,3) SE, then (2,2) E and (2,1) NE marked + (just added) at the back,
    "← front (next out)" / "← back (newest)" hints.  Right, "Search tree · 8 nodes": START → S,
    whose children S (0,2) and SE (1,2) are expanded (● blue); SE (1,2) is the highlighted
    "◀ expanding" line with children E, NE; frontier nodes ○ in the plain text colour."""
    assert snap_compare(PanelsApp(tutorial_run("bfs", 4)), terminal_size=(90, 12))


def test_dfs_after_three_steps(snap_compare) -> None:
    """DFS after 3 steps: "Stack (LIFO) · 5" with NE (2,1) on top (▶+), then E, S, SW (+) and the
    old S (0,2) at the bottom; the tree shows SE (1,2) highlighted with its four children
    SW, S, E, NE in that order."""
    assert snap_compare(PanelsApp(tutorial_run("dfs", 3)), terminal_size=(90, 12))


def test_iddfs_found_path_in_tree(snap_compare) -> None:
    """Iterative deepening at the end: the title "Search tree · depth limit 7 · 13 nodes", the
    path START → S → SE → NE → NE → E → SE → S in green (bold), the goal line "★ S (5,2)  ★ goal",
    SE (5,1) still marked "◀ expanding" but green like the rest of the path (no blue band),
    unexpanded siblings ○ in the plain colour, and "★ goal" in the legend at the bottom right."""
    app = PanelsApp(tutorial_run("iddfs", None), frontier=False)
    assert snap_compare(app, terminal_size=(56, 17))

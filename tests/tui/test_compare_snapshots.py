"""Pictures of compare mode (look at them as PNGs before accepting a change)."""

from __future__ import annotations

from tests.tui.test_app import TUTORIAL
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp


def compare_app() -> SearchApp:
    return SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")


def test_compare_on_the_tutorial_at_step_3(snap_compare) -> None:
    """BFS left, DFS right, both at step 3 of the tutorial: the queue holds (1,2) S (0,3)... and
    the stack (2,1) on top; the table says '… step 3' for both, with no marks yet."""
    assert snap_compare(compare_app(), press=["n", "n", "n"], terminal_size=(150, 44))


def test_compare_on_the_tutorial_at_the_end(snap_compare) -> None:
    """After end: BFS at 22/22, DFS 'done at step 7', both paths green; the table marks DFS's 7
    expanded and both costs 8.657 with *, and says 'BFS expanded 22 nodes, DFS 7; both paths
    have 7 moves'."""
    assert snap_compare(compare_app(), press=["end"], terminal_size=(150, 44))


def test_compare_at_80_by_24(snap_compare) -> None:
    """The tutorial's demo in the smallest terminal, after end: both 6x6 maps whole (start,
    goal and both paths), each pane's queue or stack under its map; the table gives way."""
    assert snap_compare(compare_app(), press=["end"], terminal_size=(80, 24))


def test_compare_with_an_exercise_at_120_by_40(snap_compare) -> None:
    """Exercise 1 on top across the screen, BFS and DFS side by side under it, each map whole
    with its lists under it; no empty column beside the panes."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs", exercise=1)
    assert snap_compare(app, press=["end"], terminal_size=(120, 40))

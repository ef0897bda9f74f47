"""Pictures of graphs (issue 37): look at each as a PNG before accepting a change."""

from __future__ import annotations

from tests.tui.test_graphs import DFS_BACKTRACKS
from tui_search.engine.maps.graph_file import built_in_graph, load_graph
from tui_search.tui.app import SearchApp


def romania(algorithm: str = "astar") -> SearchApp:
    return SearchApp(built_in_graph("romania"), algorithm=algorithm, theme="dark")


def test_romania_under_a_star_midway_at_120_by_40(snap_compare) -> None:
    """A* after 3 steps: Arad and Sibiu expanded, Rimnicu being expanded (its chip lit),
    Fagaras, Pitesti, Craiova and the rest of the frontier as rings; every city named in
    full with every road's cost; the priority queue lists f, g and h, Fagaras next (f 415
    below Pitesti's 417); the tree names each node with its road's cost."""
    assert snap_compare(romania(), press=["n", "n", "n"], terminal_size=(120, 40))


def test_romania_at_80_by_24(snap_compare) -> None:
    """A* at its end in the smallest terminal: the whole map in its box, names cut no
    shorter than three letters, the path Arad, Sibiu, Rimnicu, Pitesti, Bucharest lit, and
    the status line's route at cost 418 (the lowest)."""
    assert snap_compare(romania(), press=["end"], terminal_size=(80, 24))


def test_a_teaching_graph_under_dfs_beside_bfs(snap_compare) -> None:
    """dfs-backtracks laid out in layers (S on top), BFS left and DFS right after 3 steps:
    BFS has expanded S, B and found G's ring on its queue; DFS has gone down A to E, its
    stack holding C and B."""
    app = SearchApp(load_graph(DFS_BACKTRACKS), path=DFS_BACKTRACKS, compare="bfs,dfs",
                    theme="dark")
    assert snap_compare(app, press=["n", "n", "n"], terminal_size=(120, 40))

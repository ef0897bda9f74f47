"""A picture of a generated maze (issue 23): the recursive backtracker's maze -- a depth-first
search carving its own maze -- solved by the app's DFS, at the end, under the four moves the
mazes are made for.  Update with ``pytest tests/tui/test_generate_snapshots.py
--snapshot-update`` and look at the changed SVG before accepting it."""

from __future__ import annotations

from tests.tui.test_snapshots import SIZE
from tui_search.engine.maps.generate import generate, parse_recipe
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp

RECIPE = parse_recipe("maze 21x15 7")


def test_a_generated_maze_under_dfs_at_the_end(snap_compare) -> None:
    """The maze's corridors one cell wide; DFS's path from the top left to the bottom right
    corner, what it tried and backed out of expanded beside it; the title the recipe."""
    app = SearchApp(generate(RECIPE), algorithm="dfs", unsaved_name=RECIPE.title,
                    semantics=Semantics(order=("N", "E", "S", "W")))
    assert snap_compare(app, press=["end"], terminal_size=SIZE)

"""Pictures of the tutorial in the other themes (the default dark one is in test_snapshots.py,
unchanged by themes).  Update with ``pytest tests/tui/test_snapshots_themes.py
--snapshot-update`` and look at every changed SVG before accepting it."""

from __future__ import annotations

from tests.tui.test_app import TUTORIAL
from tests.tui.test_snapshots import SIZE
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp


def themed_app(theme: str) -> SearchApp:
    return SearchApp(load_map(TUTORIAL), path=TUTORIAL, theme=theme)


def test_tutorial_in_the_light_theme(snap_compare) -> None:
    """The light theme for projectors, BFS after four steps: near-black text on white; green S,
    yellow G, charcoal obstacles, frontier ○ on orange, expanded ● light blue, the node being
    expanded ◉ dark blue with a white glyph; the panels (grey borders) and the key bar light too."""
    assert snap_compare(themed_app("light"), press=["n"] * 4, terminal_size=SIZE)


def test_tutorial_at_the_end_in_the_light_theme(snap_compare) -> None:
    """The light theme at BFS's last step: the path ◆ white on dark green over the light blue
    expanded cells; the tree's path lines dark green."""
    assert snap_compare(themed_app("light"), press=["end"], terminal_size=SIZE)


def test_tutorial_in_the_colour_blind_theme(snap_compare) -> None:
    """The colour-blind-safe theme at BFS's last step: grey obstacles, S white, G yellow,
    expanded ● dark blue, the path ◆ vermillion on the map and in the tree (expanded nodes
    blue there): no red against green anywhere."""
    assert snap_compare(themed_app("colour-blind"), press=["end"], terminal_size=SIZE)

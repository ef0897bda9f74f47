"""Pictures of terrain: the mud map (maps/terrain-mud.txt) at the end of BFS, which wades
straight through the mud, and of uniform-cost search, which walks round it -- in the default
dark theme and the colour-blind one.  Update with ``pytest tests/tui/test_terrain_snapshots.py
--snapshot-update`` and look at every changed SVG before accepting it."""

from __future__ import annotations

import pytest

from tests.tui.test_app import MAPS
from tests.tui.test_snapshots import SIZE
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp

MUD = MAPS / "terrain-mud.txt"


@pytest.mark.parametrize("theme", ["dark", "colour-blind"])
@pytest.mark.parametrize("algorithm", ["bfs", "ucs"])
def test_the_mud_map_at_the_end(snap_compare, algorithm: str, theme: str) -> None:
    """BFS: 7 moves through the mud, cost 32.11 (lowest 9.24); UCS: 8 moves round it, the
    lowest.  The mud shaded by the ramp and its cells saying 9, the legend's ramp."""
    app = SearchApp(load_map(MUD), path=MUD, algorithm=algorithm, theme=theme)
    assert snap_compare(app, press=["end"], terminal_size=SIZE)

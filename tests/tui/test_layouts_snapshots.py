"""A picture of a Pacman layout in the app (an SVG snapshot); the docstring says what it must
show."""

from __future__ import annotations

from pathlib import Path

from tui_search.engine.course.presets import preset_semantics
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.registry import get_algorithm
from tui_search.tui.app import SearchApp

ROOT = Path(__file__).resolve().parents[2]
THREE = ROOT / "examples" / "cs188_style" / "layouts" / "threeDots.lay"


def test_a_layout_under_the_cs188_preset(snap_compare) -> None:
    """threeDots.lay under --preset cs188 (BFS), three steps in: the walls, the start at
    (1,3), the goal the first dot (8,1); the status line's moves N,S,E,W, visit and goal test
    on expand; the cursor moved up twice to the capsule, the readout 'Cursor (1,1) course
    (1,3)' (the course's y from the bottom row) and that it is on the frontier; the note of
    the three dots, which is the goal, still in the status line."""
    app = SearchApp(load_map(THREE), path=THREE, algorithm="bfs",
                    semantics=preset_semantics("cs188", get_algorithm("bfs")))
    assert snap_compare(app, terminal_size=(80, 24), press=["n", "n", "n", "up", "up"])

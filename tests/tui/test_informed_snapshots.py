"""Pictures of informed search (SVG snapshots; look at every changed one before accepting)."""

from __future__ import annotations

from tests.tui.test_app import TUTORIAL, tutorial_app
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp

SIZE = (100, 30)


def test_a_star_mid_run_with_its_priority_queue(snap_compare) -> None:
    """A* on the tutorial after five steps: the panel 'Priority queue (A*: f = g + h)' lists
    its five entries in the order they come out, each 'f g h', (2,1) next (▶), (0,3) just added
    at g 3.00 (+) and its older entry at g 3.83 struck out as stale; the status line shows
    'f 7.00 (g 2.00 + h 5.00)'; the narration '(0,3) reached with a lower g'."""
    assert snap_compare(tutorial_app("astar"), press=["n"] * 5, terminal_size=SIZE)


def test_the_inadmissible_warning(snap_compare) -> None:
    """A* with the manhattan heuristic at its end: the status line says 'heuristic manhattan ·
    inadmissible heuristic: the path may not be optimal'; the path's cost beside the lowest."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, algorithm="astar",
                    semantics=Semantics(heuristic="manhattan"))
    assert snap_compare(app, press=["end"], terminal_size=(120, 30))

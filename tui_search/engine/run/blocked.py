"""Why a search found no path: name the rule that blocked it, when a rule did.

A map can have no path at all (the goal is walled in), or have one that the choices in force
forbid: a corner rule that refuses the diagonal squeeze the path needs, or a move order without
diagonals.  Students should hear which, so the rules are relaxed one at a time and the map is
searched again with BFS (complete, and fast on any map the app opens).
"""

from __future__ import annotations

from tui_search.engine.maps.grid import DEFAULT_ORDER, DIRECTIONS, Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics


def _has_path(grid: Grid, semantics: Semantics) -> bool:
    moves_only = Semantics(order=semantics.order, corners=semantics.corners)  # BFS's own rest
    return Run(grid, "bfs", moves_only).outcome().found


def blocking_rule(grid: Grid, semantics: Semantics) -> str | None:
    """A few words on the rule that leaves ``grid`` without a path (None when no rule does:
    there is no path whatever the rules)."""
    moves = ",".join(semantics.order)
    if semantics.corners != "always" and _has_path(grid, semantics.replace(corners="always")):
        return f"the corner rule '{semantics.corners}' blocks it (with 'always' there is a path)"
    if set(semantics.order) != set(DIRECTIONS):
        everything = semantics.replace(order=DEFAULT_ORDER)
        if _has_path(grid, everything):
            return f"the moves {moves} block it (with all eight there is a path)"
        if _has_path(grid, everything.replace(corners="always")):
            return (f"the moves {moves} and the corner rule '{semantics.corners}' block it "
                    "(all eight moves with 'always' find a path)")
    return None

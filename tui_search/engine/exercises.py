"""The tutorial's two exercises as checks on a map.

Both exercises are comparisons of BFS and DFS on the same map (the tutorial's defaults):

1. "change the location of the target such that Breadth first search will give a faster
   result than depth first search (expand less nodes)": solved when both find the goal and
   BFS expands fewer nodes than DFS.  The exercise moves only the target: a map whose start or
   obstacles differ from the tutorial's still counts, with a hint that more than the goal
   changed.
2. "Change the orientation of the obstacles, start, and goal such that the results provide
   non-optimal solutions": solved when DFS's path has more moves than BFS's.

Plain Python, no UI: the command line grades a student's file with it, and the app's
challenge panel shows the same figures live.
"""

from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

from tui_search.engine.grid import Grid
from tui_search.engine.outcome import Outcome
from tui_search.engine.run import MAX_STEPS, Run
from tui_search.engine.semantics import DEFAULT_SEMANTICS

#: The exercises' words, quoted from the tutorial.
QUOTES = {
    1: "Change the location of the target such that breadth first search will give a faster "
       "result than depth first search (expand less nodes).",
    2: "Change the orientation of the obstacles, start, and goal such that the results "
       "provide non-optimal solutions.",
}


#: The tutorial's map, shipped in the package: where the exercises start.
TUTORIAL_MAP = Path(__file__).resolve().parents[1] / "maps" / "tutorial.txt"
#: Maps bigger than this are not checked at each edit by the app (two whole searches an edit,
#: and a mouse stroke is an edit a cell; a BFS and a DFS of 10,000 cells: ~20 ms) but in a
#: thread once the edits pause.
LIVE_CELLS = 10_000


def tutorial_grid() -> Grid:
    """The tutorial's 6x6 map."""
    from tui_search.engine.mapfile import parse_map_text

    return parse_map_text(TUTORIAL_MAP.read_text("utf-8"), TUTORIAL_MAP.name)


class Verdict(NamedTuple):
    """An exercise checked on a map: solved or not, why, and the two searches' outcomes."""

    exercise: int
    solved: bool
    reason: str  # one line in the tutorial's terms
    bfs: Outcome
    dfs: Outcome
    hint: str = ""  # exercise 1 on a map whose start or obstacles moved

    def as_json(self) -> dict[str, object]:
        def figures(out: Outcome) -> dict[str, object]:
            return {"found": out.found, "moves": out.length, "expanded": out.expanded,
                    "generated": out.generated, "gave_up": out.gave_up}

        return {"exercise": self.exercise, "solved": self.solved, "reason": self.reason,
                "hint": self.hint or None, "bfs": figures(self.bfs), "dfs": figures(self.dfs)}


def check(exercise: int, grid: Grid, tutorial: Grid | None = None,
          max_steps: int = MAX_STEPS) -> Verdict:
    """Exercise ``exercise`` (1 or 2) on ``grid``; ``tutorial``, the map the exercise starts
    from, for exercise 1's hint.  ``ValueError`` for another number or a map without start
    or goal."""
    if exercise not in QUOTES:
        raise ValueError(f"exercise {exercise}: the tutorial has exercises 1 and 2")
    bfs = Run(grid, "bfs", DEFAULT_SEMANTICS, max_steps).outcome()
    dfs = Run(grid, "dfs", DEFAULT_SEMANTICS, max_steps).outcome()
    both = f"BFS expanded {bfs.expanded:,} nodes, DFS {dfs.expanded:,}"
    quitters = [name for name, out in (("BFS", bfs), ("DFS", dfs)) if out.gave_up]
    if quitters:  # not "no path": the map may well have one, further than the steps allowed
        who = " and ".join(quitters)
        return Verdict(exercise, False, f"not graded: {who} gave up at {max_steps:,} steps "
                       f"before finding the goal ({both})", bfs, dfs)
    if not (bfs.found and dfs.found):
        return Verdict(exercise, False, f"no path to the goal ({both})", bfs, dfs)
    assert bfs.length is not None and dfs.length is not None
    moves = (f"both paths have {bfs.length} moves" if bfs.length == dfs.length
             else f"BFS's path has {bfs.length} moves, DFS's {dfs.length}")
    if exercise == 1:
        solved = bfs.expanded < dfs.expanded
        hint = ""
        if tutorial is not None and not _only_goal_moved(grid, tutorial):
            hint = "the exercise moves only the target: here more than the goal changed"
        return Verdict(1, solved, f"{both}; {moves}", bfs, dfs, hint)
    solved = dfs.length > bfs.length
    return Verdict(2, solved, f"{moves}; {both}", bfs, dfs)


def _only_goal_moved(grid: Grid, tutorial: Grid) -> bool:
    return ((grid.width, grid.height, grid.start) == (tutorial.width, tutorial.height,
                                                      tutorial.start)
            and grid.blocked == tutorial.blocked)


__all__ = [
    "LIVE_CELLS",
    "QUOTES",
    "TUTORIAL_MAP",
    "Verdict",
    "check",
    "tutorial_grid",
]

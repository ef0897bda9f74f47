"""The tutorial's two exercises as checks on a map, and comparing searches on one map.

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

from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from typing import NamedTuple

from tui_search.engine.algorithms import get_algorithm
from tui_search.engine.grid import Grid
from tui_search.engine.outcome import Outcome
from tui_search.engine.run import MAX_STEPS, Run
from tui_search.engine.semantics import DEFAULT_SEMANTICS, Semantics

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

    def as_json(self) -> dict:
        def figures(out: Outcome) -> dict:
            return {"found": out.found, "moves": out.length, "expanded": out.expanded,
                    "generated": out.generated}

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


# -- comparing searches ------------------------------------------------------------------------


class Contender(NamedTuple):
    """One search of a comparison: an algorithm and its choices (a heuristic of its own)."""

    algorithm: str
    semantics: Semantics

    @property
    def label(self) -> str:
        algo = get_algorithm(self.algorithm)
        if algo.informed and self.semantics.heuristic != DEFAULT_SEMANTICS.heuristic:
            return f"{algo.short} ({self.semantics.heuristic})"
        return algo.short


def parse_compare(text: str, semantics: Semantics = DEFAULT_SEMANTICS,
                  fit: bool = False) -> list[Contender]:
    """``bfs,dfs`` or ``astar:manhattan,ucs``: two to four registry keys, each informed one
    with an optional heuristic.  ``ValueError`` (one line) for anything else -- or, with
    ``fit``, for a choice that does not apply to one of them, that one visits on generate
    (the app's settings apply to every pane where they can)."""
    from tui_search.engine.heuristics import HEURISTICS

    parts = [p.strip() for p in text.split(",") if p.strip()]
    if not 2 <= len(parts) <= 4:
        raise ValueError(f"compare two to four searches, not {len(parts)} ({text!r})")
    out = []
    for part in parts:
        key, _, heuristic = part.partition(":")
        algo = get_algorithm(key)
        sem = semantics
        if heuristic:
            if not algo.informed:
                raise ValueError(f"{part!r}: {key} uses no heuristic")
            if heuristic not in HEURISTICS:
                raise ValueError(f"{part!r}: unknown heuristic (use {', '.join(HEURISTICS)})")
            sem = replace(sem, heuristic=heuristic)
        try:
            sem.check(algo)
        except ValueError:
            if not fit:
                raise
            sem = replace(sem, visit="generate")
        out.append(Contender(key, sem))
    return out


class TableRow(NamedTuple):
    label: str
    outcome: Outcome
    fewest_expanded: bool
    cheapest: bool


def comparison(labels: list[str], outcomes: list[Outcome], marks: bool = True) -> list[TableRow]:
    """The table's rows: each run with a mark on the fewest expanded and the cheapest path
    (ties marked alike); no marks with ``marks=False`` (runs still going)."""
    fewest = min(o.expanded for o in outcomes)
    costs = [o.cost for o in outcomes if o.cost is not None]
    cheapest = min(costs) if costs else None
    return [TableRow(label, o, marks and o.expanded == fewest, marks and o.cost is not None
                     and cheapest is not None and o.cost <= cheapest + 1e-9)
            for label, o in zip(labels, outcomes)]


#: The comparison table's columns.
TABLE_HEAD = ("search", "found", "moves", "cost", "expanded", "generated", "max frontier")
#: The line under the table that says what the marks mean.
MARKS_KEY = "* the fewest expanded, the cheapest path"


def table_cells(rows: list[TableRow], steps: Sequence[int | None] | None = None
                ) -> list[tuple[str, ...]]:
    """The table as text cells, the head first.  ``steps``: for each row, the step a run that
    is still going is at (its "found" says so), or None for a finished run."""
    out: list[tuple[str, ...]] = [TABLE_HEAD]
    for i, r in enumerate(rows):
        o = r.outcome
        step = steps[i] if steps is not None else None
        if step is not None:
            found = f"… step {step:,}"
        else:
            found = "gave up" if o.gave_up else ("yes" if o.found else "no")
        out.append((
            r.label,
            found,
            f"{o.length:,}" if o.length is not None else "-",
            (f"{o.cost:.3f}" + (" *" if r.cheapest else "  ")) if o.cost is not None else "-",
            f"{o.expanded:,}" + (" *" if r.fewest_expanded else "  "),
            f"{o.generated:,}",
            f"{o.max_frontier:,}",
        ))
    return out


def table_lines(cells: list[tuple[str, ...]]) -> list[str]:
    """The cells in aligned columns, a line a row."""
    widths = [max(len(c[i]) for c in cells) for i in range(len(cells[0]))]
    return ["  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip() for row in cells]


def summary_sentence(rows: list[TableRow]) -> str:
    """In the tutorial's terms: "DFS expanded 7 nodes, BFS 22; both paths have 7 moves"."""
    first, *rest = rows
    expanded = f"{first.label} expanded {first.outcome.expanded:,} nodes" + "".join(
        f", {r.label} {r.outcome.expanded:,}" for r in rest)
    found = [r for r in rows if r.outcome.found]
    if not found:
        gave_up = [r.label for r in rows if r.outcome.gave_up]
        if gave_up:
            return f"{expanded}; no path found, {', '.join(gave_up)} stopped at the step limit"
        return f"{expanded}; no path"
    lengths = {r.outcome.length for r in found}
    if len(found) == len(rows) and len(lengths) == 1:
        n = found[0].outcome.length
        paths = f"{'both' if len(rows) == 2 else 'all'} paths have {n} moves"
    else:
        paths = ", ".join(f"{r.label}'s path has {r.outcome.length} moves" if r.outcome.found
                          else f"{r.label} found none" for r in rows)
    return f"{expanded}; {paths}"


__all__ = [
    "LIVE_CELLS",
    "MARKS_KEY",
    "QUOTES",
    "TABLE_HEAD",
    "TUTORIAL_MAP",
    "Contender",
    "TableRow",
    "Verdict",
    "check",
    "comparison",
    "parse_compare",
    "summary_sentence",
    "table_cells",
    "table_lines",
    "tutorial_grid",
]

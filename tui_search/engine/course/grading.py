"""An exercise graded on a map: its searches run, its ``solved`` condition evaluated, and the
edits it does not allow caught (:func:`grade`).

The exercises themselves are files (:mod:`tui_search.engine.course.exercise_file`); the tutorial's
two ship as two of them:

1. "change the location of the target such that Breadth first search will give a faster
   result than depth first search (expand less nodes)": solved when both find the goal and
   BFS expands fewer nodes than DFS.  The exercise moves only the target: a map where more
   changed still counts, with a hint (``other_edits = "hint"``).
2. "Change the orientation of the obstacles, start, and goal such that the results provide
   non-optimal solutions": solved when DFS's path has more moves than BFS's.

Plain Python, no UI: the command line grades a student's file with it, and the app's
challenge panel shows the same figures live.
"""

from __future__ import annotations

from typing import NamedTuple

from tui_search.engine.course.condition import Value, evaluate
from tui_search.engine.course.exercise_file import Exercise
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import MAX_STEPS, Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.registry import get_algorithm

#: Maps bigger than this are not checked at each edit by the app (two whole searches an edit,
#: and a mouse stroke is an edit a cell: benchmarks/README.md, "limits") but in a thread once
#: the edits pause.
LIVE_CELLS = 10_000
_PATH_FIGURES = ("moves", "cost")


class Verdict(NamedTuple):
    """An exercise checked on a map: solved or not, why, and each search's outcome."""

    exercise: Exercise
    solved: bool
    reason: str  # one line in the tutorial's terms
    outcomes: tuple[tuple[str, str, Outcome], ...]  # (the condition's name, label, outcome)
    figures: dict[str, Value | None]  # the condition's SEARCH.FIELD -> its value
    hint: str = ""  # what else changed, when the exercise hints at it (other_edits = "hint")
    graded: bool = True  # False: a search gave up before the end (--max-steps)
    measured: str = ""  # the figures' phrase, when ``reason`` is something else (an edit refused)

    @property
    def said(self) -> str:
        """The reason with the figures: a verdict failed for an edit still shows what the
        searches did, as a teacher needs them most there."""
        return f"{self.reason}; {self.measured}" if self.measured else self.reason

    @property
    def status(self) -> str:
        return "not graded" if not self.graded else "solved" if self.solved else "not solved"

    @property
    def hints(self) -> str:
        """What the app and a one-map grading say under the verdict: the edits' hint, and the
        exercise's own hint while it is not solved."""
        own = self.exercise.hint if not self.solved else ""
        return "; ".join(h for h in (self.hint, own) if h)

    def as_json(self) -> dict[str, object]:
        ex = self.exercise
        runs = {name: _figures(out) for name, _, out in self.outcomes}
        return {"exercise": ex.number if ex.number is not None else ex.path,
                "title": ex.title, "solved": self.solved, "verdict": self.status,
                "reason": self.reason, "hint": self.hints or None,
                "figures": dict(self.figures), **runs}


def _figures(out: Outcome) -> dict[str, Value | None]:
    return {"found": out.found, "moves": out.length,
            "cost": None if out.cost is None else round(out.cost, 6),
            "expanded": out.expanded, "generated": out.generated,
            "max_frontier": out.max_frontier, "gave_up": out.gave_up}


def _possessive(label: str) -> str:
    return label + "'s"


def _same(count: int) -> str:
    return {1: "its", 2: "both"}.get(count, f"all {count}")


def figure_phrase(field: str, runs: list[tuple[str, Outcome]]) -> str:
    """One field of every search in the tutorial's words: "BFS expanded 22 nodes, DFS 7"."""
    labels = [label for label, _ in runs]
    outs = [out for _, out in runs]
    if field in ("expanded", "generated"):
        values = [getattr(o, field) for o in outs]
        return (f"{labels[0]} {field} {values[0]:,} nodes"
                + "".join(f", {la} {v:,}" for la, v in zip(labels[1:], values[1:], strict=True)))
    if field == "max_frontier":
        return (f"{_possessive(labels[0])} frontier peaked at {outs[0].max_frontier:,}"
                + "".join(f", {_possessive(la)} {o.max_frontier:,}"
                          for la, o in zip(labels[1:], outs[1:], strict=True)))
    if field == "found":
        missing = [la for la, o in runs if not o.found]
        if not missing:
            return ("both" if len(runs) == 2 else labels[0] if len(runs) == 1
                    else f"all {len(runs)}") + " found the goal"
        return " and ".join(missing) + " found no path"
    if field == "moves":
        values = [f"{o.length:,}" if o.length is not None else "none" for o in outs]
        unit = "moves"
    else:
        values = [f"{o.cost:.2f}" if o.cost is not None else "none" for o in outs]
        unit = ""
    if len(set(values)) == 1 and len(runs) > 1:
        paths = f"{_same(len(runs))} paths"
        return f"{paths} have {values[0]} moves" if unit else f"{paths} cost {values[0]}"
    first = (f"{_possessive(labels[0])} path has {values[0]} moves" if unit
             else f"{_possessive(labels[0])} path costs {values[0]}")
    return first + "".join(f", {_possessive(la)} {v}"
                           for la, v in zip(labels[1:], values[1:], strict=True))


def changes(grid: Grid, base: Grid) -> list[str]:
    """What ``grid`` changed of the exercise's map ``base``: "size", or any of start, goal,
    obstacles, terrain."""
    if (grid.width, grid.height) != (base.width, base.height):
        return ["size"]
    costs = (list(grid.costs) if grid.costs is not None else None,
             list(base.costs) if base.costs is not None else None)
    return [name for name, differs in (("start", grid.start != base.start),
                                       ("goal", grid.goal != base.goal),
                                       ("obstacles", grid.blocked != base.blocked),
                                       ("terrain", costs[0] != costs[1])) if differs]


def _words(items: list[str]) -> str:
    special = {"size": "the map's size", "roads": "the graph's nodes and roads",
               "closed": "the closed nodes"}
    words = [special.get(i, f"the {i}") for i in items]
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def _not_allowed(exercise: Exercise, grid: Grid | Graph) -> list[str]:
    base = exercise.board
    if isinstance(grid, Grid) != isinstance(base, Grid):
        return ["roads"] if isinstance(base, Graph) else ["size"]
    if isinstance(grid, Graph):
        from tui_search.engine.course.graph_exercise import graph_changes

        assert isinstance(base, Graph)
        return [c for c in graph_changes(grid, base) if c not in exercise.edits]
    assert isinstance(base, Grid)
    changed = changes(grid, base)
    if changed == ["size"]:
        return [] if exercise.edits == {"start", "goal", "obstacles", "terrain"} else changed
    return [c for c in changed if c not in exercise.edits]


def _outcome(grid: Grid | Graph, key: str, semantics: Semantics, max_steps: int) -> Outcome:
    """A search run whole: recorded, or streamed for a bidirectional one (no run records
    it)."""
    algorithm = get_algorithm(key)
    if algorithm.bidirectional:
        from tui_search.engine.search.reference import stream

        return stream(grid, algorithm, semantics, max_steps)
    return Run(grid, key, semantics, max_steps).outcome()


def grade(exercise: Exercise, grid: Grid | Graph, max_steps: int = MAX_STEPS) -> Verdict:
    """``exercise`` on ``grid`` (which has a start and a goal; or on a graph, for an exercise
    on a graph): its searches run whole."""
    runs = [(name, c.label, _outcome(grid, c.algorithm, c.semantics, max_steps))
            for name, c in exercise.searches]
    labelled = [(label, out) for _, label, out in runs]
    figures: dict[str, Value | None] = {}
    for name, _, out in runs:
        for field, value in _figures(out).items():
            figures[f"{name}.{field}"] = value
    figures = {key: figures[key] for key in exercise.fields}
    expanded = figure_phrase("expanded", labelled)
    quitters = [label for label, out in labelled if out.gave_up]
    if quitters:  # not "no path": the map may well have one, further than the steps allowed
        return Verdict(exercise, False, f"{' and '.join(quitters)} gave up at "
                       f"{max_steps:,} steps before finding the goal ({expanded})",
                       tuple(runs), figures, graded=False)
    solved = bool(evaluate(exercise.condition, figures))
    missing = [label for label, out in labelled if not out.found]
    if missing:
        shown = [figure_phrase(f, labelled) for f in exercise.figures
                 if f not in _PATH_FIGURES and f != "found"]
        whose = "" if len(missing) == len(runs) else " for " + " and ".join(missing)
        reason = f"no path to the goal{whose}" + (f" ({'; '.join(shown)})" if shown else "")
    else:
        reason = "; ".join(figure_phrase(f, labelled) for f in exercise.figures)
    hint = ""
    other = _not_allowed(exercise, grid)
    measured = ""
    if other and exercise.other_edits == "fail":
        solved, measured = False, reason
        reason = f"changed {_words(other)}, which the exercise does not allow"
    elif other:
        allowed = _words(sorted(exercise.edits)) if exercise.edits else "nothing"
        hint = f"the exercise changes only {allowed}: here {_words(other)} changed"
    return Verdict(exercise, solved, reason, tuple(runs), figures, hint, measured=measured)


__all__ = ["LIVE_CELLS", "Verdict", "changes", "figure_phrase", "grade"]

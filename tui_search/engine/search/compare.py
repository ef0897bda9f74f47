"""Comparing searches on one map: the searches ``--compare`` names (:func:`parse_compare`)
and the table of their figures, the same in the app's compare mode and in
``--headless --compare``: a row a search, marks on the fewest expanded and the cheapest path,
and the tutorial's sentence.

Plain Python, no UI.
"""

# No future import: CONTRIBUTING.md, "Start-up".
from collections.abc import Sequence
from typing import NamedTuple

from tui_search.engine.search.choices import (
    DEFAULT_SEMANTICS,
    STOP_RULES,
    TURN_RULES,
    Semantics,
)
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.registry import Algorithm, get_algorithm


class Contender(NamedTuple):
    """One search of a comparison: an algorithm and its choices (a heuristic of its own)."""

    algorithm: str
    semantics: Semantics

    @property
    def label(self) -> str:
        """"A*", "A* (manhattan)", "A* (w=2)", "A* (manhattan, w=2)"."""
        algo = get_algorithm(self.algorithm)
        said = []
        if algo.informed and self.semantics.heuristic != DEFAULT_SEMANTICS.heuristic:
            said.append(self.semantics.heuristic)
        if self.semantics.weight != 1.0:
            said.append(f"w={self.semantics.weight:g}")
        if algo.bidirectional and self.semantics.stop != STOP_RULES[0]:
            said.append(self.semantics.stop)
        if algo.bidirectional and self.semantics.turn != TURN_RULES[0]:
            said.append(self.semantics.turn)
        return f"{algo.short} ({', '.join(said)})" if said else algo.short


def parse_compare(text: str, semantics: Semantics = DEFAULT_SEMANTICS,
                  fit: bool = False, fewest: int = 2) -> list[Contender]:
    """``bfs,dfs`` or ``astar:manhattan,ucs``: ``fewest`` (two; the app's panes: one) to four
    registry keys, each informed one with an optional heuristic, A* with an optional weight
    (``astar:w=2``, ``astar:manhattan:w=2``; else the given choices' weight), a bidirectional
    one with its stopping rule and turn (``biastar:first-meeting``, ``bibfs:smaller``).
    ``ValueError``
    (one line) for anything else -- or, with ``fit``, for a choice that does not apply to one
    of them, that one takes the default instead (:meth:`~tui_search.engine.search.choices.Semantics.
    fitted`: the app's settings apply to every pane where they can)."""
    from tui_search.engine.search.heuristics import HEURISTICS

    parts = [p.strip() for p in text.split(",") if p.strip()]
    if not fewest <= len(parts) <= 4:
        words = {1: "one", 2: "two"}.get(fewest, str(fewest))
        raise ValueError(f"compare {words} to four searches, not {len(parts)} ({text!r})")
    out = []
    for part in parts:
        key, *extras = part.split(":")
        algo = get_algorithm(key)
        sem, extras = _stop_of(part, algo, semantics, extras)
        heuristic = ""
        for extra in extras:
            if extra.startswith("w="):
                if algo.priority != "g+h":
                    raise ValueError(f"{part!r}: a weight applies to astar only, not {key}")
                try:
                    sem = sem.replace(weight=float(extra[2:]))
                except ValueError:
                    raise ValueError(f"{part!r}: the weight is a number 1 or more") from None
            elif heuristic:
                raise ValueError(f"{part!r}: one heuristic, then w=W")
            else:
                heuristic = extra
        if sem.weight != 1.0 and algo.priority != "g+h" and not extras:
            sem = sem.replace(weight=1.0)  # the choices' weight is A*'s alone
        if heuristic:
            if not algo.informed:
                raise ValueError(f"{part!r}: {key} uses no heuristic")
            if heuristic not in HEURISTICS:
                raise ValueError(f"{part!r}: unknown heuristic (use {', '.join(HEURISTICS)})")
            sem = sem.replace(heuristic=heuristic)
        try:
            sem.check(algo)
        except ValueError:
            if not fit:
                raise
            sem = sem.fitted(algo)
        out.append(Contender(key, sem))
    return out


def _stop_of(part: str, algo: Algorithm, sem: Semantics, extras: list[str]
             ) -> tuple[Semantics, list[str]]:
    """The choices with ``part``'s stopping rule and turn (a bidirectional search's: the
    choices' own are theirs alone), and its other extras."""
    rules = [extra for extra in extras if extra in STOP_RULES + TURN_RULES]
    if rules and not algo.bidirectional:
        raise ValueError(f"{part!r}: a stopping rule or a turn applies to bibfs, biucs, "
                         f"biastar only, not {algo.key}")
    if not algo.bidirectional:
        return sem.replace(stop=STOP_RULES[0], turn=TURN_RULES[0]), extras
    for extra in rules:
        sem = sem.replace(**{"stop" if extra in STOP_RULES else "turn": extra})
    return sem, [extra for extra in extras if extra not in rules]


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
            for label, o in zip(labels, outcomes, strict=True)]


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
    return ["  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip()
            for row in cells]


def summary_sentence(rows: list[TableRow], terrain: bool = False) -> str:
    """In the tutorial's terms: "DFS expanded 7 nodes, BFS 22; both paths have 7 moves".  On
    a map with ``terrain`` each path's cost too, where the costs differ: "BFS's path has 7
    moves, cost 32.11; UCS's 8 moves, cost 9.24" -- the fewest moves is not the cheapest."""
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
    costs = {round(r.outcome.cost or 0.0, 6) for r in found}
    if terrain and len(costs) > 1:
        said: list[str] = []
        for r in rows:
            o = r.outcome
            what = f"{o.length or 0:,} moves, cost {o.cost or 0.0:.2f}"
            said.append(f"{r.label} found none" if not o.found else
                        f"{r.label}'s {what}" if said else f"{r.label}'s path has {what}")
        paths = "; ".join(said)
    elif len(found) == len(rows) and len(lengths) == 1:
        n = found[0].outcome.length
        paths = f"{'both' if len(rows) == 2 else 'all'} paths have {n or 0:,} moves"
    else:
        paths = ", ".join(f"{r.label}'s path has {r.outcome.length or 0:,} moves" if r.outcome.found
                          else f"{r.label} found none" for r in rows)
    return f"{expanded}; {paths}"


__all__ = [
    "MARKS_KEY",
    "TABLE_HEAD",
    "Contender",
    "TableRow",
    "comparison",
    "parse_compare",
    "summary_sentence",
    "table_cells",
    "table_lines",
]

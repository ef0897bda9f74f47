"""Checking a trace (:mod:`~tui_search.engine.traces.read`) against one of the app's searches,
step by step: the first expansion or the first successor list that differs, in words a
student can act on.

The reference is the app's own recorded :class:`~tui_search.engine.run.recorded.Run`, read through
its named queries.  A search that visits on expand takes cells off the frontier that it has already
expanded and does nothing with them (a *discarded* step): a trace may list those pops (with
``"discarded": true`` or with no successors) or leave them out, and both match.  Steps are numbered
as the trace numbers them (its own expansion lines).
"""

from __future__ import annotations

from dataclasses import dataclass

from tui_search.engine.maps.grid import DELTAS, Cell, Grid
from tui_search.engine.run.recorded import Run, Step
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.registry import Algorithm, Frontier, get_algorithm
from tui_search.engine.traces.read import Trace, TraceStep, show

#: How far ahead the check looks for the step at which the reference expands a cell.
LOOK_AHEAD = 100_000
#: The steps a check records at first (then twice as many each time, for the compiled core):
#: most candidates a diagnosis tries part from the trace within a few steps.
FIRST_CHUNK = 32


def choices_text(algo: Algorithm, semantics: Semantics) -> str:
    """The search and its choices in a few words: "BFS (order N,W,S,E; visit on generate; goal
    test on generate)"."""
    parts = [f"order {','.join(semantics.order)}"]
    if semantics.tree_search:
        parts.append("tree search")
    elif not (algo.iterative or algo.weighted):
        parts.append(f"visit on {semantics.visit}")
    parts.append(f"goal test on {semantics.goal_test_for(algo)}")
    if semantics.corners != "always":
        parts.append(f"corners {semantics.corners}")
    if algo.informed:
        parts.append(f"heuristic {semantics.heuristic}")
    return f"{algo.short} ({'; '.join(parts)})"


@dataclass(frozen=True)
class Difference:
    """The first place the trace parts from the search: its step (the trace's numbering), the
    trace line, what kind (``expand``, ``successors``, ``ends``, ``goes_on``), the sentence, and
    the cells the search expected and the trace had (None where it has none)."""

    step: int
    line: int | None
    kind: str
    message: str
    expected: Cell | None = None
    got: Cell | None = None
    #: The search parts from the trace at a tie of its priority: "h" where the trace took
    #: the lower or higher h of an f tie, "entry" where it took another entry; "" no tie.
    tie: str = ""

    def as_json(self) -> dict[str, object]:
        return {"step": self.step, "line": self.line, "kind": self.kind,
                "message": self.message,
                "expected": None if self.expected is None else list(self.expected),
                "got": None if self.got is None else list(self.got), "tie": self.tie or None}


@dataclass(frozen=True)
class Verdict:
    """How a trace compares with one search: the steps matched before the first difference
    (all of them when there is none)."""

    algorithm: str
    semantics: Semantics
    steps: int  # the trace's expansions
    matched: int
    difference: Difference | None
    #: What the search is called when not by its choices ("a recursive DFS (order S,E,N,W)").
    label: str = ""
    #: The search's discarded pops the trace left out, before the difference: each the index
    #: of the trace's step it came before (the trace's length: after its last) and its cell.
    left_out: tuple[tuple[int, Cell], ...] = ()

    @property
    def matches(self) -> bool:
        return self.difference is None

    @property
    def choices(self) -> str:
        return self.label or choices_text(get_algorithm(self.algorithm), self.semantics)

    def text(self) -> str:
        """The verdict in words, a line or two."""
        if self.difference is None:
            return f"matches {self.choices} for all {self.steps} steps"
        lines = [self.difference.message]
        span = {0: "no step matches", 1: "step 1 matches"}.get(
            self.matched, f"steps 1-{self.matched} match")
        lines.append(f"  ({span} {self.choices})")
        return "\n".join(lines)

    def as_json(self) -> dict[str, object]:
        algo = get_algorithm(self.algorithm)
        return {"verdict": "match" if self.matches else "difference",
                "algorithm": self.algorithm, "search": self.choices,
                "choices": self.semantics.as_json(algo),
                "steps": self.steps, "matched_steps": self.matched,
                "first_difference": None if self.difference is None
                else self.difference.as_json()}


def _next_words(algo: Algorithm) -> str:
    """Where the search takes its next node from: "the queue's front"."""
    if algo.frontier is Frontier.PRIORITY:
        return f"the lowest {algo.priority_name} in the priority queue"
    return f"the {algo.frontier.noun}'s {algo.frontier.next_end}"


class _Checker:
    """One comparison: the trace's steps against the run's, in lockstep."""

    def __init__(self, trace: Trace, run: Run, look_ahead: int) -> None:
        self.trace, self.run, self.look_ahead = trace, run, look_ahead
        self.algo = run.algo
        self.name = run.algo.short
        self.counts_discarded: bool | None = None  # does the trace list the discarded pops?
        self.left_out: list[tuple[int, Cell]] = []  # the discarded pops it did not list

    def engine_step(self, k: int) -> Step | None:
        run = self.run
        if k > run.recorded and not run.done:
            run.advance(k)
        return run.steps.at(k) if k <= run.recorded else None

    def later_step(self, n: int, k: int, cell: Cell) -> int | None:
        """The trace's step number at which the search would expand ``cell``, looking from
        its step ``k`` (the trace's step ``n``); None when it never does (soon)."""
        at = n
        for k2 in range(k, k + self.look_ahead):
            step = self.engine_step(k2)
            if step is None:
                return None
            if step.discarded:
                at += 1 if self.counts_discarded else 0
                continue
            if step.node == cell and k2 > k:
                return at
            at += 1
        return None

    def expand_difference(self, n: int, k: int, t: TraceStep, e: Step) -> Difference:
        later = self.later_step(n, k, t.node)
        if later is not None:
            where = f"which {self.name} would expand at step {later}"
        elif self.run.done and not self.run.gave_up and self.look_ahead:
            where = f"which {self.name} never expands"
        else:
            where = (f"which {self.name} does not expand in its first "
                     f"{self.run.recorded:,} steps")
        tie, tie_kind = self.tie_words(k, e, t) if self.algo.priority is not None else ("", "")
        return Difference(n, t.line, "expand",
                          f"step {n}: {self.name} expands {show(e.node)} next "
                          f"({_next_words(self.algo)}); your trace expands {show(t.node)}, "
                          f"{where}{tie}", e.node, t.node, tie_kind)

    def tie_words(self, k: int, e: Step, t: TraceStep) -> tuple[str, str]:
        """When the cell the trace took ties with the search's on its priority: "; f ties
        at 4.83: your trace took the lower h (1.00, not 2.00)" and the kind of tie ("h" or
        "entry"); ("", "") when they do not tie."""
        run = self.run
        run.goto(k - 1)
        now, cell, costs = run.now, run.nodes.cell, run.nodes.costs
        mine = theirs = None
        for g in now.frontier():
            if now.is_stale(g):
                continue
            if mine is None and cell(g) == t.node:
                mine = costs(g)
            if theirs is None and cell(g) == e.node:
                theirs = costs(g)
        if mine is None or theirs is None or abs(mine[2] - theirs[2]) > 1e-9:
            return "", ""
        name = self.algo.priority_name
        words = f"; {name} ties at {theirs[2]:.2f}: your trace took "
        if name == "f" and abs(mine[1] - theirs[1]) > 1e-9:
            lower = "lower" if mine[1] < theirs[1] else "higher"
            return words + f"the {lower} h ({mine[1]:.2f}, not {theirs[1]:.2f})", "h"
        return words + f"another entry ({self.name} takes the oldest of a tie)", "entry"

    def successor_difference(self, n: int, t: TraceStep, e: Step) -> Difference | None:
        got, want = list(t.successors), [c for _, c in e.successors]
        if got == want:
            return None
        name = self.name

        def diff(message: str, expected: Cell | None, cell: Cell | None) -> Difference:
            return Difference(n, t.line, "successors", f"step {n}: {message}", expected, cell)

        seen: set[Cell] = set()
        for c in got:
            if c in seen:
                return diff(f"your trace added {show(c)} twice", None, c)
            seen.add(c)
        for c in got:
            if c not in want:
                return diff(f"your trace added {show(c)}, which {name} does not add from "
                            f"{show(t.node)} ({self._why_not(t.node, c)})", None, c)
        for c in want:
            if c not in seen:
                return diff(f"{name} adds {show(c)} from {show(t.node)}; your trace does not",
                            c, None)
        first = next(i for i, (a, b) in enumerate(zip(got, want, strict=True)) if a != b)
        order = ",".join(self.run.semantics.order)
        return diff(f"your trace added {', '.join(map(show, got))}; {name} adds "
                    f"{', '.join(map(show, want))} (order {order}): {show(want[first])} "
                    f"before {show(got[first])}", want[first], got[first])

    def _why_not(self, node: Cell, cell: Cell) -> str:
        delta = (cell[0] - node[0], cell[1] - node[1])
        move = next((d for d, v in DELTAS.items() if v == delta), None)
        if move is None:
            return "it is not one move away"
        if move not in self.run.semantics.order:
            return f"move {move} is not in order {','.join(self.run.semantics.order)}"
        return "it was reached already, or the corner rule refuses it"

    def check(self) -> Verdict:
        steps = self.trace.steps
        k = 1
        for i, t in enumerate(steps):
            n = i + 1
            e = self.engine_step(k)
            while e is not None and e.discarded and not (e.node == t.node and not t.successors):
                self.counts_discarded = False if self.counts_discarded is None else \
                    self.counts_discarded
                self.left_out.append((i, e.node))
                k += 1
                e = self.engine_step(k)
            if e is None:
                return self.verdict(i, Difference(
                    n, t.line, "goes_on",
                    f"step {n}: your trace expands {show(t.node)}; {self.name} has stopped "
                    f"after its step {k - 1} ({self._why_stopped()})", None, t.node))
            if e.discarded:  # the trace lists the pop that did nothing
                self.counts_discarded = True
                k += 1
                continue
            if t.discarded:
                return self.verdict(i, Difference(
                    n, t.line, "expand",
                    f"step {n}: your trace discards {show(t.node)}; {self.name} expands "
                    f"{show(e.node)} (a cell it has not expanded before)", e.node, t.node))
            if e.node != t.node:
                return self.verdict(i, self.expand_difference(n, k, t, e))
            wrong = self.successor_difference(n, t, e)
            if wrong is not None:
                return self.verdict(i, wrong)
            k += 1
        e = self.engine_step(k)
        while e is not None and e.discarded:
            self.left_out.append((len(steps), e.node))
            k += 1
            e = self.engine_step(k)
        if e is not None:
            n = len(steps)
            return self.verdict(n, Difference(
                n + 1, None, "ends",
                f"step {n + 1}: your trace ends after step {n}; {self.name} goes on and "
                f"expands {show(e.node)} ({_next_words(self.algo)})", e.node, None))
        return self.verdict(len(steps), None)

    def _why_stopped(self) -> str:
        run = self.run
        if run.found:
            return f"it found the goal, tested on {run.goal_test}"
        return "it gave up" if run.gave_up else "its frontier was empty"

    def verdict(self, matched: int, difference: Difference | None) -> Verdict:
        return Verdict(self.run.algorithm, self.run.semantics, len(self.trace.steps), matched,
                       difference, left_out=tuple(self.left_out))


def check_trace(trace: Trace, grid: Grid, algorithm: str, semantics: Semantics,
                max_steps: int | None = None, look_ahead: int = LOOK_AHEAD) -> Verdict:
    """Compare ``trace`` with ``algorithm`` under ``semantics`` on ``grid``, step by step
    (``look_ahead``: how many of the search's steps to look through for the step at which it
    would expand the cell the trace took instead; 0 leaves that out)."""
    limit = max_steps if max_steps is not None else 4 * len(trace.steps) + LOOK_AHEAD
    return _Checker(trace, Run(grid, algorithm, semantics, limit, first_chunk=FIRST_CHUNK),
                    look_ahead).check()


__all__ = ["Difference", "Verdict", "check_trace", "choices_text"]

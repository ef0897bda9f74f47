"""Checking a trace (:mod:`~tui_search.engine.traces.read`) against one of the app's searches,
step by step: the first expansion or the first successor list that differs, with its cause in a
sentence a student can act on (:mod:`~tui_search.engine.traces.differences`).

The reference is the app's own recorded :class:`~tui_search.engine.run.recorded.Run`, read through
its named queries.  What a trace may leave out or add and still match:

* a search that visits on expand takes cells off the frontier that it has already expanded and
  does nothing with them (a *discarded* step): a trace may list those pops (with
  ``"discarded": true`` or with no successors) or leave them out;
* the goal's pop: a trace may end with the goal's line or without it (the search that tests
  the goal when it takes it off ends with it; the one that tests it when it adds it, without);
* successors: a trace whose lines list none (*expansions only*, as a course's autograder
  records the states passed to the successor function) is checked against the order of the
  expansions alone, and its verdict says what could not be checked.

Steps are numbered as the trace numbers them: its own expansion lines, from 1.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run, Step
from tui_search.engine.search.choices import (
    RECURSIVE_WORDS,
    VISIT_WORDS,
    Semantics,
    order_words,
)
from tui_search.engine.search.registry import Algorithm, get_algorithm
from tui_search.engine.search.state import State
from tui_search.engine.traces.causes import TRACE_VOICE, Difference, Voice
from tui_search.engine.traces.differences import Causes
from tui_search.engine.traces.read import Trace, TraceStep, show
from tui_search.engine.traces.ties import TIE_ORDER

#: How far ahead the check looks for the step at which the reference expands a cell.
LOOK_AHEAD = 100_000
#: The steps a check records at first (then twice as many each time, for the compiled core):
#: most candidates a diagnosis tries part from the trace within a few steps.
FIRST_CHUNK = 32
#: The same for the loop of the choices of published code, which records the reference's steps
#: (so a step costs more) and keeps the chunk's size.
FIRST_PUBLISHED = 8

#: What a verdict notes of a trace that matched with a part left out.
GOAL_LEFT_OUT = "your trace leaves out the goal's pop, this search's last step (a trace may)"
GOAL_LISTED = "your trace lists the goal's pop, which this search stops before (a trace may)"
EXPANSIONS_ONLY = ("your trace lists no successors: only the order of its expansions is "
                   "checked, not what each step added")
#: The notes a check makes of the trace (said once, of the first search listed).
ALL_NOTES = (GOAL_LEFT_OUT, GOAL_LISTED, EXPANSIONS_ONLY)


def choices_text(algo: Algorithm, semantics: Semantics) -> str:
    """The search and its choices in a student's words: "BFS (order N,W,S,E; visit on
    generate; goal test on generate)", "A* (manhattan; ties: smallest cell first; no
    re-opening; order N,E,S,W; goal test on expand)", "a recursive DFS (order E,S,W,N; a line
    lists the calls; goal test on generate)"."""
    parts = [semantics.heuristic] if algo.informed else []
    parts += semantics.published_words()
    parts.append(f"order {order_words(semantics)}")
    if semantics.recursive:
        parts.append(RECURSIVE_WORDS[semantics.recursive])
    if semantics.tree_search:
        parts.append("tree search" if semantics.path_check else "tree search, no path check")
    elif not (algo.iterative or algo.weighted or semantics.recursive):
        parts.append(VISIT_WORDS[semantics.visit])
    parts.append(f"goal test on {semantics.goal_test_for(algo)}")
    if semantics.corners != "always":
        parts.append(f"corners {semantics.corners}")
    name = f"a recursive {algo.short}" if semantics.recursive else algo.short
    return f"{name} ({'; '.join(parts)})"


@dataclass(frozen=True)
class Verdict:
    """How a trace compares with one search: the steps matched before the first difference
    (all of them when there is none)."""

    algorithm: str
    semantics: Semantics
    steps: int  # the trace's expansions
    matched: int
    difference: Difference | None
    #: What the search is called when not by its choices.
    label: str = ""
    #: The search's discarded pops the trace left out, before the difference: each the index
    #: of the trace's step it came before (the trace's length: after its last) and its cell.
    left_out: tuple[tuple[int, State], ...] = ()
    #: What the trace left out or added and still matched, or could not be checked.
    notes: tuple[str, ...] = ()

    @property
    def matches(self) -> bool:
        return self.difference is None

    @property
    def choices(self) -> str:
        return self.label or choices_text(get_algorithm(self.algorithm), self.semantics)

    def text(self) -> str:
        """The verdict in words, a line or a few."""
        if self.difference is None:
            lines = [f"matches {self.choices} for all {self.steps} steps"]
        else:
            span = {0: "no step matches", 1: "step 1 matches"}.get(
                self.matched, f"steps 1-{self.matched} match")
            lines = [self.difference.message, f"  ({span} {self.choices})"]
        return "\n".join(lines + [f"  note: {note}" for note in self.notes])

    def as_json(self) -> dict[str, object]:
        algo = get_algorithm(self.algorithm)
        return {"verdict": "match" if self.matches else "difference",
                "algorithm": self.algorithm, "search": self.choices,
                "choices": self.semantics.as_json(algo),
                "steps": self.steps, "matched_steps": self.matched,
                "first_difference": None if self.difference is None
                else self.difference.as_json(), "notes": list(self.notes)}


class _Checker:
    """One comparison: the trace's steps against the run's, in lockstep."""

    def __init__(self, trace: Trace, run: Run, look_ahead: int,
                 voice: Voice = TRACE_VOICE) -> None:
        self.trace, self.run, self.look_ahead = trace, run, look_ahead
        self.algo = run.algo
        self.name = f"this {run.algo.short}" if run.semantics.recursive else run.algo.short
        self.causes = Causes(trace, run, self.name, voice)
        self.counts_discarded: bool | None = None  # does the trace list the discarded pops?
        self.left_out: list[tuple[int, State]] = []  # the discarded pops it did not list
        self.notes: list[str] = []
        if trace.steps and trace.expansions_only:
            self.notes.append(EXPANSIONS_ONLY)

    def engine_step(self, k: int) -> Step | None:
        run = self.run
        if k > run.recorded and not run.done:
            run.advance(k)
        return run.steps.at(k) if k <= run.recorded else None

    def later_step(self, n: int, k: int, cell: State) -> int | None:
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
        return self.causes.expansion(n, t, e, k, where)

    def check(self) -> Verdict:
        steps = self.trace.steps
        k = 1
        for i, t in enumerate(steps):
            n = i + 1
            e = self.next_step(k, i, t)
            if e is None:
                if n == len(steps) and self.goal_pop(t):
                    self.notes.append(GOAL_LISTED)
                    return self.verdict(n, None)
                return self.verdict(i, Difference(
                    n, t.line, "goes_on",
                    f"step {n}: your trace expands {show(t.node)}; {self.name} has stopped "
                    f"after its step {self.run.recorded} ({self._why_stopped()})", None, t.node,
                    suggest=self._goes_on_suggests(), cause="goes-on"))
            k = e.index
            if e.discarded:  # the trace lists the pop that did nothing
                self.counts_discarded = True
                k += 1
                continue
            if t.discarded:
                return self.verdict(i, Difference(
                    n, t.line, "expand",
                    f"step {n}: your trace discards {show(t.node)}; {self.name} expands "
                    f"{show(e.node)} (a cell it has not expanded before)", e.node, t.node,
                    cause="discarded"))
            if e.node != t.node:
                return self.verdict(i, self.expand_difference(n, k, t, e))
            wrong = self.causes.successors(n, t, e) if t.listed else None
            if wrong is not None:
                return self.verdict(i, wrong)
            k += 1
        e = self.next_step(k, len(steps), None)
        if e is not None:
            n = len(steps)
            if self.engine_step(e.index + 1) is None and e.found_goal and not e.successors:
                self.notes.append(GOAL_LEFT_OUT)
                return self.verdict(n, None)
            return self.verdict(n, Difference(
                n + 1, None, "ends",
                f"step {n + 1}: your trace ends after step {n}; {self.name} goes on and "
                f"expands {show(e.node)} ({self.causes._next_words()})", e.node, None,
                suggest=self._ends_suggests(), cause="ends"))
        return self.verdict(len(steps), None)

    def next_step(self, k: int, i: int, t: TraceStep | None) -> Step | None:
        """The search's step from ``k`` on that the trace's step ``i`` (``t``; None: after its
        last) stands for: its discarded pops skipped (noted as left out) unless the trace
        lists this one (its cell, nothing added)."""
        e = self.engine_step(k)
        while e is not None and e.discarded and not (
                t is not None and e.node == t.node and not t.successors):
            if self.counts_discarded is None:
                self.counts_discarded = False
            self.left_out.append((i, e.node))
            k += 1
            e = self.engine_step(k)
        return e

    def goal_pop(self, t: TraceStep) -> bool:
        """Is ``t``, after the search stopped, the goal's pop (the goal, nothing added) of a
        search that found the goal?"""
        return self.run.found and t.node == self.run.goal and not t.successors

    def _goes_on_suggests(self) -> tuple[tuple[tuple[str, object], ...], ...]:
        if self.run.found and self.run.goal_test == "generate":
            return ((("goal_test", "expand"),),)
        return ()

    def _ends_suggests(self) -> tuple[tuple[tuple[str, object], ...], ...]:
        if self.run.goal_test == "expand":
            return ((("goal_test", "generate"),),)
        return ()

    def _why_stopped(self) -> str:
        run = self.run
        if run.found:
            return f"it found the goal, tested on {run.goal_test}"
        return "it gave up" if run.gave_up else "its frontier was empty"

    def verdict(self, matched: int, difference: Difference | None) -> Verdict:
        return Verdict(self.run.algorithm, self.run.semantics, len(self.trace.steps), matched,
                       difference, left_out=tuple(self.left_out), notes=tuple(self.notes))


def check_trace(trace: Trace, grid: Grid | Graph, algorithm: str, semantics: Semantics,
                max_steps: int | None = None, look_ahead: int = LOOK_AHEAD,
                voice: Voice = TRACE_VOICE) -> Verdict:
    """Compare ``trace`` with ``algorithm`` under ``semantics`` on ``grid``, step by step
    (``look_ahead``: how many of the search's steps to look through for the step at which it
    would expand the cell the trace took instead; 0 leaves that out; ``voice``: whom the
    sentences speak of, the trace's author by default)."""
    limit = max_steps if max_steps is not None else 4 * len(trace.steps) + LOOK_AHEAD

    def checked(sem: Semantics, ahead: int, tie_order: tuple[str, ...] = TIE_ORDER) -> Verdict:
        # The loop of the published choices pauses every first chunk's steps all along: a
        # few at first, as most candidates part within them.
        first = FIRST_CHUNK if sem.plain else FIRST_PUBLISHED
        checker = _Checker(trace, Run(grid, algorithm, sem, limit, first_chunk=first), ahead,
                           voice)
        checker.causes.tie_order = tie_order
        return checker.check()

    verdict = checked(semantics, look_ahead)
    difference = verdict.difference
    if difference is not None and difference.cause == "out-of-turn" and look_ahead \
            and trace.expansions_only and semantics.visit == "generate" \
            and not (semantics.tree_search or semantics.recursive):
        return _visit_named(verdict, checked)
    if difference is None or difference.cause != "tie" or len(difference.suggest) < 2 \
            or not look_ahead:
        return verdict
    # Several tie rules take the trace's cell here: the sentence names the one under which
    # the trace matches longest (a sorted list's newest entry may be the smallest cell too).
    rules = [str(dict(s)["ties"]) for s in difference.suggest]
    longest = {r: checked(semantics.replace(ties=r), 0).matched for r in rules}
    best = sorted(rules, key=lambda r: -longest[r])
    if best[0] == rules[0]:
        return verdict
    return checked(semantics, look_ahead, (*best, *(r for r in TIE_ORDER if r not in best)))


def _visit_named(verdict: Verdict, checked: Callable[[Semantics, int], Verdict]) -> Verdict:
    """An expansions-only trace taken out of turn by a search visiting on generate: where a
    search visiting on expand goes on with it longer, the difference says so (a course's
    autograder records exactly such searches)."""
    difference = verdict.difference
    assert difference is not None
    for visit in ("expand", "expand-again"):
        if checked(verdict.semantics.replace(visit=visit), 0).matched > verdict.matched:
            flag = f"--visit {visit}"
            words = (f"; a search that marks cells visited when it takes them off goes on as "
                     f"yours does ({flag})")
            return replace(verdict, difference=replace(
                difference, message=difference.message + words, cause="visit-on-expand",
                suggest=((("visit", visit),),)))
    return verdict


__all__ = ["Difference", "Verdict", "check_trace", "choices_text"]

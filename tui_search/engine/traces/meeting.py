"""Checking a student's bidirectional search (``--check-trace FILE -a bibfs``) against the
reference's (:mod:`~tui_search.engine.search.bidirectional.loop`), its stopping rule included:
the trace's steps, one a line in the order taken (forward, backward, forward, ...), each the
node taken off and the successors it added (backward: the cells a move reaches it from).

The reference runs under both stopping rules, so a trace that matches the other rule's steps
is said to (the commonest slip: stopping at the first meeting); a trace that stops early or
goes on is told where the rule stops and why; a difference is the first step that differs,
with whose turn it was.  Steps are numbered as the trace numbers its expansion lines.

**Without -a** (:func:`diagnose_trace`), a trace that *looks bidirectional*
(:attr:`~tui_search.engine.traces.read.Trace.bidirectional`, read with ``both_ways=None``: a
line says ``"dir": "backward"`` or, its successors listed, a line expands a goal that no
earlier line added, the backward search's root -- which no one-directional search from the
start takes off) is diagnosed as any other trace
(:func:`~tui_search.engine.traces.diagnose.diagnose`) and checked against bibfs, biucs and
biastar (with each heuristic) too, under both turn and both stopping rules, with the move orders
its steps allow (:func:`~tui_search.engine.traces.orders.bidirectional_orders`) and, a diagonal
among them, each corner rule; each candidate runs beside the trace until its first difference.
The whole matches are named (one a search, stopping rule and turn rule); when none matches, the
one that matches longest, with this check's sentences.  A one-directional trace is diagnosed
exactly as before: the rule costs nothing."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, replace

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.bidirectional.loop import BidirectionalSearch
from tui_search.engine.search.choices import (
    CORNER_RULES,
    STOP_RULES,
    TURN_RULES,
    Semantics,
    order_words,
)
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.registry import BIDIRECTIONAL, get_algorithm
from tui_search.engine.search.rules import Expansion
from tui_search.engine.search.state import State, state_json
from tui_search.engine.traces.check import ALL_NOTES, Verdict
from tui_search.engine.traces.diagnose import Diagnosis, diagnose
from tui_search.engine.traces.orders import bidirectional_orders, order_notes
from tui_search.engine.traces.read import Trace, TraceStep, show


class MeetingVerdict:
    """What the check found: ``matches``, the trace's ``steps``, those ``matched`` before
    the first difference, the ``cause`` in a few words ("" on a match), the sentences, and
    the ``first`` difference as a one-directional check's JSON gives it (None on a match):
    its ``step``, ``line``, ``kind`` (``expand``, ``successors``, ``ends``, ``goes_on``),
    ``cause``, ``message`` (the first sentence), ``expected`` and ``got`` cells, ``tie``."""

    def __init__(self, algorithm: str, search: str, matches: bool, steps: int, matched: int,
                 cause: str, lines: list[str], first: dict[str, object] | None = None
                 ) -> None:
        self.algorithm, self.search, self.matches = algorithm, search, matches
        self.steps, self.matched, self.cause, self.lines = steps, matched, cause, lines
        self.first = first

    def text(self) -> str:
        return "\n".join(self.lines)

    def as_json(self) -> dict[str, object]:
        return {"algorithm": self.algorithm, "search": self.search, "matches": self.matches,
                "steps": self.steps, "matched_steps": self.matched,
                "cause": self.cause or None, "first_difference": self.first,
                "text": self.text()}


def _reference(board: Grid | Graph, key: str, semantics: Semantics, most: int
               ) -> tuple[list[Expansion], BidirectionalSearch]:
    """The reference's first ``most`` steps (all of them when it stops sooner)."""
    search = BidirectionalSearch(board, get_algorithm(key), semantics)
    steps = []
    for step in search:
        steps.append(step)
        if len(steps) >= most:
            break
    return steps, search


def same_step(t: TraceStep, e: Expansion) -> bool:
    """Is the trace's step the reference's: the node taken off, and the successors added
    where the trace lists them?"""
    return t.node == e.node.cell and (
        not t.listed or tuple(t.successors) == tuple(s.cell for s in e.successors))


def _first_difference(trace: Sequence[TraceStep], steps: list[Expansion]) -> int | None:
    """The index of the first step that differs, within the shorter of the two (None: one is
    the other's beginning)."""
    for i, (t, e) in enumerate(zip(trace, steps, strict=False)):
        if not same_step(t, e):
            return i
    return None


def _met_on_expand(board: Grid | Graph, key: str, semantics: Semantics,
                    t_steps: Sequence[TraceStep], most: int) -> str | None:
    """Why the trace stopped, when it is a search that tests the meeting on taking a cell
    off (None: it is not)."""
    search = BidirectionalSearch(board, get_algorithm(key), semantics, meet_on_expand=True)
    steps: list[Expansion] = []
    for step in search:
        steps.append(step)
        if len(steps) >= most:
            return None
    if len(steps) != len(t_steps) or _first_difference(t_steps, steps) is not None:
        return None
    return search.why()


def check_bidirectional(trace: Trace, board: Grid | Graph, key: str, semantics: Semantics,
                        max_steps: int) -> MeetingVerdict:
    """``trace`` against ``key`` (bibfs, biucs, biastar) under ``semantics``, its stopping
    rule the one to meet."""
    algo = get_algorithm(key)
    chosen = semantics.stop
    other = STOP_RULES[1] if chosen == STOP_RULES[0] else STOP_RULES[0]
    t_steps = trace.steps
    most = min(len(t_steps) + 1, max_steps)
    ref, search = _reference(board, key, semantics, most)
    alt, alt_search = _reference(board, key, semantics.replace(stop=other), most)
    name = f"{algo.short} (stop: {chosen})"
    n = len(t_steps)
    diff = _first_difference(t_steps, ref)

    def verdict(matches: bool, matched: int, cause: str, *lines: str, at: int = 0,
                kind: str = "", got: State | None = None, expected: State | None = None
                ) -> MeetingVerdict:
        first = None if matches else {
            "step": at, "line": t_steps[at - 1].line if at <= n else None, "kind": kind,
            "cause": cause, "message": lines[0],
            "expected": None if expected is None else state_json(expected),
            "got": None if got is None else state_json(got), "tie": None}
        return MeetingVerdict(key, name, matches, n, matched, cause, list(lines), first)

    if diff is None and n == len(ref):
        return verdict(True, n, "", f"match: your trace is {name} step for step ({n:,} "
                       f"steps), and it stops where the rule does: {search.why()}")
    matched = min(n, len(ref)) if diff is None else diff
    if _first_difference(t_steps, alt) is None and n == len(alt):  # the other rule's run
        if chosen == STOP_RULES[0]:  # it stopped at the first meeting
            return verdict(False, matched, "stopping rule", f"difference at step {n:,}: your "
                           f"search stops at the first meeting: {alt_search.why()}", f"{name} "
                           "goes on until the best meeting is proven the cheapest: the first "
                           "meeting need not be", at=n, kind="ends")
        return verdict(False, matched, "stopping rule", f"difference at step {len(ref):,}: "
                       f"{name} stops there ({search.why()}); your search goes on, as proven "
                       f"does: {alt_search.why()}", at=len(ref), kind="goes_on")
    slip = _met_on_expand(board, key, semantics, t_steps, most)
    if slip is not None:  # the classroom slip: the meeting tested when a cell is taken off
        return verdict(False, matched, "stopping rule", f"difference at step {n:,}: your "
                       f"search tests the meeting when it takes a cell off: {slip}", f"{name} "
                       "tests it when it pushes one (meeting on generation), "
                       + ("and stops at the first meeting" if chosen != STOP_RULES[0] else
                          "and stops once the best meeting is proven the cheapest"),
                       at=n, kind="ends")
    if diff is None:
        if n < len(ref):
            return verdict(False, n, "ends early", f"difference at step {n + 1}: your trace "
                           f"ends after step {n:,}; {name} goes on (step {n + 1} is the "
                           f"{ref[n].direction} search's)", at=n + 1, kind="ends")
        return verdict(False, len(ref), "goes on", f"difference at step {len(ref) + 1}: "
                       f"{name} stops after step {len(ref):,} ({search.why()}); your trace "
                       f"goes on to step {n:,}", at=len(ref) + 1, kind="goes_on")
    t, e = t_steps[diff], ref[diff]
    line = f"difference at step {diff + 1} (line {t.line}): "
    if t.node != e.node.cell:
        text = (f"{line}your search took off {show(t.node)}; {name} takes off "
                f"{show(e.node.cell)}, the {e.direction} search's turn")
        later = ref[diff + 1] if diff + 1 < len(ref) else None
        if later is not None and later.node.cell == t.node:
            rule = ("one step each in turn, forward first" if semantics.turn == "alternate"
                    else "the step of the one whose frontier is smaller, forward on a tie")
            return verdict(False, diff, "turn", text, "your search takes the other search's "
                           f"step: the two searches take {rule}", at=diff + 1, kind="expand",
                           got=t.node, expected=e.node.cell)
        return verdict(False, diff, "expansion", text, at=diff + 1, kind="expand", got=t.node,
                       expected=e.node.cell)
    added = ", ".join(show(s) for s in t.successors) or "nothing"
    wanted = ", ".join(show(s.cell) for s in e.successors) or "nothing"
    hint = (" (backward, a cell's successors are the cells a move reaches it from)"
            if e.direction == "backward" else "")
    return verdict(False, diff, "successors", f"{line}from {show(t.node)} your search added "
                   f"{added}; the {e.direction} search adds {wanted}{hint}", at=diff + 1,
                   kind="successors")


# -- without -a: a trace that looks bidirectional, diagnosed ---------------------------------
#: The move orders tried, of those the trace allows: the app's where it fits, and the first
#: inferred (every order that keeps each step's successors in the order added makes the same
#: search of the trace, but for a step cut short at a meeting).
ORDERS = 2


def diagnose_trace(trace: Trace, board: Grid | Graph, max_steps: int | None = None
                   ) -> Diagnosis | MeetingDiagnosis:
    """``--check-trace`` without ``-a``: :func:`~tui_search.engine.traces.diagnose.diagnose`,
    and for a trace that looks bidirectional the bidirectional searches too (module doc)."""
    if not trace.bidirectional:
        return diagnose(trace, board, max_steps)
    one_way = _one_way(trace, board, max_steps)
    most = len(trace.steps) + 1 if max_steps is None else min(len(trace.steps) + 1, max_steps)
    orders = bidirectional_orders(trace, board)
    scored = [_score(trace, board, i, key, sem, most)
              for i, (key, sem) in enumerate(bidirectional_candidates(orders[:ORDERS], board))]
    scored.sort(key=lambda s: (-s.matched, not s.whole, s.index))
    whole: dict[tuple[str, str, str], _Scored] = {}
    for s in scored:
        if s.whole:
            whole.setdefault((s.key, s.semantics.stop, s.semantics.turn), s)
    listed = list(whole.values()) or scored[:1]
    found = [(s, check_bidirectional(trace, board, s.key, s.semantics, most)) for s in listed]
    notes = tuple(order_notes(orders))
    return MeetingDiagnosis(one_way, found, one_way.tried + len(scored), notes)


def _one_way(trace: Trace, board: Grid | Graph, max_steps: int | None) -> Diagnosis:
    """The one-directional diagnosis of a trace that looks bidirectional.  No one-directional
    search matches it up to a step ``k`` that takes off a goal no earlier step added (each
    listing what it added): its first ``k`` steps are diagnosed alone (a recursion's calls
    form then runs as far as theirs, not seconds), unless one matches them all."""
    goals = set(board.goals) if isinstance(board, Graph) else {board.goal}
    added = {board.start}
    for k, t in enumerate(trace.steps, 1):
        if not t.listed:
            break
        if t.node not in added and t.node in goals:
            one_way = diagnose(replace(trace, steps=trace.steps[:k]), board, max_steps)
            if one_way.matches or any(v.matched >= k for v in one_way.best):
                break
            n = len(trace.steps)
            return replace(one_way, best=[replace(v, steps=n) for v in one_way.best])
        added.update(t.successors)
    return diagnose(trace, board, max_steps)


def bidirectional_candidates(orders: list[tuple[str, ...]], board: Grid | Graph
                             ) -> Iterator[tuple[str, Semantics]]:
    """Every bidirectional search under every choice that tells them apart, the plainest
    first: each search (biastar with each heuristic, the default first), each order, each
    corner rule (with a diagonal), each turn rule, each stopping rule."""
    if isinstance(board, Graph):
        from tui_search.engine.search.choices import graph_heuristics

        heuristics = graph_heuristics(board)
    else:
        heuristics = sorted(HEURISTICS, key=lambda h: h != DEFAULT_HEURISTIC)
    for key, algo in BIDIRECTIONAL.items():
        for heuristic in heuristics if algo.informed else heuristics[:1]:
            for order in orders:
                diagonal = any(len(move) == 2 for move in order)
                for corners in CORNER_RULES if diagonal else ("always",):
                    for turn in TURN_RULES:
                        for stop in STOP_RULES:
                            yield key, Semantics(order=order, corners=corners,
                                                 heuristic=heuristic, stop=stop, turn=turn)


def bidirectional_name(key: str, sem: Semantics) -> str:
    """A bidirectional search and its choices in a student's words: "BiBFS (stop:
    first-meeting; order N,E,S,W)", "BiA* (stop: proven; turn: the smaller frontier first;
    manhattan; order E,S,W,N; corners never)"."""
    algo = get_algorithm(key)
    parts = [f"stop: {sem.stop}"]
    if sem.turn != TURN_RULES[0]:
        parts.append("turn: the smaller frontier first")
    if algo.informed:
        parts.append(sem.heuristic)
    parts.append(f"order {order_words(sem)}")
    if sem.corners != "always":
        parts.append(f"corners {sem.corners}")
    return f"{algo.short} ({'; '.join(parts)})"


@dataclass(frozen=True)
class _Scored:
    """A candidate run beside the trace: the steps it matched, is it the whole trace, why the
    search stopped there (a whole match's)."""

    matched: int
    whole: bool
    index: int
    key: str
    semantics: Semantics
    why: str


def _score(trace: Trace, board: Grid | Graph, index: int, key: str, sem: Semantics,
           most: int) -> _Scored:
    """Run the candidate beside the trace until its first difference (or ``most`` steps)."""
    search = BidirectionalSearch(board, get_algorithm(key), sem)
    steps = iter(search)
    matched = 0
    for t in trace.steps:
        if matched >= most:  # cut at --max-steps
            break
        e = next(steps, None)
        if e is None or not same_step(t, e):
            return _Scored(matched, False, index, key, sem, "")
        matched += 1
    whole = matched == len(trace.steps) and (matched >= most or next(steps, None) is None)
    return _Scored(matched, whole, index, key, sem, search.why() if whole else "")


class MeetingDiagnosis:
    """The diagnosis of a trace that looks bidirectional: the one-directional ``one_way``,
    and the bidirectional candidates ``found`` (every whole match, one a search and its
    stopping and turn rules; else the nearest), each with its check's verdict; the
    ``notes`` of whichever leads (``orders_notes``: what the bidirectional orders leave open)."""

    def __init__(self, one_way: Diagnosis, found: list[tuple[_Scored, MeetingVerdict]],
                 tried: int, orders_notes: tuple[str, ...]) -> None:
        self.one_way, self.found, self.tried = one_way, found, tried
        self.notes = orders_notes if self.leads else one_way.notes

    @property
    def matches(self) -> bool:
        return self.found[0][1].matches or self.one_way.matches

    @property
    def leads(self) -> bool:
        """Is a bidirectional search the answer (a match, or the nearest: the one-directional
        searches match no longer and none matches)?"""
        first = self.found[0][1]
        best = self.one_way.best
        return first.matches or not self.one_way.matches and (
            not best or first.matched >= best[0].matched)

    def text(self) -> str:
        one_way, (top, verdict) = self.one_way, self.found[0]
        if verdict.matches:
            n = verdict.steps
            name = bidirectional_name(top.key, top.semantics)
            lines = [f"your trace is {name}, for all {n} steps",
                     f"  (it stops where the rule does: {top.why})"]
            lines += [f"  also {bidirectional_name(s.key, s.semantics)}, for all {n} steps"
                      for s, _ in self.found[1:]]
            lines += [f"  also {v.choices}, for all {v.steps} steps"
                      for v in one_way.best if v.matches]
            if one_way.best and not one_way.matches:
                v = one_way.best[0]
                span = f"up to step {v.matched}" if v.matched else "differs from step 1"
                lines.append(f"  next: {v.choices} {span}")
        elif one_way.matches:
            lines = one_way.text().splitlines()[:-1]
            span = f"up to step {top.matched}" if top.matched else "differs from step 1"
            lines.insert(len(lines) - len(one_way.notes) - sum(
                note in ALL_NOTES for note in one_way.best[0].notes),
                f"  next: {bidirectional_name(top.key, top.semantics)} {span}")
            return "\n".join([*lines, f"  ({self.tried} searches and choices tried)"])
        else:
            near = self._nearest(top, verdict)
            others = [f"  {v.choices}{one_way.parted(v)}" for v in self._one_way_listed()]
            lines = ["closest:", *(near + others if self.leads else others + near)]
        lines += [f"  note: {note}" for note in self.notes]
        lines.append(f"  ({self.tried} searches and choices tried)")
        return "\n".join(lines)

    def _one_way_listed(self) -> list[Verdict]:
        """The one-directional candidates listed: the first alone under a bidirectional one
        that leads and does not match."""
        best = self.one_way.best
        return best[:1] if self.leads and not self.matches else best

    @staticmethod
    def _nearest(top: _Scored, verdict: MeetingVerdict) -> list[str]:
        """The nearest bidirectional search, where it parts and why, in its check's words."""
        first, *more = verdict.lines
        where = first.removeprefix("difference at ")
        span = f" up to step {verdict.matched}; then {where}" if verdict.matched else (
            f" from {where}")
        return [f"  {bidirectional_name(top.key, top.semantics)}{span}",
                *(f"    {line}" for line in more)]

    def candidates(self) -> list[dict[str, object]]:
        """The candidates as the text lists them, each as the JSON gives it."""
        two = [self._json(s, v) for s, v in self.found]
        one = [v.as_json() for v in self._one_way_listed()]
        if self.found[0][1].matches:
            return two + one
        return one + two[:1] if self.one_way.matches or not self.leads else two[:1] + one

    @staticmethod
    def _json(s: _Scored, v: MeetingVerdict) -> dict[str, object]:
        """A bidirectional candidate as a one-directional one's JSON, with its check's
        ``cause`` and ``text``."""
        return {"verdict": "match" if v.matches else "difference", "algorithm": s.key,
                "search": bidirectional_name(s.key, s.semantics),
                "choices": s.semantics.as_json(get_algorithm(s.key)), "steps": v.steps,
                "matched_steps": v.matched, "first_difference": v.first, "notes": [],
                "cause": v.cause or None, "text": v.text()}

    def as_json(self) -> dict[str, object]:
        return {"verdict": "match" if self.matches else "closest", "tried": self.tried,
                "candidates": self.candidates(), "notes": list(self.notes),
                "bidirectional": True}


def summary(diagnosis: Diagnosis | MeetingDiagnosis) -> dict[str, object]:
    """The first candidate as a student's records keep it (None where there is none)."""
    if isinstance(diagnosis, MeetingDiagnosis) and diagnosis.leads:
        top, verdict = diagnosis.found[0]
        return {"algorithm": top.key, "search": bidirectional_name(top.key, top.semantics),
                "steps": verdict.steps, "matched_steps": verdict.matched,
                "cause": verdict.cause or None}
    one_way = diagnosis.one_way if isinstance(diagnosis, MeetingDiagnosis) else diagnosis
    best = one_way.best[0] if one_way.best else None
    difference = best.difference if best is not None else None
    return {"algorithm": best.algorithm if best else None,
            "search": best.choices if best else None,
            "steps": best.steps if best else None,
            "matched_steps": best.matched if best else None,
            "cause": difference.cause if difference else None}


__all__ = ["ORDERS", "MeetingDiagnosis", "MeetingVerdict", "bidirectional_candidates",
           "bidirectional_name", "check_bidirectional", "diagnose_trace", "same_step", "summary"]

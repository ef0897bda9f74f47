"""Checking a student's bidirectional search (``--check-trace FILE -a bibfs``) against the
reference's (:mod:`~tui_search.engine.search.bidirectional.loop`), its stopping rule included:
the trace's steps, one a line in the order taken (forward, backward, forward, ...), each the
node taken off and the successors it added (backward: the cells a move reaches it from).

The reference runs under both stopping rules, so a trace that matches the other rule's steps
is said to (the commonest slip: stopping at the first meeting); a trace that stops early or
goes on is told where the rule stops and why; a difference is the first step that differs,
with whose turn it was.  Steps are numbered as the trace numbers its expansion lines."""

from __future__ import annotations

from collections.abc import Sequence

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.bidirectional.loop import BidirectionalSearch
from tui_search.engine.search.choices import STOP_RULES, Semantics
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.rules import Expansion
from tui_search.engine.traces.read import Trace, TraceStep, show


class MeetingVerdict:
    """What the check found: ``matches``, the trace's ``steps``, those ``matched`` before
    the first difference, the ``cause`` in a few words ("" on a match) and the sentences."""

    def __init__(self, algorithm: str, search: str, matches: bool, steps: int, matched: int,
                 cause: str, lines: list[str]) -> None:
        self.algorithm, self.search, self.matches = algorithm, search, matches
        self.steps, self.matched, self.cause, self.lines = steps, matched, cause, lines

    def text(self) -> str:
        return "\n".join(self.lines)

    def as_json(self) -> dict[str, object]:
        return {"algorithm": self.algorithm, "search": self.search, "matches": self.matches,
                "steps": self.steps, "matched_steps": self.matched,
                "cause": self.cause or None, "text": self.text()}


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


def _first_difference(trace: Sequence[TraceStep], steps: list[Expansion]) -> int | None:
    """The index of the first step that differs, within the shorter of the two (None: one is
    the other's beginning)."""
    for i, (t, e) in enumerate(zip(trace, steps, strict=False)):
        if t.node != e.node.cell:
            return i
        if t.listed and tuple(t.successors) != tuple(s.cell for s in e.successors):
            return i
    return None


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

    def verdict(matches: bool, matched: int, cause: str, *lines: str) -> MeetingVerdict:
        return MeetingVerdict(key, name, matches, n, matched, cause, list(lines))

    if diff is None and n == len(ref):
        return verdict(True, n, "", f"match: your trace is {name} step for step ({n:,} "
                       f"steps), and it stops where the rule does: {search.why()}")
    matched = min(n, len(ref)) if diff is None else diff
    if _first_difference(t_steps, alt) is None and n == len(alt):  # the other rule's run
        if chosen == STOP_RULES[0]:  # it stopped at the first meeting
            return verdict(False, matched, "stopping rule", f"difference at step {n:,}: your "
                           f"search stops at the first meeting: {alt_search.why()}", f"{name} "
                           "goes on until the best meeting is proven the cheapest: the first "
                           "meeting need not be")
        return verdict(False, matched, "stopping rule", f"difference at step {len(ref):,}: "
                       f"{name} stops there ({search.why()}); your search goes on, as proven "
                       f"does: {alt_search.why()}")
    if diff is None:
        if n < len(ref):
            return verdict(False, n, "ends early", f"difference at step {n + 1}: your trace "
                           f"ends after step {n:,}; {name} goes on (step {n + 1} is the "
                           f"{ref[n].direction} search's)")
        return verdict(False, len(ref), "goes on", f"difference at step {len(ref) + 1}: "
                       f"{name} stops after step {len(ref):,} ({search.why()}); your trace "
                       f"goes on to step {n:,}")
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
                           f"step: the two searches take {rule}")
        return verdict(False, diff, "expansion", text)
    added = ", ".join(show(s) for s in t.successors) or "nothing"
    wanted = ", ".join(show(s.cell) for s in e.successors) or "nothing"
    hint = (" (backward, a cell's successors are the cells a move reaches it from)"
            if e.direction == "backward" else "")
    return verdict(False, diff, "successors", f"{line}from {show(t.node)} your search added "
                   f"{added}; the {e.direction} search adds {wanted}{hint}")


__all__ = ["MeetingVerdict", "check_bidirectional"]

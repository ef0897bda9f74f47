"""Which lines of a bidirectional search's pseudocode
(:mod:`~tui_search.engine.search.bidirectional.pseudo`) the step at its position executed --
as :mod:`~tui_search.tui.view.code_trace` says it of a one-way search, from the half that took
the step: its take-off and the loop's head on every step, the turn, the proof's test while
``proven`` stops, a discard, the skips of its successors, a push, a new best meeting, and
the line that ended the search."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.search.choices import STOP_RULES, TURN_RULES
from tui_search.tui.view.code_trace import code_of, skipped

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun

#: The most specific lines first: the one the Code panel keeps in view.
FOCUS_KINDS = ("first", "meet", "discard", "corner", "reached", "goal_start", "fail")


def two_way_kinds(run: BiRun) -> frozenset[str]:
    """The kinds of the lines the step at ``run``'s position executed."""
    k = run.k
    proven = run.semantics.stop == STOP_RULES[0]
    alternate = run.semantics.turn == TURN_RULES[0]
    ended = run.at_end and not run.gave_up
    if k == 0:
        kinds = {"init", "mark_start", "mu", "side" if alternate else "init"}
        if ended and run.found:
            kinds.add("goal_start")
        return frozenset(kinds)
    kinds = {"while", "take"} | ({"proven"} if proven else set())
    if not alternate:
        kinds.add("side")
    elif k > 1:
        kinds.add("turn")  # the step before handed the turn over
    back = run.direction(k) != "forward"
    half = run.halves[back]
    if half.steps.is_discarded(half.k):
        kinds.add("discard")
    else:
        kinds.add("for")
        skips = skipped(half, half.k, reverse=back and run.graph is None)
        kinds.update(skip.kind for skip in skips)
        added = half.steps.succ_range(half.k)
        if run.algo.weighted and (len(added) or any(s.kind == "reached" for s in skips)):
            kinds.add("cost")
        if len(added):
            kinds.add("push")
        if run.meeting() is not None and run.mu() < run.mu(k - 1):
            kinds.add("meet")
            if not proven:
                kinds.add("first")
    if ended and not run.found:
        kinds.add("fail")
    return frozenset(kinds)


def two_way_lines(run: BiRun) -> tuple[frozenset[int], int | None, list[int]]:
    """The lit lines' numbers, the most specific of them (None: only ordinary ones) and the
    lines the Code panel keeps in sight first (the push, the most specific)."""
    code, kinds = code_of(run), two_way_kinds(run)
    lit = code.numbers(kinds)
    focus = next((number for kind in FOCUS_KINDS if kind in kinds
                  and (number := code.number(kind)) is not None), None)
    if run.at_end and run.found and "proven" in kinds:  # the test that stopped it
        focus = code.number("proven")
    push = code.number("push") if "push" in kinds else None
    named = sorted({n for n in (push, focus) if n is not None})
    return lit, focus, named


__all__ = ["FOCUS_KINDS", "two_way_kinds", "two_way_lines"]

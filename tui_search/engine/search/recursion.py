"""A recursive search's *calls* form (``--recursive calls``), defined from its *neighbours*
form: the reference's definition of the recursion a student writes when each line lists the
cells the call recursed into.

The neighbours form is the reference loop on a :class:`~tui_search.engine.search.rules.CallStack`:
a line lists the neighbours the call will try (those not visited on entry), and a neighbour
visited meanwhile, deeper down, is skipped when the loop comes to it (a discarded step).  The
calls form lists, of those, the ones the call did recurse into -- the neighbours form's
successors whose entry was later taken off and entered -- so it has no discarded step, and
leaves out the neighbours still to try when the goal was found.  Its goal is found when the
recursion comes to it, as the neighbours form with the goal tested on expand finds it; tested on
generate ("found as a neighbour") the goal's own line is not written.

A step's successors are known only once its subtree is done, so the steps of an iteration are
kept (iterative deepening gives out each iteration as it ends: one with no goal tried all it
listed) and given out renumbered when it ends.  A search cut at ``max_steps`` lists the calls
made by then: its steps are given out at ``max_steps + 1`` (one more than the limit, which says
the search went on), and a run of it keeps at most :data:`MAX_HELD` steps (they are held in
memory until the iteration ends).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace
from typing import Protocol

from tui_search.engine.search.rules import Expansion, Node

#: The most steps of the calls form a run records: they are held until their iteration ends.
MAX_HELD = 1 << 20


class Counted(Protocol):
    """What a search says of itself when its steps are done (the reference search's)."""

    goal: Node | None
    expanded: int
    discarded: int
    generated: int
    max_frontier: int


class _Renumbered:
    """The calls form's events and steps, numbered anew as iterations are given out."""

    def __init__(self) -> None:
        self.generated = 0
        self.steps = 0
        self.peak = 1
        self.mapped: dict[int, Node] = {}

    def iteration(self, steps: list[Expansion], goal: Node | None) -> Iterator[Expansion]:
        """An iteration's steps of the neighbours form as the calls form's: the discarded
        ones left out, and each step's successors those later entered (or the goal)."""
        entered = {step.node.event for step in steps if not step.discarded}
        root = steps[0].node
        mapped = self.mapped
        mapped[root.event] = Node(self.generated, root.cell, None, None, 0, root.g)
        self.generated += 1
        first = self.generated - 1  # this iteration's root
        taken = 0
        for step in steps:
            if step.discarded:
                continue
            node = mapped[step.node.event]
            successors = []
            for s in step.successors:
                if s.event in entered or s is goal:
                    child = Node(self.generated, s.cell, node, s.move, s.depth, s.g)
                    mapped[s.event] = child
                    successors.append(child)
                    self.generated += 1
            taken += 1
            self.steps += 1
            size = self.generated - first - taken
            self.peak = max(self.peak, size)
            new_root = mapped[root.event] if step.new_root is not None else None
            yield replace(step, index=self.steps, node=node, successors=tuple(successors),
                          frontier_size=size, new_root=new_root)


def calls_form(search: Counted, steps: Iterator[Expansion], goal_line: bool,
               max_steps: int | None = None) -> Iterator[Expansion]:
    """The calls form of ``steps``, the neighbours form run with the goal tested on expand
    (``goal_line``: keep the goal's line, the goal tested on expand; else it is dropped), up
    to ``max_steps + 1`` steps (None: all).  Once they are all given out, ``search``'s goal
    and counts are the calls form's."""
    numbers = _Renumbered()
    kept: list[Expansion] = []
    taken = 0  # the calls form's steps given out or kept
    for step in steps:
        if step.new_root is not None and kept:
            yield from numbers.iteration(kept, None)
            kept = []
        kept.append(step)
        taken += not (step.discarded or step.found and not goal_line)  # (a line dropped)
        if max_steps is not None and taken > max_steps:
            search.goal = None  # cut short: what was found after is not
            break
    if kept and kept[-1].found and not goal_line:
        kept.pop()
    if kept:
        yield from numbers.iteration(kept, search.goal)
    elif search.goal is not None:  # the start is the goal, found before any step
        numbers.mapped[search.goal.event] = Node(0, search.goal.cell, None, None, 0)
        numbers.generated = 1
    if search.goal is not None:
        search.goal = numbers.mapped[search.goal.event]
    search.expanded, search.discarded = numbers.steps, 0
    search.generated, search.max_frontier = numbers.generated, numbers.peak


__all__ = ["MAX_HELD", "calls_form"]

"""Which of the app's searches is a trace?  Try every registry algorithm under the choices that
tell them apart, with the move order inferred from the order the trace added successors
(:mod:`~tui_search.engine.traces.orders`), and rank them by how many steps each matches before it
parts from the trace.

Each candidate is checked by :func:`~tui_search.engine.traces.check.check_trace`, which stops
at its first difference (and records its run only that far), so a candidate that disagrees
early costs little.  The choices of published code (a tie rule, a closed set, exact costs, an
unmarked start, a node expanded again, no path check, the calls form of a recursion) are tried
where a candidate parts for a reason one of them explains: each difference names the choices
that would (:class:`~tui_search.engine.traces.causes.Difference`'s ``suggest``), and the
candidate is tried again with each, up to :data:`VARIANTS` changes in a row.  Every candidate
that matches the whole trace is listed; when none does, the closest, each with where it parts.
"""

from __future__ import annotations

import heapq
from collections.abc import Iterator
from dataclasses import dataclass, replace
from itertools import chain
from typing import Any

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import CORNER_RULES, Semantics
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.registry import ALGORITHMS, get_algorithm
from tui_search.engine.traces.check import ALL_NOTES, Verdict, check_trace
from tui_search.engine.traces.orders import (
    expansion_orders,
    flipped_order,
    inferred_orders,
    order_notes,
)
from tui_search.engine.traces.read import Trace, show

#: Candidates listed when none matches the whole trace (and at least this many lines).
BEST = 3
#: Choices of published code changed in a row from a candidate, each where it parts.
VARIANTS = 3
#: The most variants tried in one diagnosis (those of the candidates that matched longest
#: first): a trace whose every step is a tie (greedy with no estimate) suggests thousands.
VARIANT_BUDGET = 400
#: Listed together when either comes first: greedy best-first can match a trace longer than
#: A* does (an A* with another tie rule), and A* longer than greedy.
BEST_FIRST = ("greedy", "astar")


def candidates(orders: list[tuple[str, ...]], calls_orders: list[tuple[str, ...]] | None = None,
               heuristics_of: list[str] | None = None) -> Iterator[tuple[str, Semantics]]:
    """Every (algorithm, choices) worth telling apart, the plainest first (a corner rule only
    for orders with a diagonal: without one every rule is the same search).  A recursion's
    calls form is tried with each of ``calls_orders`` (default ``orders``): its lines leave out
    the neighbours visited deeper down, and which those are depends on the order of every
    move, not only of those a line lists.  ``heuristics_of``: a graph's, its default first
    (default: a grid's)."""
    usable = heuristics_of or sorted(HEURISTICS, key=lambda h: h != DEFAULT_HEURISTIC)
    for key, algo in ALGORITHMS.items():
        heuristics = usable if algo.informed else usable[:1]
        for kind, order in _shapes(key, orders, calls_orders or orders):
            diagonal = any(len(move) == 2 for move in order)
            for goal_test in (algo.goal_test, "generate" if algo.goal_test == "expand"
                              else "expand"):
                for corners in CORNER_RULES if diagonal else ("always",):
                    for heuristic in heuristics:
                        yield key, Semantics(order=order, corners=corners, goal_test=goal_test,
                                             heuristic=heuristic, **kind)


def _shapes(key: str, orders: list[tuple[str, ...]], calls_orders: list[tuple[str, ...]]
            ) -> Iterator[tuple[dict[str, Any], tuple[str, ...]]]:
    """Each shape of :func:`_kinds` with each order it is tried with."""
    for order in orders:
        for kind in _kinds(key):
            if kind.get("recursive") != "calls":
                yield kind, order
    for kind in _kinds(key):
        if kind.get("recursive") == "calls":
            for order in calls_orders:
                yield kind, order


def _kinds(key: str) -> list[dict[str, Any]]:
    """The search's shapes tried from the first: graph search under each visit rule, tree
    search and, for DFS and iterative deepening, recursion (both forms)."""
    algo = ALGORITHMS[key]
    kinds: list[dict[str, Any]] = [{}]
    if not (algo.iterative or algo.weighted):
        kinds.append({"visit": "expand"})
    kinds.append({"tree_search": True})
    if key in ("dfs", "iddfs"):
        kinds += [{"recursive": "neighbours"}, {"recursive": "calls"}]
        kinds.append({"recursive": "neighbours", "tree_search": True})
        if not algo.iterative:  # a recursion with no visited set (its path check a variant)
            kinds.append({"recursive": "calls", "tree_search": True})
    return kinds


def _plainness(sem: Semantics) -> int:
    """How many choices of published code ``sem`` makes, fewer the plainer (recursion is no
    tweak of a search but its shape: a recursive DFS is as plain as a stack one)."""
    return len(sem.published_words()) + (not sem.path_check) + (sem.visit == "expand-again")


@dataclass(frozen=True)
class _Scored:
    """A candidate checked: what ranks it, then the candidate."""

    rank: tuple[int, bool, bool, int, bool, int]
    key: str
    semantics: Semantics
    verdict: Verdict
    alike: str = ""  # what matches alike, a few words


@dataclass(frozen=True)
class Diagnosis:
    """The candidates listed, the longest match first, and whether the first matches it all."""

    best: list[Verdict]
    tried: int
    notes: tuple[str, ...] = ()

    @property
    def matches(self) -> bool:
        return bool(self.best) and self.best[0].matches

    def text(self) -> str:
        lines = []
        if self.matches:
            top = self.best[0]
            lines.append(f"your trace is {top.choices}, for all {top.steps} steps")
            lines += [f"  ({note})" for note in top.notes if note not in ALL_NOTES]
            for v in self.best[1:]:
                if v.matches:
                    lines.append(f"  also {v.choices}, for all {v.steps} steps")
                    lines += [f"    ({note})" for note in v.notes if note not in ALL_NOTES]
                elif v.matched == v.steps:
                    lines.append(f"  next: {v.choices}, all {v.steps} steps, but it does not "
                                 "stop there")
                elif self._no_stack_order(v):
                    lines.append(f"  next: {v.choices}{self.parted(v)}")
                else:
                    assert v.difference is not None
                    tie = (f", where {get_algorithm(v.algorithm).priority_name} ties"
                           if v.difference.tie else "")
                    span = (f"up to step {v.matched}" if v.matched
                            else "differs from step 1")
                    lines.append(f"  next: {v.choices} {span}{tie}")
            lines += [f"  note: {note}" for note in top.notes if note in ALL_NOTES]
        else:
            lines.append("closest:")
            lines += [f"  {v.choices}{self.parted(v)}" for v in self.best]
        lines += [f"  note: {note}" for note in self.notes]
        lines.append(f"  ({self.tried} searches and choices tried)")
        return "\n".join(lines)

    def _no_stack_order(self, v: Verdict) -> bool:
        """Is ``v`` a stack DFS listed under a recursive DFS that matches longer?"""
        return (v.algorithm == "dfs" and not v.semantics.recursive
                and bool(self.best[0].semantics.recursive)
                and v.difference is not None and v.difference.kind == "expand"
                and v.difference.got is not None)

    def parted(self, v: Verdict) -> str:
        """Where ``v`` parts from the trace: " up to step 12; then step 13: ...", " from step
        1: ..." when it parts at once; for a stack DFS under a recursive one, the issue's
        words: "...; then your trace expands (4,1), which no stack order explains (a
        recursive DFS does)"."""
        d = v.difference
        assert d is not None
        if self._no_stack_order(v):
            assert d.got is not None
            then = (f"your trace expands {show(d.got)}, which no stack order explains (a "
                    "recursive DFS does)")
            return f" up to step {v.matched}; then {then}" if v.matched else f" from {then}"
        return f" up to step {v.matched}; then {d.message}" if v.matched else f" from {d.message}"

    def as_json(self) -> dict[str, object]:
        return {"verdict": "match" if self.matches else "closest", "tried": self.tried,
                "candidates": [v.as_json() for v in self.best], "notes": list(self.notes),
                "bidirectional": False}


class _Search:
    """The candidates of one diagnosis, checked in turn, with their variants."""

    def __init__(self, trace: Trace, grid: Grid | Graph, limit: int) -> None:
        self.trace, self.grid, self.limit = trace, grid, limit
        self.seen: set[tuple[str, Semantics]] = set()
        self.scored: list[_Scored] = []
        self.queued = 0  # variants queued (what breaks a tie of their order)
        self.nodes: Trace | None = None  # the trace's expansions alone, once asked for
        goal = trace.goal or (grid.goal if isinstance(grid, Grid) else grid.goals[0])
        self.goal = goal
        self.flipped: tuple[str, ...] | None = ()  # the flipped steps' order, once asked
        # Every order that keeps each step's successors in the order the trace added them
        # makes the same search of this trace up to its first difference (the same
        # successors, pushed in the same order, so the same ties): one of them stands for
        # all -- but for a step that stopped at the goal, which says nothing of the moves
        # after the goal's.  Where a candidate parts there, it is tried again with the
        # goal's move before those.
        self.stopping = inferred_orders(trace, goal)[0]
        self.goal_steps = {n for n, step in enumerate(trace.steps, 1)
                           if step.successors and step.successors[-1] == goal}

    def run(self, bases: Iterator[tuple[str, Semantics]]) -> None:
        """Check every base candidate, then their variants, those of the candidates that
        matched longest first (a variant takes over where its candidate parted), at most
        :data:`VARIANT_BUDGET` of them."""
        variants: list[tuple[int, int, int, int, str, Semantics]] = []  # a heap
        calls: list[tuple[int, str, Semantics]] = []
        for i, (key, sem) in enumerate(bases):
            if sem.recursive == "calls":
                calls.append((i, key, sem))  # checked last: see score
            else:
                self.score(key, sem, 0, i, variants)
        for i, key, sem in calls:
            self.score(key, sem, 0, i, variants)
        budget = VARIANT_BUDGET
        while variants and budget:
            _, depth, i, _, key, sem = heapq.heappop(variants)
            if (key, sem) not in self.seen:
                budget -= 1
                self.score(key, sem, depth, i, variants)

    def score(self, key: str, sem: Semantics, depth: int, i: int,
              variants: list[tuple[int, int, int, int, str, Semantics]]) -> None:
        """Check a candidate, rank it, and queue the variants its difference suggests."""
        if (key, sem) in self.seen:
            return
        self.seen.add((key, sem))
        if sem.recursive == "calls" and not self.calls_may_lead(key, sem):
            return
        verdict, sem = self.check(key, sem)
        difference = verdict.difference
        # Of those matching as long, an A* whose f tied where the trace took the lower (or
        # higher) h first, of those the heuristic exact for the moves the trace made.
        tie = difference is not None and difference.tie == "h"
        # Then the plainest (graph search before tree search), then as enumerated.
        rank = (-verdict.matched, not tie, not (tie and _fits(sem)), _plainness(sem),
                sem.tree_search, i)
        self.scored.append(_Scored(rank, key, sem, verdict))
        if difference is None or depth >= VARIANTS:
            return
        algo = ALGORITHMS[key]
        for change in difference.suggest:
            if dict(change).get("flip_even"):  # the order as the trace's flipped steps give it
                flipped = self.flipped_order()
                if flipped is None:
                    continue
                change = (("flip_even", True), ("order", flipped))
            try:
                variant = sem.replace(**dict(change))
                variant.check(algo)
            except ValueError:
                continue
            self.queued += 1
            heapq.heappush(variants, (-verdict.matched, depth + 1, i, self.queued, key,
                                      variant))

    def flipped_order(self) -> tuple[str, ...] | None:
        """:func:`~tui_search.engine.traces.orders.flipped_order` of the trace, once."""
        if self.flipped == ():
            self.flipped = flipped_order(self.trace, self.goal)
        return self.flipped

    def calls_may_lead(self, key: str, sem: Semantics) -> bool:
        """May a recursion's calls form match as long as the best candidate so far?  Its
        lines are known only once the search is done (:mod:`~tui_search.engine.search.
        recursion`), so it is checked in full only when the order of its expansions -- its
        neighbours form's, run with the goal tested on expand, the cells it skips left out --
        matches the trace's at least that long."""
        best = max((s.verdict.matched for s in self.scored), default=0)
        if self.nodes is None:
            self.nodes = replace(self.trace, steps=tuple(
                t._replace(successors=(), listed=False) for t in self.trace.steps))
        order = check_trace(self.nodes, self.grid, key, sem.replace(
            recursive="neighbours", goal_test="expand"), max_steps=self.limit, look_ahead=0)
        return order.matched >= best

    def check(self, key: str, sem: Semantics) -> tuple[Verdict, Semantics]:
        """The candidate checked (with the goal's move first, where that matches longer)."""
        verdict = check_trace(self.trace, self.grid, key, sem, max_steps=self.limit,
                              look_ahead=0)
        if (verdict.difference is not None and verdict.difference.step in self.goal_steps
                and self.stopping != sem.order):
            self.seen.add((key, sem))
            again_sem = sem.replace(order=self.stopping)
            again = check_trace(self.trace, self.grid, key, again_sem, max_steps=self.limit,
                                look_ahead=0)
            if again.matched > verdict.matched:
                return again, again_sem
        return verdict, sem


def diagnose(trace: Trace, grid: Grid | Graph, max_steps: int | None = None) -> Diagnosis:
    """The searches that match ``trace`` on ``grid``: every one that matches it all, else the
    :data:`BEST` that match longest (a DFS or BFS never above an A* that matched longer)."""
    limit = 4 * len(trace.steps) + 64  # a search that gives up (max_steps) stops there too
    if max_steps is not None:
        limit = min(limit, max_steps)
    expansions_only = trace.expansions_only
    orders = (expansion_orders(trace) if expansions_only
              else inferred_orders(trace, grid=grid if isinstance(grid, Grid) else None))
    search = _Search(trace, grid, limit)
    heuristics = None
    if isinstance(grid, Graph):
        from tui_search.engine.search.choices import graph_heuristics

        heuristics = graph_heuristics(grid)
    bases = candidates(orders if expansions_only else orders[:1], orders, heuristics)
    flipped = None if expansions_only else search.flipped_order()
    if flipped is not None:  # the trace reads as an order reversed on every other cell
        bases = chain(bases, ((key, sem.replace(flip_even=True)) for key, sem in candidates(
            [flipped], [flipped], heuristics)))
    search.run(bases)
    scored = sorted(search.scored, key=lambda s: s.rank)
    listed = _listed(scored)
    best = [check_trace(trace, grid, s.key, s.semantics, max_steps=limit) for s in listed]
    best = [replace(v, notes=(*v.notes, s.alike)) if s.alike else v
            for v, s in zip(best, listed, strict=True)]
    notes = ([] if expansions_only else order_notes(orders))
    if expansions_only:
        notes.append(f"the trace lists no successors, so its move order cannot be inferred: "
                     f"{len(orders)} orders were tried")
    return Diagnosis(best, len(search.seen), tuple(notes))


def _fits(sem: Semantics) -> bool:
    """Is ``sem``'s heuristic the exact distance for its moves (Manhattan for four straight
    moves, octile with diagonals)?"""
    straight = set(sem.order) <= {"N", "E", "S", "W"}
    return sem.heuristic == ("manhattan" if straight else "octile")


def _listed(scored: list[_Scored]) -> list[_Scored]:
    """The candidates listed, from ``scored`` (sorted, best first): every full match, one
    a search and choices (those that differ only by a corner rule or a heuristic that changes
    nothing on this trace: the first); else the best of each algorithm, :data:`BEST` of them,
    with greedy and A* both when either comes first or A* parted at a tie of f on h, and the
    best stack DFS under a recursive one.  In the order of ``scored``."""
    full = [s for s in scored if s.verdict.matches]
    first = scored[0]
    wanted: list[str] = []
    if first.semantics.recursive and first.key == "dfs":
        wanted.append("dfs")  # where the stack DFS parts: "which no stack order explains"
    if full:
        picked = _distinct(full)
        listed = {(s.key, bool(s.semantics.recursive)) for s in picked}
        rest = [s for s in scored if not s.verdict.matches
                and (s.key, bool(s.semantics.recursive)) not in listed]
        more = _best_of_each(rest, BEST - len(picked), wanted) if rest else []
        return picked + [s for s in more if s.key in wanted or len(picked) < BEST]
    if wanted:
        pass
    elif first.key in BEST_FIRST or any(
            s.key == "astar" and s.verdict.difference is not None
            and s.verdict.difference.tie == "h" for s in scored[:BEST * 4]):
        wanted += BEST_FIRST
    return _best_of_each(scored, BEST, wanted)


def _distinct(full: list[_Scored]) -> list[_Scored]:
    """One of each full match that differs from the others by more than the corner rule, the
    heuristic or the goal test (those that differ by that alone behave alike on this trace:
    the goal's pop is optional); the first of each notes the goal tests that match too."""
    out: dict[tuple[str, Semantics], _Scored] = {}
    for s in full:
        kind = (s.key, s.semantics.replace(corners="always", heuristic=DEFAULT_HEURISTIC,
                                           goal_test=None))
        first = out.setdefault(kind, s)
        test = s.semantics.goal_test_for(ALGORITHMS[s.key])
        if first is not s and test != first.semantics.goal_test_for(ALGORITHMS[first.key]):
            out[kind] = replace(first, alike=f"the goal tested on {test} matches too")
    return list(out.values())


def _best_of_each(scored: list[_Scored], count: int, wanted: list[str]) -> list[_Scored]:
    """The best of each algorithm (a recursive DFS apart from a stack one): the first of
    ``scored``, the best of each of ``wanted``, then the next best up to ``count`` in all;
    in the order of ``scored``."""
    best: dict[tuple[str, bool], _Scored] = {}
    for s in scored:
        best.setdefault((s.key, bool(s.semantics.recursive)), s)
    order = list(best.values())
    picked = order[:1] + [best[key, False] for key in wanted if (key, False) in best]
    picked = list({id(s): s for s in picked}.values())
    for s in order:
        if len(picked) >= count:
            break
        if all(s is not p for p in picked):
            picked.append(s)
    return sorted(picked, key=lambda s: s.rank)


__all__ = ["Diagnosis", "candidates", "diagnose", "inferred_orders", "order_notes"]

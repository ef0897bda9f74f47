"""Which of the app's searches is a trace?  Try every registry algorithm under every choice that
can tell them apart, with the move order inferred from the order the trace added successors,
and rank them by how many steps each matches before it parts from the trace.

Each candidate is checked by :func:`~tui_search.engine.traces.check.check_trace`, which stops
at its first difference (and records its run only that far), so the candidates that disagree
early cost little.  The best three are then checked again with the look-ahead that says where
the search would have expanded the cell the trace took.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, replace

from tui_search.engine.maps.grid import DELTAS, Cell, Grid
from tui_search.engine.search.choices import CORNER_RULES, Semantics
from tui_search.engine.search.heuristics import DEFAULT_HEURISTIC, HEURISTICS
from tui_search.engine.search.registry import ALGORITHMS, get_algorithm
from tui_search.engine.traces.check import Verdict, check_trace
from tui_search.engine.traces.read import Trace, show

#: The most move orders tried when the trace leaves their order open.
MAX_ORDERS = 24

#: Candidates listed.
BEST = 3


def _move(node: Cell, cell: Cell) -> str | None:
    delta = (cell[0] - node[0], cell[1] - node[1])
    return next((d for d, v in DELTAS.items() if v == delta), None)


def inferred_orders(trace: Trace, goal: Cell | None = None) -> list[tuple[str, ...]]:
    """The move orders consistent with the order in which each step added its successors:
    the moves the trace used, ordered every way the trace allows (at most
    :data:`MAX_ORDERS`; the order first seen first).  When the trace contradicts itself (E
    before N in one step, N before E in another), the order first seen alone.

    A step that stops at the ``goal`` (its last successor) says nothing of the moves after
    the goal's, so the goal's move is put before every move that step did not add, wherever
    no other step says otherwise: the search then stops there too."""
    used: list[str] = []
    after: dict[str, set[str]] = {}
    goal_steps: list[list[str]] = []
    for step in trace.steps:
        moves = [m for m in (_move(step.node, c) for c in step.successors) if m is not None]
        for m in moves:
            if m not in used:
                used.append(m)
                after[m] = set()
        for i, a in enumerate(moves):
            after[a].update(b for b in moves[i + 1:] if b != a)
        if moves and step.successors[-1] == goal:
            goal_steps.append(moves)
    for moves in goal_steps:
        for m in used:
            if m not in moves and not _reaches(after, m, moves[-1]):
                after[moves[-1]].add(m)
    if not used:
        return [("N", "W", "S", "E")]
    orders = list(_linear(used, after, ()))
    return orders or [tuple(used)]


def _reaches(after: dict[str, set[str]], a: str, b: str) -> bool:
    """Must ``a`` come before ``b`` (a chain of ``after`` from one to the other)?"""
    todo, seen = [a], {a}
    while todo:
        m = todo.pop()
        if m == b:
            return True
        todo += [n for n in after[m] if n not in seen]
        seen.update(after[m])
    return False


def _linear(used: list[str], after: dict[str, set[str]],
            done: tuple[str, ...]) -> Iterator[tuple[str, ...]]:
    """Every order of ``used`` that keeps each ``a`` before everything in ``after[a]`` (the
    first :data:`MAX_ORDERS` of them)."""
    if len(done) == len(used):
        yield done
        return
    count = 0
    for m in used:
        if m in done or any(m in after[o] for o in used if o not in done and o != m):
            continue
        for order in _linear(used, after, (*done, m)):
            yield order
            count += 1
            if count >= MAX_ORDERS:
                return


def candidates(orders: list[tuple[str, ...]]) -> Iterator[tuple[str, Semantics]]:
    """Every (algorithm, choices) worth telling apart, the plainest first."""
    for key, algo in ALGORITHMS.items():
        heuristics = list(HEURISTICS) if algo.informed else [DEFAULT_HEURISTIC]
        heuristics.sort(key=lambda h: h != DEFAULT_HEURISTIC)
        visits = ["generate"] if algo.iterative or algo.weighted else ["generate", "expand"]
        for order in orders:
            for tree in (False, True):
                for visit in (["generate"] if tree else visits):
                    for goal_test in (algo.goal_test, "generate" if algo.goal_test == "expand"
                                      else "expand"):
                        for corners in CORNER_RULES:
                            for heuristic in heuristics:
                                yield key, Semantics(order=order, corners=corners,
                                                     visit=visit, goal_test=goal_test,
                                                     tree_search=tree, heuristic=heuristic)


def order_notes(orders: list[tuple[str, ...]]) -> list[str]:
    """What the inferred order leaves open: moves the trace never made, and other orders the
    trace allows as well."""
    used = set(orders[0])
    straight = ("N", "E", "S", "W")
    moves = straight if used <= set(straight) else tuple(DELTAS)
    notes = []
    never = [m for m in moves if m not in used]
    if never:
        notes.append(f"the trace never moves {', '.join(never)}: where in the order, or "
                     "whether at all, cannot be told")
    if len(orders) > 1:
        more = " or more" if len(orders) >= MAX_ORDERS else ""
        others = " or ".join(",".join(o) for o in orders[1:4])
        notes.append(f"{len(orders)}{more} orders of its moves fit the order it added them "
                     f"in: {','.join(orders[0])} or {others}"
                     + (" or ..." if len(orders) > 4 else ""))
    return notes


@dataclass(frozen=True)
class Diagnosis:
    """The best candidates, the longest match first, and whether the first matches it all."""

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
            for v in self.best[1:]:
                if v.matches:
                    lines.append(f"  also {v.choices}, for all {v.steps} steps")
                elif v.matched == v.steps:
                    lines.append(f"  next: {v.choices}, all {v.steps} steps, but it does not "
                                 "stop there")
                elif self._no_stack_order(v):
                    lines.append(f"  next: {v.choices}{self._parted(v)}")
                else:
                    assert v.difference is not None
                    tie = (f", where {get_algorithm(v.algorithm).priority_name} ties"
                           if v.difference.tie else "")
                    span = (f"up to step {v.matched}" if v.matched
                            else "differs from step 1")
                    lines.append(f"  next: {v.choices} {span}{tie}")
        else:
            lines.append("closest:")
            lines += [f"  {v.choices}{self._parted(v)}" for v in self.best]
        lines += [f"  note: {note}" for note in self.notes]
        lines.append(f"  ({self.tried} searches and choices tried)")
        return "\n".join(lines)

    def _no_stack_order(self, v: Verdict) -> bool:
        """Is ``v`` a stack DFS listed under a recursive DFS that matches longer?"""
        return (v.algorithm == "dfs" and not v.label and bool(self.best[0].label)
                and v.difference is not None and v.difference.kind == "expand"
                and v.difference.got is not None)

    def _parted(self, v: Verdict) -> str:
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
                "candidates": [v.as_json() for v in self.best], "notes": list(self.notes)}


def diagnose(trace: Trace, grid: Grid, max_steps: int | None = None) -> Diagnosis:
    """The :data:`BEST` searches that match ``trace`` longest on ``grid``.  Candidates that
    behave alike on this trace (a corner rule on a map with no corner to cut) are told apart
    by the plainest first; only the best of each algorithm is kept (greedy best-first can
    match a trace of A* longer than A* with the wrong tie rule does: both are listed)."""
    limit = 4 * len(trace.steps) + 64  # a search that gives up (max_steps) stops there too
    if max_steps is not None:
        limit = min(limit, max_steps)
    scored: list[tuple[int, bool, bool, int, str, Semantics]] = []
    tried = 0
    goal = trace.goal or grid.goal
    orders = inferred_orders(trace)
    # Every order that keeps each step's successors in the order the trace added them makes
    # the same search of this trace up to its first difference (the same successors, pushed
    # in the same order, so the same ties): one of them stands for all -- but for a step
    # that stopped at the goal, which says nothing of the moves after the goal's.  Where a
    # candidate parts there, it is tried again with the goal's move before those.
    stopping = inferred_orders(trace, goal)[0]
    goal_steps = {n for n, step in enumerate(trace.steps, 1)
                  if step.successors and step.successors[-1] == goal}
    for i, (key, sem) in enumerate(candidates(orders[:1])):
        tried += 1
        verdict = check_trace(trace, grid, key, sem, max_steps=limit, look_ahead=0)
        if (verdict.difference is not None and verdict.difference.step in goal_steps
                and stopping != sem.order):
            tried += 1
            again = check_trace(trace, grid, key, sem.replace(order=stopping),
                                max_steps=limit, look_ahead=0)
            if again.matched > verdict.matched:
                verdict, sem = again, sem.replace(order=stopping)
        # Of those matching as long, an A* whose f tied where the trace took the lower (or
        # higher) h first: the trace is that search with another tie rule.  (Other ties --
        # uniform-cost's g wherever moves cost alike, any entry of equal priority -- say
        # little, and keep the plainest first.)
        # Of those that tie alike, the heuristic exact for the moves the trace made (Manhattan
        # for four moves, octile for eight): the one a student's A* would use.
        tie = verdict.difference is not None and verdict.difference.tie == "h"
        scored.append((-verdict.matched, not tie, not (tie and _fits(sem)), i, key, sem))
    # A recursive DFS is listed when its pattern is seen: when it matches longer than every
    # search of the registry (else it would crowd out the searches the trace is nearer).
    longest = -min(m for m, *_ in scored)
    mirror = mirrored(trace)
    for i, sem in enumerate(_recursive_candidates(mirror), len(scored)):
        tried += 1
        verdict = check_trace(mirror, grid, "dfs", sem, max_steps=limit, look_ahead=0)
        if verdict.matched > longest:
            scored.append((-verdict.matched, True, True, i, RECURSIVE, sem))
    scored.sort()
    picked = _listed(scored)
    best: list[Verdict] = []
    for key, sem in picked:
        if key == RECURSIVE:
            verdict = check_trace(mirror, grid, "dfs", sem, max_steps=limit)
            best.append(replace(verdict, label=recursive_label(sem)))
        else:
            best.append(check_trace(trace, grid, key, sem, max_steps=limit))
    return Diagnosis(best, tried, tuple(order_notes(orders)))


#: Listed together when either comes first: greedy best-first can match a trace longer than
#: A* does (an A* with another tie rule), and A* longer than greedy.
BEST_FIRST = ("greedy", "astar")


def _fits(sem: Semantics) -> bool:
    """Is ``sem``'s heuristic the exact distance for its moves (Manhattan for four straight
    moves, octile with diagonals)?"""
    straight = set(sem.order) <= {"N", "E", "S", "W"}
    return sem.heuristic == ("manhattan" if straight else "octile")


def _listed(scored: list[tuple[int, bool, bool, int, str, Semantics]]
            ) -> list[tuple[str, Semantics]]:
    """The :data:`BEST` candidates listed, from ``scored`` (sorted, best first): the best of
    each algorithm; when greedy best-first or A* comes first, or A* parted at a tie of f on
    h (the trace is an A* with another tie rule), the best of both; when a recursive DFS comes
    first, the best stack DFS too (the one missing takes the last place)."""
    picked: list[tuple[str, Semantics]] = []
    best_of: dict[str, Semantics] = {}
    h_tie = False
    for _, no_tie, _, _, key, sem in scored:
        if key not in best_of:
            best_of[key] = sem
            h_tie |= key == "astar" and not no_tie
            if len(picked) < BEST:
                picked.append((key, sem))
    keys = [key for key, _ in picked]
    wanted: list[str] = []
    if keys and keys[0] == RECURSIVE:
        wanted.append("dfs")  # where the stack DFS parts: "which no stack order explains"
    elif keys and (keys[0] in BEST_FIRST or h_tie):
        wanted += BEST_FIRST
    for other in wanted:
        if other in keys or other not in best_of:
            continue
        if len(picked) == BEST:  # drop the last that is neither the first nor wanted
            del picked[max(i for i, (key, _) in enumerate(picked)
                           if i and key not in wanted)]
        picked.append((other, best_of[other]))
        keys = [key for key, _ in picked]
    return picked


#: The key a recursive DFS is scored under (not a registry algorithm: a stack DFS run on the
#: trace mirrored).
RECURSIVE = "dfs-recursive"


def mirrored(trace: Trace) -> Trace:
    """The trace with each step's successors in reverse order.  A recursive DFS that marks a
    cell visited when it enters it, and lists the neighbours not yet visited, expands its
    cells in the order a stack DFS does that visits on expand and pushes them in reverse
    order (the cells it skips are the stack's discarded pops): its mirror is that search's
    trace."""
    return replace(trace, steps=trace.steps.mirrored())


def _recursive_candidates(mirror: Trace) -> Iterator[Semantics]:
    order = inferred_orders(mirror)[0]
    for goal_test in ("expand", "generate"):
        for corners in CORNER_RULES:
            yield Semantics(order=order, corners=corners, visit="expand", goal_test=goal_test)


def recursive_label(sem: Semantics) -> str:
    """A recursive DFS named by the student's order (the mirror's, reversed)."""
    parts = [f"order {','.join(reversed(sem.order))}", f"goal test on {sem.goal_test}"]
    if sem.corners != "always":
        parts.append(f"corners {sem.corners}")
    return f"a recursive DFS ({'; '.join(parts)})"


__all__ = ["Diagnosis", "candidates", "diagnose", "inferred_orders", "mirrored", "order_notes"]

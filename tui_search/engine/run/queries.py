"""What a record says of its generation events, wherever a run stands: each event's cell,
parent and move, the chain from the root, the path and the outcome -- the tree's and the
answer's queries of a recorded run.  A :class:`~tui_search.engine.run.recorded.Run` has one,
over its :class:`~tui_search.engine.run.recording.Recording`."""

from __future__ import annotations

from array import array
from bisect import bisect_left, bisect_right
from collections.abc import Callable, Iterator, Sequence
from itertools import pairwise
from typing import Any

from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.grid import DIRECTIONS
from tui_search.engine.run.recording import Recording, Step
from tui_search.engine.search.heuristics import admissible, heuristic_for, priority_of
from tui_search.engine.search.loops.best_first import move_costs
from tui_search.engine.search.loops.compiled import selected
from tui_search.engine.search.outcome import Outcome
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import ROOT_DIR
from tui_search.engine.search.registry import Frontier
from tui_search.engine.search.state import State

#: Direction names indexed by stored direction code; a root is shown as START.
DIR_NAMES: tuple[str, ...] = DIRECTIONS + ("START",)


class EventTree:
    """Queries on a recording's events (no position)."""

    def __init__(self, recording: Recording) -> None:
        self._recording = recording
        self._rec = recording.rec  # the same record as long as the recording lives
        self._algo = algo = recording.algo
        self._problem = recording.problem
        self._warning: str | None = None  # estimate_warning's, once asked
        self._in_order = algo.frontier is Frontier.FIFO  # event g expanded at step g+1
        self._gen_step = array("i")  # event -> step that expanded it (LIFO; lazy)
        self._gen_step_filled = 0
        self._path: set[int] | None = None
        self._path_gens: list[int] | None = None  # once found: the goal's chain never changes
        self._levels = array("i", [0])  # FIFO: the first event of each depth
        self._next_same = array("i")  # event -> the next event of the same cell (-1: none)
        self._prev_same = array("i")  # event -> the previous event of the same cell (-1: none)
        self._depths: dict[int, int] = {}  # gen_depth's answers where a chain was walked
        core = selected()[0]
        self._walk = None if core is None else core.ancestors  # ancestors' loop in C
        self._last_of_cell: dict[int, int] = {}
        # a bidirectional search's backward half: offsets reversed, a move costs its parent
        self._reverse = recording.source is not None and recording.source.reverse
        problem = self._problem
        if not isinstance(problem, Problem):  # a graph's answers, by node number
            self._grid: Problem | None = None
            self._estimate: Callable[[int], float] = problem.estimate
            self._priority_at = problem.priority(algo.priority or "g")
            self._move_cost: dict[int, float] = {}
            self._terrain: array[float] | None = None
        else:  # a grid's, worked out from the padded cells as the loops do
            self._grid = problem
            goal = problem.unpad(problem.goal)
            heuristic = heuristic_for(recording.semantics.heuristic, problem.lowest)
            priority = priority_of(algo.priority or "g", heuristic, goal,
                                   recording.semantics.weight)
            unpad, (gx, gy) = problem.unpad, goal

            def estimate(p: int) -> float:
                x, y = unpad(p)
                return heuristic(abs(x - gx), abs(y - gy))

            def priority_at(g: float, p: int) -> float:
                return priority(g, *unpad(p))

            self._estimate, self._priority_at = estimate, priority_at
            self._move_cost = move_costs(problem)
            if self._reverse:  # the offsets reversed
                self._move_cost = {-off: c for off, c in self._move_cost.items()}
            self._terrain = problem.terrain  # None: every cell costs 1
        # gen_gs: the last step looked up (its events lo .. hi - 1, its number, the event it
        # took off)
        self._gs_step = (0, 1, 0, -1)  # step 0: the root

    # -- costs (the cost-ordered searches) ----------------------------------------------------
    def gen_g(self, g: int) -> float:
        """Event ``g``'s cost so far (a cost-ordered search only): the g of the entry its
        generating step took off plus its move's cost (its length times its cell's cost) --
        the very sum the loop pushed, so the record keeps a g a step rather than an event.  A
        root's is 0 (step 0 generated it)."""
        rec = self._rec
        step_g = rec.step_g
        assert step_g is not None, "only a cost-ordered search records costs"
        k, roots = bisect_right(rec.step_end, g), rec.iter_root
        if k == 0 or roots[min(bisect_left(roots, g), len(roots) - 1)] == g:
            return 0.0  # a root (IDA*'s iterations each have one)
        node = rec.gen_node
        if self._grid is None:
            return step_g[k] + self._problem.step_cost(node[rec.exp(k)], node[g])
        length = self._move_cost[node[g] - node[rec.exp(k)]]
        terrain = self._terrain
        paid = node[rec.exp(k)] if self._reverse else node[g]  # the cell whose cost it pays
        return step_g[k] + (length if terrain is None else length * terrain[paid])

    def gen_gs(self, events: Sequence[int]) -> list[float]:
        """:meth:`gen_g` of each of ``events``, which ascend (a step's successors, the open
        events of a frontier rebuilt in bulk): the same sums, with each generating step looked
        up once, not once an event -- its g and its parent's cell read once for all of its
        events among these.

        The last step looked up is remembered, so a run stepping either way finds the next
        one beside it, and the event that step took off (a step back puts it on the frontier
        again) has the step's own g: the entry the loop took off carried the g it was pushed
        with."""
        rec = self._rec
        if len(rec.iter_root) > 1:  # IDA*: a root among the events, each looked up
            return [self.gen_g(e) for e in events]
        step_g, ends, node, cost = rec.step_g, rec.step_end, rec.gen_node, self._move_cost
        assert step_g is not None, "only a cost-ordered search records costs"
        lo, hi, k, taken = self._gs_step
        n = len(events)
        if n == 1 and k and events[0] == taken:
            return [step_g[k]]
        out: list[float] = []
        i = 0
        while i < n:
            e = events[i]
            if not lo <= e < hi:  # find the step that generated events[i]
                if k + 1 < len(ends) and hi <= e < ends[k + 1]:
                    k += 1  # the next step's (a step forwards)
                elif k > 1 and ends[k - 2] <= e < lo:
                    k -= 1  # the step before's (a step back)
                else:
                    k = bisect_right(ends, e, k if e >= hi else 0)
                lo, hi = ends[k - 1] if k else 0, ends[k]
                taken = rec.exp(k) if k else -1
                self._gs_step = lo, hi, k, taken
            j = n if events[n - 1] < hi else bisect_left(events, hi, i)  # all of step k's
            if k:
                base, parent, terrain = step_g[k], node[taken], self._terrain
                if self._grid is None:  # a graph: each road's cost
                    step_cost = self._problem.step_cost
                    out += [base + step_cost(parent, node[e]) for e in events[i:j]]
                elif terrain is None:
                    out += [base + cost[node[e] - parent] for e in events[i:j]]
                elif self._reverse:  # the cell a move leaves: the parent
                    out += [base + cost[node[e] - parent] * terrain[parent] for e in events[i:j]]
                else:
                    out += [base + cost[node[e] - parent] * terrain[node[e]] for e in events[i:j]]
            else:
                out.append(0.0)  # the root, generated by no step
            i = j
        return out

    def gen_costs(self, g: int) -> tuple[float, float, float] | None:
        """Event ``g``'s cost so far, the heuristic's estimate from its cell and its priority
        (``g``, ``h`` and the priority the queue orders by); None for a queue or a stack."""
        if self._rec.step_g is None:
            return None
        cost = self.gen_g(g)
        p = self._rec.gen_node[g]
        h = self._estimate(p) if self._algo.informed else 0.0
        return cost, h, self._priority_at(cost, p)

    def priority_key(self, g: int) -> float:
        """The priority event ``g`` was pushed with (the frontier model's order)."""
        if self._algo.priority == "g":  # uniform-cost: the cost itself, no cell needed
            return self.gen_g(g)
        return self._priority_at(self.gen_g(g), self._rec.gen_node[g])

    def priority_keys(self, events: Sequence[int]) -> list[Any]:
        """:meth:`priority_key` of each of ``events``, which ascend (see :meth:`gen_gs`);
        under a tie rule other than the oldest first, ``(priority, tie)`` with the rule's key
        (:func:`~tui_search.engine.search.rules.tie_key`'s: the frontier model's order)."""
        costs = self.gen_gs(events)
        ties = self._recording.semantics.ties
        if self._algo.priority == "g":
            keys = costs
        else:
            priority, node = self._priority_at, self._rec.gen_node
            keys = [priority(g, node[e]) for g, e in zip(costs, events, strict=True)]
        if ties == "fifo":
            return keys
        return list(zip(keys, self._tie_keys(ties, events, costs), strict=True))

    def _tie_keys(self, ties: str, events: Sequence[int], costs: list[float]) -> list[Any]:
        """The tie rule's key of each of ``events`` (with their ``costs``)."""
        if ties == "lifo":
            return [-e for e in events]
        if ties in ("low-g", "high-g"):
            return costs if ties == "low-g" else [-g for g in costs]
        if ties == "node":
            return [self.gen_cell(e) for e in events]
        node, estimate = self._rec.gen_node, self._estimate
        h = [estimate(node[e]) for e in events]
        return h if ties == "low-h" else [-v for v in h]

    def pushed_again(self, g: int) -> int:
        """The next event of event ``g``'s cell, -1 when none was recorded.  A cost-ordered
        search pushes a cell again only with a lower g, so once that event is generated ``g``
        is *stale*: it will be discarded when it comes off.  (Kept as recorded, extended
        lazily: one dictionary look-up per event, paid only by those who ask.)"""
        self._index_same_cell()
        return self._next_same[g]

    def previous_same(self, g: int) -> int:
        """The event before ``g`` of ``g``'s cell, -1 when ``g`` is its first (what the cell's
        latest event is again once a step back undoes ``g``)."""
        if g >= len(self._prev_same):
            self._index_same_cell()
        return self._prev_same[g]

    def _index_same_cell(self) -> None:
        """Extend the next- and previous-event-of-the-same-cell tables over what was recorded
        since they were last extended."""
        nxt, prev, gen_node = self._next_same, self._prev_same, self._rec.gen_node
        if len(nxt) < len(gen_node):
            last = self._last_of_cell
            start = len(nxt)
            nxt.extend(array("i", [-1]) * (len(gen_node) - start))
            prev.extend(array("i", [-1]) * (len(gen_node) - start))
            for e in range(start, len(gen_node)):
                p = gen_node[e]
                before = last.get(p)
                if before is not None:
                    nxt[before] = e
                    prev[e] = before
                last[p] = e

    @property
    def admissible(self) -> bool:
        """Can the run's heuristic be trusted to find the cheapest path (True when none is
        used)?  On a graph, its estimate is checked against its roads."""
        warning = self.estimate_warning()  # (a graph's may say it is only inconsistent)
        return not warning or (isinstance(self._recording.board, Graph)
                               and "not admissible" not in warning)

    def estimate_warning(self) -> str:
        """:meth:`_estimate_warning`, worked out once (on a graph it searches the graph)."""
        if self._warning is None:
            self._warning = self._estimate_warning()
        return self._warning

    def _estimate_warning(self) -> str:
        """Why the run's heuristic may miss the cheapest path ("" when it cannot, or none is
        used): manhattan with diagonal moves on a grid; on a graph, an estimate that says more
        than the cheapest way to a goal somewhere
        (:func:`~tui_search.engine.search.estimate_check.estimate_faults`), else one whose drop
        along a road is more than the road's cost (A* may expand a node again)."""
        semantics = self._recording.semantics
        if not self._algo.informed:
            return ""
        board = self._recording.board
        if isinstance(board, Graph):  # (the check's module imported only for a graph)
            from tui_search.engine.search.estimate_check import estimate_faults

            return next(iter(estimate_faults(board, semantics.heuristic)), "")
        if admissible(semantics.heuristic, semantics.order):
            return ""
        from tui_search.engine.search.heuristics import INADMISSIBLE

        return INADMISSIBLE

    def gen_cell(self, g: int) -> State:
        """Event ``g``'s cell (a graph's: its node's name)."""
        return self._problem.unpad(self._rec.gen_node[g])

    def gen_parent(self, g: int) -> int:
        """The event expanded to generate ``g`` (-1 for a root): the expansion of the step
        whose successors include ``g``."""
        rec = self._rec
        it = bisect_right(rec.iter_root, g) - 1
        if rec.iter_root[it] == g:
            return -1
        return rec.exp(bisect_right(rec.step_end, g))

    def gen_dir(self, g: int) -> str:
        """The move that reached event ``g`` from its parent (``START`` for a root)."""
        parent = self.gen_parent(g)
        if parent < 0:
            return DIR_NAMES[ROOT_DIR]
        node = self._rec.gen_node
        return self._problem.move_name(node[parent], node[g])

    def gen_depth(self, g: int) -> int:
        """Event ``g``'s depth (moves from the root).  Where it is not recorded, the chain up
        to the root is walked once: what it met is remembered, so asking for every cell on
        screen costs each event once."""
        cheap = self.cheap_depth(g)
        if cheap is not None:
            return cheap
        depths = self._depths
        chain = []
        while g >= 0 and g not in depths:
            chain.append(g)
            g = self.gen_parent(g)
        depth = depths[g] if g >= 0 else -1
        for e in reversed(chain):
            depth += 1
            depths[e] = depth
        return depth

    def cheap_depth(self, g: int) -> int | None:
        """Event ``g``'s depth when it costs little to know: recorded (iterative deepening),
        or from the levels of a FIFO search; None for a stack, where only walking the chain
        up to the root (as deep as the map is big) would tell."""
        rec = self._rec
        if rec.gen_depth is not None:
            return rec.gen_depth[g]
        if not self._in_order:
            return None
        # A queue expands events in the order generated, so depth L+1 begins at
        # ``step_end[s]`` where depth L begins at event ``s``: by the end of step ``s`` every
        # event above has been taken off.  The level starts are kept, O(depth) over a run.
        levels, step_end = self._levels, rec.step_end
        while levels[-1] <= g and levels[-1] < len(step_end):
            nxt = step_end[levels[-1]]
            if nxt <= levels[-1]:
                break
            levels.append(nxt)
        return bisect_right(levels, g) - 1

    def expanded_at(self, g: int) -> int | None:
        """The step at which event ``g`` was expanded, if it was (in the whole record)."""
        if self._in_order:
            return g + 1 if g + 1 <= self._rec.steps else None
        table = self._gen_step
        if len(table) < len(self._rec.gen_node):  # extend it over what was recorded since
            filled = self._gen_step_filled
            table.extend(array("i", [-1]) * (len(self._rec.gen_node) - len(table)))
            for k in range(filled + 1, self._rec.steps + 1):
                table[self._rec.step_exp[k]] = k
            self._gen_step_filled = self._rec.steps
        step = table[g]
        return step if step > 0 else None

    def ancestors(self, g: int) -> list[int]:
        """Events from the root down to ``g`` (the compiled core's walk, when it runs, is
        this loop's twin: ``tests/engine/test_rebuild.py``)."""
        if self._walk is not None and g >= 0:
            rec = self._rec
            root = rec.iter_root[bisect_right(rec.iter_root, g) - 1]
            exp = rec.step_exp if isinstance(rec.step_exp, array) else None
            chain: list[int] = self._walk(rec.step_end, exp, root, g)
            return chain
        chain = []
        while g >= 0:
            chain.append(g)
            g = self.gen_parent(g)
        chain.reverse()
        return chain

    def path_gens(self) -> list[int]:
        """Events from the start to the goal (empty when not found or not yet recorded)."""
        if not self._rec.found:
            return []
        if self._path_gens is None:
            self._path_gens = self.ancestors(self._rec.goal_gen)
        return list(self._path_gens)

    def path(self) -> list[State] | None:
        if not self._rec.found:
            return None
        return [self.gen_cell(g) for g in self.path_gens()]

    def path_set(self) -> set[int]:
        """Padded cells on the path (empty until the goal is found)."""
        if self._path is None:
            if not self._rec.found:
                return set()
            self._path = {self._rec.gen_node[g] for g in self.path_gens()}
        return self._path

    def moves(self) -> list[str] | None:
        if not self._rec.found:
            return None
        # gen_dir of each event but the start, its parent the event before it on the path
        node, name = self._rec.gen_node, self._problem.move_name
        return [name(node[a], node[b]) for a, b in pairwise(self.path_gens())]

    def outcome(self) -> Outcome:
        """The result of the whole search (records it all first)."""
        self._recording.advance()
        rec = self._rec
        path = self.path()
        return Outcome(
            algorithm=self._recording.algorithm,
            semantics=self._recording.semantics,
            path=path,
            moves=self.moves(),
            expanded=rec.steps - len(rec.discarded),
            discarded=len(rec.discarded),
            generated=len(rec.gen_node),
            max_frontier=self._recording.peak_frontier(rec.steps),
            gave_up=rec.gave_up,
            cost=self._problem.path_cost(path),
        )

    def outcome_so_far(self, k: int) -> Outcome:
        """The figures after step ``k`` (recorded): the counts up to it, and the path only
        when ``k`` is the last step (at the last step, :meth:`outcome`)."""
        rec = self._rec
        discarded = bisect_right(rec.discarded, k)
        last = rec.done and k == rec.steps
        path = self.path() if last else None
        return Outcome(
            algorithm=self._recording.algorithm,
            semantics=self._recording.semantics,
            path=path,
            moves=self.moves() if last else None,
            expanded=k - discarded,
            discarded=discarded,
            generated=rec.step_end[k],
            max_frontier=self._recording.peak_frontier(k),
            gave_up=last and rec.gave_up,
            cost=self._problem.path_cost(path),
        )

    def step(self, k: int) -> Step:
        """Step ``k`` (1-based) as a value."""
        if k > self._rec.steps:
            self._recording.advance(k)
        if not 1 <= k <= self._rec.steps:
            raise IndexError(f"step {k} is outside 1..{self._rec.steps}")
        rec = self._rec
        succ = tuple((self.gen_dir(h), self.gen_cell(h)) for h in self._recording.succ_range(k))
        return Step(
            index=k,
            node=self.gen_cell(rec.exp(k)),
            successors=succ,
            depth_limit=self._recording.depth_limit(k),
            found_goal=rec.found and k == rec.steps,
            discarded=self._recording.is_discarded(k),
            f_limit=rec.iter_f_limit[self._recording.iteration_of(k)]
            if rec.iter_f_limit is not None else None,
        )

    def steps(self) -> Iterator[Step]:
        """Every step, in order, recording the search as it goes: the search as a generator
        of steps."""
        k = 1
        while True:
            if k > self._rec.steps:
                self._recording.advance(k)
                if k > self._rec.steps:
                    return
            yield self.step(k)
            k += 1


__all__ = ["DIR_NAMES", "EventTree"]

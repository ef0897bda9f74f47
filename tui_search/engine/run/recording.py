"""Recording a search: the fast loop run in chunks, up to a step limit, into a
:class:`~tui_search.engine.search.record.Record`, and what the record says of any step.

A :class:`~tui_search.engine.run.recorded.Run` has one: it drives the loop and owns the record (no
one else reads the record's arrays but the run's other parts, the tree of
:mod:`~tui_search.engine.run.queries` and the position of :mod:`~tui_search.engine.run.position`).
It knows the steps, never where the run is.
"""

# No future import: CONTRIBUTING.md, "Start-up".
from array import array
from bisect import bisect_right
from collections.abc import Generator, Iterator
from typing import TYPE_CHECKING, NamedTuple, cast

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.peak import PeakTable
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.loops.dispatch import Loop, loop_for
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import CHUNK, Record
from tui_search.engine.search.registry import Algorithm, get_algorithm
from tui_search.engine.search.state import State
from tui_search.engine.util.frozen import Frozen

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.search.graph_problem import GraphProblem

class Step(Frozen):
    """One step: the node taken off the frontier and the successors it added, in order (none
    for a discarded step, which took off a cell already expanded).  A :class:`Frozen` value,
    not a frozen slotted dataclass (which every start would pay for: benchmarks/README.md,
    "startup"), nor a NamedTuple (its field ``index`` would hide ``tuple.index``)."""

    __slots__ = ("depth_limit", "direction", "discarded", "f_limit", "found_goal", "index",
                 "node", "successors")
    _FIELDS = ("index", "node", "successors", "depth_limit", "found_goal", "discarded",
               "f_limit", "direction")

    index: int
    node: State  # a cell on a grid, a node's name on a graph
    successors: tuple[tuple[str, State], ...]
    depth_limit: int | None
    found_goal: bool
    discarded: bool
    f_limit: float | None  # IDA*'s limit on f
    direction: str  # a bidirectional search's "forward" or "backward" ("": one way)

    def __init__(self, index: int, node: State, successors: tuple[tuple[str, State], ...],
                 depth_limit: int | None = None, found_goal: bool = False,
                 discarded: bool = False, f_limit: float | None = None,
                 direction: str = "") -> None:
        self._assign(index=index, node=node, successors=successors, depth_limit=depth_limit,
                     found_goal=found_goal, discarded=discarded, f_limit=f_limit,
                     direction=direction)


#: The default step limit: expansions recorded before a run gives up (iterative deepening
#: on a big maze would record far more than memory holds: benchmarks/README.md, "limits").
#: A whole number of chunks, so a run stops exactly there; smaller limits (at most a chunk)
#: are exact too.
MAX_STEPS = 5000 * CHUNK


class Source(NamedTuple):
    """Where a recording's steps come from when they are not a registry search's: what the
    run is (its description: not in the registry, so no key, menu or setting offers it) and
    the loop that fills its record (a replayed trace: :mod:`~tui_search.engine.traces.as_run`)."""

    algo: Algorithm
    loop: Loop
    #: What the status line says of its rules, in a few words each, instead of how they
    #: differ from the defaults (a trace never declares them: its file, what was inferred).
    notes: tuple[str, ...] = ()
    #: The steps go from the goal (a bidirectional search's backward half,
    #: :mod:`~tui_search.engine.run.bidirectional`): a move's cost on a grid is that of the
    #: cell it leaves, the parent's, as the forward move it reverses enters it.
    reverse: bool = False


class Recording:
    """A search on a snapshot of a grid, recorded lazily in chunks.

    The grid is copied: editing the original afterwards never changes this run.
    """

    def __init__(self, grid: "Grid | Graph", algorithm: str, semantics: Semantics, max_steps: int,
                 source: Source | None = None, first_chunk: int = CHUNK) -> None:
        """Record ``grid`` (copied) searched with ``algorithm`` (its key) under ``semantics``,
        up to ``max_steps`` expansions (a :class:`~tui_search.engine.run.recorded.Run` gives the
        defaults); ``source``: the steps come from its loop instead, and ``algorithm`` is
        its description's key.  ``first_chunk``: the steps recorded at first (a check that
        may stop at step 1 asks for few); a loop that takes a chunk's size doubles it from
        there up to :data:`CHUNK`, the others pause every ``first_chunk`` steps."""
        self.algo = algo = get_algorithm(algorithm) if source is None else source.algo
        self.source = source
        semantics.check(algo)
        if max_steps < 1:
            raise ValueError("max_steps must be at least 1")
        #: What is searched: a copy of the grid or the graph given.
        self.board: "Grid | Graph" = grid.copy()
        self.algorithm = algorithm
        self.semantics = semantics.for_algorithm(algo)
        if semantics.recursive == "calls":  # its steps are held until their calls return
            from tui_search.engine.search.recursion import MAX_HELD

            max_steps = min(max_steps, MAX_HELD)
        self.problem: "Problem | GraphProblem"
        if isinstance(self.board, Grid):
            self.problem = Problem(self.board, semantics, semantics.goal_test_for(algo))
        else:  # a graph (its modules imported only for one)
            from tui_search.engine.search.graph_problem import GraphProblem

            self.problem = GraphProblem(self.board, semantics, semantics.goal_test_for(algo),
                                        algo.weighted)
        self.problem.max_steps = max_steps
        #: The raw record: read by the run's parts (tree, position) and by checks, never the app.
        self.rec = Record()
        self.max_steps = max_steps
        self._chunk = min(first_chunk, CHUNK)  # the next chunk's steps, doubling to CHUNK
        # The loops are generator functions: close() ends one that gives up.  The compiled
        # core's takes the steps a chunk may run (sent: None for its own); the others ignore it.
        loop = source.loop if source is not None else loop_for(
            algo, semantics, graph=not isinstance(self.board, Grid))
        self._loop = cast(Generator[int, int | None, None],
                          loop(self.problem, self.rec, min(self._chunk, max_steps)))
        self._peak = PeakTable(self.rec, self.iteration_of)
        self._advance_once()  # records the start (and the answer, when start == goal)

    @property
    def grid(self) -> Grid:
        """The grid searched (a run on a graph has none: :attr:`board`)."""
        board = self.board
        assert isinstance(board, Grid), "a run on a graph has no grid"
        return board

    def _advance_once(self, steps: int | None = None) -> None:
        """Record a chunk: up to ``steps`` more when the loop takes that, never past
        ``max_steps`` (the compiled core's runs on in C, with no pause between chunks)."""
        rec = self.rec
        if not rec.done:
            try:
                self._loop.send(steps)  # None for the first: a generator starts so
            except StopIteration:
                pass
            if rec.steps > self.max_steps or (not rec.done and rec.steps == self.max_steps):
                self._give_up()
            self._chunk = min(CHUNK, 2 * self._chunk)
            self._peak.extend(rec.steps)  # kept as it is recorded: the end costs no scan

    def _give_up(self) -> None:
        """Stop at exactly ``max_steps`` expansions (iterative deepening can take billions of
        steps on a big map): what the last chunk recorded past the limit is cut off, a goal
        found there included, and the loop is closed."""
        rec, n = self.rec, self.max_steps
        if rec.steps > n:
            events = rec.step_end[n]
            del rec.step_end[n + 1 :]
            if isinstance(rec.step_exp, array):
                del rec.step_exp[n + 1 :]
            if rec.step_g is not None:
                del rec.step_g[n + 1 :]
            if rec.step_next is not None:
                del rec.step_next[n + 1 :]
            del rec.gen_node[events:]
            while rec.discarded and rec.discarded[-1] > n:
                rec.discarded.pop()
            if rec.gen_depth is not None:
                del rec.gen_depth[events:]
            while rec.iter_first_step[-1] > n:
                rec.iter_first_step.pop()
                rec.iter_root.pop()
                rec.iter_limit.pop()
                if rec.iter_f_limit is not None:
                    rec.iter_f_limit.pop()
        rec.goal_gen = -1
        rec.done = rec.gave_up = True
        self._loop.close()

    def advance(self, until_step: int | None = None) -> bool:
        """Record more of the search: at least up to ``until_step`` (all of it when None), in
        chunks.  Returns True once the whole search is recorded."""
        rec = self.rec
        target = self.max_steps if until_step is None else min(until_step, self.max_steps)
        while not rec.done and (until_step is None or rec.steps < until_step):
            self._advance_once(max(self._chunk, target - rec.steps) if rec.steps < target else None)
        return rec.done

    def advance_some(self) -> bool:
        """Record one more chunk (for callers that compute in slices); True when done."""
        self._advance_once()
        return self.rec.done

    def iteration_of(self, k: int) -> int:
        """Index of the iteration that step ``k`` belongs to (step 0 is in iteration 0)."""
        return max(0, bisect_right(self.rec.iter_first_step, k) - 1)

    def depth_limit(self, k: int) -> int | None:
        """Iterative deepening's depth limit at step ``k`` (None for other searches)."""
        return self.rec.iter_limit[self.iteration_of(k)]

    def f_limits(self, k: int) -> tuple[float, float] | None:
        """IDA*'s limit on f at step ``k`` and the smallest f over it met by then in its
        iteration (inf: none yet); None for the other searches."""
        rec = self.rec
        if rec.iter_f_limit is None or rec.step_next is None:
            return None
        it = self.iteration_of(k)
        nxt = rec.step_next[k] if rec.iter_first_step[it] <= k else float("inf")
        return rec.iter_f_limit[it], nxt

    def iteration_span(self, it: int) -> tuple[int, int]:
        """First and last step of iteration ``it`` (as recorded)."""
        first = self.rec.iter_first_step[it]
        last = (self.rec.iter_first_step[it + 1] - 1
                if it + 1 < len(self.rec.iter_first_step) else self.rec.steps)
        return first, last

    def succ_range(self, k: int) -> range:
        """Generation events added by step ``k`` (k >= 1), in the order added."""
        rec = self.rec
        lo = rec.step_end[k - 1]
        it = self.iteration_of(k)
        if it and rec.iter_first_step[it] == k:
            lo += 1  # skip the new iteration's root, generated before its first expansion
        return range(lo, rec.step_end[k])

    def frontier_size_at(self, k: int) -> int:
        """The frontier's size after step ``k``."""
        rec = self.rec
        it = self.iteration_of(k)
        first = rec.iter_first_step[it]
        if k < first:
            return 1
        return (rec.step_end[k] - rec.iter_root[it]) - (k - first + 1)

    def peak_frontier(self, k: int) -> int:
        """The largest frontier size over steps 0..k (see :class:`PeakTable`)."""
        return self._peak.peak_frontier(k)

    def is_discarded(self, k: int) -> bool:
        """Did step ``k`` take off a cell already expanded, and so do nothing?"""
        d = self.rec.discarded
        i = bisect_right(d, k) - 1
        return i >= 0 and d[i] == k

    def discarded_upto(self, k: int) -> int:
        """Discarded steps among steps 1..k."""
        return bisect_right(self.rec.discarded, k)

    def discarded_steps(self) -> list[int]:
        """The discarded steps recorded so far, in order."""
        return list(self.rec.discarded)

    def expanded_event(self, k: int) -> int:
        """The event step ``k`` took off the frontier (k >= 1)."""
        return self.rec.step_exp[k]

    @property
    def goal_event(self) -> int:
        """The event that reached the goal, once found; -1 until then."""
        return self.rec.goal_gen

    def first_step_of_iteration(self, it: int) -> int:
        """The first step of iteration ``it`` (iterative deepening restarts; 1 for the
        only iteration of any other search)."""
        return self.rec.iter_first_step[it]

    def iteration_root(self, it: int) -> int:
        """The root event of iteration ``it`` (0, the start, for the only iteration of any
        other search)."""
        return self.rec.iter_root[it]

    def generated_at(self, g: int) -> int:
        """The step whose successors include event ``g`` (0 for the start; a later
        iteration's root counts as its first step's)."""
        return bisect_right(self.rec.step_end, g)

    def generated_by(self, k: int) -> int:
        """Events generated by the end of step ``k`` (all iterations counted): the number of
        the first event a later step adds."""
        return self.rec.step_end[k]

    def expansions(self, first: int, last: int) -> Iterator[tuple[int, range]]:
        """Steps ``first .. last`` of one iteration, in order: the event each took off and
        the events it added (:meth:`succ_range`'s), the record read at C speed."""
        rec = self.rec
        step_exp, step_end = rec.step_exp, rec.step_end
        it = self.iteration_of(first)
        # skip the new iteration's root
        if first <= last and it and rec.iter_first_step[it] == first:
            yield step_exp[first], range(step_end[first - 1] + 1, step_end[first])
            first += 1
        for j in range(first, last + 1):
            yield step_exp[j], range(step_end[j - 1], step_end[j])


__all__ = ["MAX_STEPS", "Recording", "Source", "Step"]

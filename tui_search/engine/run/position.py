"""A recorded run's position: the state of the search after ``k`` steps, moved either way.

At the position it answers what every cell is (unseen, frontier, expanded, being expanded, on
the path), what the frontier holds in order (its model, :mod:`~tui_search.engine.run.frontier`,
is the same for every algorithm), and what the search tree looks like.  A
:class:`~tui_search.engine.run.recorded.Run` has one, over its recording and its event tree.

Moving one step either way costs time proportional to that step's successors -- never to the
map or the run -- because the position is kept as counters per cell that a step increments and
its reversal decrements.  The only exception is crossing an iteration boundary of iterative
deepening backwards, which replays the previous iteration.  Memory: three counters per cell of
the map, allocated on first use (a run recorded and never moved or drawn pays for none).  A
long jump rebuilds them in bulk, in pieces, through :mod:`~tui_search.engine.run.rebuild`'s loops.
"""

from __future__ import annotations

from array import array
from bisect import bisect_left, bisect_right
from collections.abc import Iterator, Sequence
from enum import IntEnum

from tui_search.engine.run.frontier import FrontierModel, frontier_model
from tui_search.engine.run.queries import EventTree
from tui_search.engine.run.rebuild import kernels
from tui_search.engine.run.recording import Recording
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.state import State


class CellState(IntEnum):
    """What a free cell is at the current step (walls, start and goal come from the grid)."""

    UNSEEN = 0
    FRONTIER = 1  # generated, not yet expanded (the tutorial's black)
    EXPANDED = 2  # taken off the frontier and expanded (the tutorial's blue)
    CURRENT = 3  # the node expanded by the step just taken
    PATH = 4  # on the path, once the search has found the goal and the run is at its end


class Position:
    """Where a recorded run stands: step ``k`` and the counters that say what each cell is."""

    def __init__(self, recording: Recording, tree: EventTree) -> None:
        self._recording, self._tree = recording, tree
        self._rec = recording.rec  # the same record as long as the recording lives
        self._problem = recording.problem
        # The record's queries the steps use, bound once: no look-up through the parts a step.
        self._iteration_of = recording.iteration_of
        self._succ_range = recording.succ_range
        self._is_discarded = recording.is_discarded
        self._previous_same = tree.previous_same
        self._kernels = kernels()  # the rebuild's bulk loops
        # Per-cell counters at the current position: generation events and expansions.  A
        # discarded step is no expansion: visit on expand takes off a cell expanded before, but
        # greedy best-first takes equal h in push order, so a cell's stale (costlier) entry can
        # come off before its cheaper one is ever expanded -- the cell is not expanded yet.
        # Per cell too: the latest event of it at the position, in the current iteration (-1:
        # none).  Empty until first used (_hold); until then the position is step 0.
        self._n_gen, self._n_exp, self._last = array("i"), array("i"), array("i")
        self._held = False
        self._frontier = self._new_frontier()
        #: The position: steps taken (0: none, only the start is on the frontier).
        self.k = 0
        self._frontier.reset(self._rec.iter_root[0])

    def _hold(self) -> None:
        """Allocate the counters, at step 0: only the start is generated."""
        size = self._problem.size
        # (``array * n`` fills in C: a third of the time of copying ``bytes(4 * n)`` in)
        self._n_gen = array("i", [0]) * size
        self._n_exp = array("i", [0]) * size
        self._last = array("i", [-1]) * size
        self._held = True
        root = self._rec.iter_root[0]
        node = self._rec.gen_node[root]
        self._n_gen[node] += 1
        self._last[node] = root

    def _new_frontier(self) -> FrontierModel:
        calls = self._recording.generated_at if self._recording.semantics.recursive else None
        return frontier_model(self._recording.algo.frontier, self._tree.priority_keys, calls)

    def _enter_iteration(self, it: int) -> None:
        """Set the position to the start of iteration ``it``: only its root is generated."""
        root = self._rec.iter_root[it]
        node = self._rec.gen_node[root]
        self._n_gen[node] += 1
        self._last[node] = root
        self._frontier.reset(root)

    def _clear_iteration(self, it: int, upto_step: int) -> None:
        """Undo iteration ``it`` as it stands after ``upto_step``: zero its cells' counters."""
        rec = self._rec
        end = rec.step_end[upto_step]
        n_gen, n_exp, last = self._n_gen, self._n_exp, self._last
        for g in range(rec.iter_root[it], end):
            node = rec.gen_node[g]
            n_gen[node] = 0
            n_exp[node] = 0
            last[node] = -1

    def _forward(self) -> None:
        rec = self._rec
        k = self.k + 1
        it = self._iteration_of(k)
        if it and rec.iter_first_step[it] == k:
            self._clear_iteration(it - 1, k - 1)
            self._enter_iteration(it)
        g = rec.exp(k)
        succ = self._succ_range(k)
        if succ or not self._is_discarded(k):  # a discarded step expands nothing (see _n_exp)
            self._n_exp[rec.gen_node[g]] += 1
        n_gen, gen_node, last = self._n_gen, rec.gen_node, self._last
        for h in succ:
            p = gen_node[h]
            n_gen[p] += 1
            last[p] = h
        self._frontier.forward(g, succ)
        self.k = k

    def _backward(self) -> None:
        rec = self._rec
        k = self.k
        n_gen, gen_node, latest = self._n_gen, rec.gen_node, self._last
        succ = self._succ_range(k)
        root = rec.iter_root[self._iteration_of(k)]
        for h in reversed(succ):  # the newest first: each cell back to its event before
            p = gen_node[h]
            n_gen[p] -= 1
            before = self._previous_same(h)
            latest[p] = before if before >= root else -1
        g = rec.exp(k)
        if succ or not self._is_discarded(k):  # a step that added successors was no discard
            self._n_exp[gen_node[g]] -= 1
        self._frontier.backward(g, succ)
        self.k = k - 1
        it = self._iteration_of(k)
        if it and rec.iter_first_step[it] == k:
            # Back across an iteration boundary: show the previous iteration's final state.
            # (Only this iteration's root is generated now.)
            self._n_gen[gen_node[rec.iter_root[it]]] = 0
            latest[gen_node[rec.iter_root[it]]] = -1
            first, last = self._recording.iteration_span(it - 1)
            self.k = first - 1
            self._enter_iteration(it - 1)
            while self.k < last:
                self._forward()

    def step_to(self, k: int) -> None:
        """Move the position to recorded step ``k`` a step at a time."""
        if not self._held:
            self._hold()
        while self.k < k:
            self._forward()
        while self.k > k:
            self._backward()

    def _expanded_events(self, first: int, last: int) -> Sequence[int]:
        """Events expanded by steps ``first .. last``."""
        exp = self._rec.step_exp
        return exp[first : last + 1] if isinstance(exp, array) else range(first - 1, last)

    def rebuild_pieces(self, k: int, piece: int, cells: int) -> Iterator[float]:
        """Move the position to recorded step ``k`` in bulk, one bounded piece of work per
        ``next()`` (at most ``piece`` events or ``cells`` counters),
        so that a caller with an event loop (the app's ``end`` on a big map) stays responsive.
        Each piece yields the fraction of the work done.

        The counters are built on the side, from the record alone, and take the run's place
        after the last piece: until then the run stays whole at its old position (it may be
        shown, even moved), and dropping the generator leaves it as it was.  The work is
        linear in the events of ``k``'s iteration; the frontier model rebuilds itself from the
        events expanded (:meth:`~tui_search.engine.run.frontier.LifoFrontier.rebuild_pieces`)."""
        rec = self._rec
        k = max(0, min(k, rec.steps))
        it = self._iteration_of(k)
        root, first = rec.iter_root[it], rec.iter_first_step[it]
        end = rec.step_end[k] if k >= first else root + 1
        last = max(k, first - 1)  # steps first .. last expanded events of this iteration
        frontier = self._new_frontier()
        size = self._problem.size
        # Progress in events' worth of work: zeroing a counter costs about 1/32 of an event.
        n_exp_events = last - first + 1
        total = (3 * size / 32 + 2 * (end - root) + n_exp_events
                 + frontier.rebuild_work(root, end, n_exp_events))
        done = 0.0
        n_gen, n_exp, latest = array("i"), array("i"), array("i")
        loops = self._kernels
        for counters, fill in ((n_gen, 0), (n_exp, 0), (latest, -1)):
            for lo in range(0, size, cells):
                counters.extend(array("i", [fill]) * min(cells, size - lo))
                done += min(cells, size - lo) / 32
                yield done / total
        gen_node = rec.gen_node
        for lo in range(root, end, piece):
            loops.count_generated(gen_node, lo, min(lo + piece, end), n_gen, latest)
            done += 2 * min(piece, end - lo)
            yield done / total

        def expanded() -> Iterator[Sequence[int]]:
            for lo in range(first, last + 1, piece):
                yield self._expanded_events(lo, min(lo + piece, last + 1) - 1)

        discarded, step_exp = rec.discarded, rec.step_exp
        for lo in range(first, last + 1, piece):
            hi = min(lo + piece, last + 1)
            events = self._expanded_events(lo, hi - 1)
            loops.count_expanded(gen_node, events, n_exp)
            for s in discarded[bisect_left(discarded, lo) : bisect_left(discarded, hi)]:
                n_exp[gen_node[step_exp[s]]] -= 1  # taken off, but not expanded
            done += len(events)
            yield done / total
        for work in frontier.rebuild_pieces(root, end, expanded()):
            done += work
            yield done / total
        self._n_gen, self._n_exp, self._last = n_gen, n_exp, latest
        self._frontier, self.k, self._held = frontier, k, True

    def forward(self) -> bool:
        """One step forwards; False when already at the end."""
        if not self._held:
            self._hold()
        if self.k >= self._rec.steps:
            self._recording.advance(self.k + 1)
            if self.k >= self._rec.steps:
                return False
        self._forward()
        return True

    def backward(self) -> bool:
        """One step backwards; False at step 0."""
        if self.k == 0:
            return False  # (so the counters are held: only a step forwards leaves step 0)
        self._backward()
        return True

    def reset(self) -> None:
        """Back to step 0 (all counters cleared)."""
        if not self._held:
            return  # at step 0 already
        it = self._iteration_of(self.k)
        self._clear_iteration(it, self.k)
        self.k = 0
        self._enter_iteration(0)

    @property
    def at_end(self) -> bool:
        return self._rec.done and self.k == self._rec.steps

    def cell_state(self, cell: State) -> CellState:
        if not self._held:
            self._hold()
        p = self._problem.pad(cell)
        if self.at_end and self._rec.found and p in self._tree.path_set():
            return CellState.PATH
        if self.k and p == self._rec.gen_node[self._rec.exp(self.k)]:
            return CellState.CURRENT
        if self._n_exp[p]:
            return CellState.EXPANDED
        if self._n_gen[p]:
            return CellState.FRONTIER
        return CellState.UNSEEN

    def row_states(self, y: int, x0: int = 0, x1: int | None = None) -> list[int]:
        """States of cells ``x0 .. x1-1`` of row ``y`` (the fast path for drawing a line)."""
        if not self._held:
            self._hold()
        grid = self._problem
        assert isinstance(grid, Problem), "a graph has no rows"
        x1 = grid.width if x1 is None else x1
        base = (y + 1) * grid.stride + 1
        n_gen, n_exp = self._n_gen, self._n_exp
        out = [
            2 if n_exp[p] else (1 if n_gen[p] else 0) for p in range(base + x0, base + x1)
        ]
        if self.k:
            cur = self._rec.gen_node[self._rec.exp(self.k)]
            if base + x0 <= cur < base + x1:
                out[cur - base - x0] = CellState.CURRENT
        if self.at_end and self._rec.found:
            path = self._tree.path_set()
            for i, p in enumerate(range(base + x0, base + x1)):
                if p in path:
                    out[i] = CellState.PATH
        return out

    def current_node(self) -> State | None:
        """The node expanded by the step just taken (None at step 0)."""
        return self._problem.unpad(self._rec.gen_node[self._rec.exp(self.k)]) if self.k else None

    def changed_cells(self, k: int) -> list[State]:
        """Cells whose state step ``k`` changes (its node and its successors)."""
        rec = self._rec
        cells = [rec.gen_node[rec.exp(k)]]
        cells.extend(rec.gen_node[h] for h in self._succ_range(k))
        return [self._problem.unpad(p) for p in cells]

    def times_reached(self, cell: State) -> tuple[int, int]:
        """How often ``cell`` was generated and expanded (discarded steps not counted), up to
        the position, in the iteration shown."""
        if not self._held:
            self._hold()
        p = self._problem.pad(cell)
        return self._n_gen[p], self._n_exp[p]

    def last_event(self, cell: State) -> int | None:
        """The latest generation event of ``cell`` at the position, in the iteration shown
        (None: not reached): the event that decides its came-from arrow and its depth."""
        if not self._held:
            self._hold()
        g = self._last[self._problem.pad(cell)]
        return g if g >= 0 else None

    def is_stale(self, g: int) -> bool:
        """Is event ``g`` (of a cost-ordered search) superseded at the position: its cell
        pushed again since, with a lower g?  Never IDA*'s: it expands such an entry still."""
        if self._rec.iter_f_limit is not None:
            return False
        nxt = self._tree.pushed_again(g)
        return 0 <= nxt < self.generated

    def frontier_len(self) -> int:
        return len(self._frontier)

    def frontier(self, start: int = 0, stop: int | None = None) -> list[int]:
        """Generation events on the frontier, the next to come out first: a queue front to
        back, a stack top to bottom."""
        n = len(self._frontier)
        stop = n if stop is None else min(stop, n)
        return self._frontier.entries(max(0, min(start, stop)), stop)

    def added_now(self) -> range:
        """Events added by the step just taken (empty at step 0)."""
        return self._succ_range(self.k) if self.k else range(0)

    def children(self, g: int) -> range:
        """Events generated by expanding ``g``, if it has been expanded by the position."""
        step = self._tree.expanded_at(g)
        if step is None or step > self.k:
            return range(0)
        return self._succ_range(step)

    def tree_root(self) -> int:
        """The root event of the tree shown at the position (the current iteration's)."""
        return self._rec.iter_root[self._iteration_of(self.k)]

    def tree_size(self) -> int:
        """Events in the tree at the position."""
        return self._rec.step_end[self.k] - self.tree_root()

    @property
    def expanded(self) -> int:
        """Steps up to the position that expanded a node (discarded ones do not)."""
        return self.k - self.discarded

    @property
    def discarded(self) -> int:
        """Steps up to the position that took off a cell already expanded (visit on expand)."""
        return bisect_right(self._rec.discarded, self.k)

    @property
    def generated(self) -> int:
        return self._rec.step_end[self.k]


"""A recorded run: a search's steps, and the state of the search at any step k.

The app and the headless command stand on :class:`Run`.  Its three jobs live in three
modules: recording (:mod:`~tui_search.engine.recording`: the search computed lazily, in chunks,
into a compact :class:`~tui_search.engine.record.Record`), the record's queries
(:mod:`~tui_search.engine.queries`: parents, moves, the path), and, here, one *position* ``k``:
after ``k`` steps.  At that position it answers what every cell is (unseen, frontier, expanded,
being expanded, on the path), what the frontier holds in order (its model,
:mod:`~tui_search.engine.frontier`, is the same for every algorithm), and what the search tree
looks like.

Moving one step either way costs time proportional to that step's successors -- never to the
map or the run -- because the position is kept as counters per cell that a step increments and
its reversal decrements.  The only exception is crossing an iteration boundary of iterative
deepening backwards, which replays the previous iteration.  Memory grows with the steps (the
record) plus three counters per cell of the map.
"""

from __future__ import annotations

from array import array
from bisect import bisect_left, bisect_right
from collections.abc import Iterator, Sequence
from enum import IntEnum
from typing import Any

from tui_search.engine.frontier import FrontierModel, frontier_model
from tui_search.engine.grid import Cell
from tui_search.engine.queries import DIR_NAMES, RecordedTree
from tui_search.engine.record import ROOT_DIR
from tui_search.engine.recording import MAX_STEPS, Step


class CellState(IntEnum):
    """What a free cell is at the current step (walls, start and goal come from the grid)."""

    UNSEEN = 0
    FRONTIER = 1  # generated, not yet expanded (the tutorial's black)
    EXPANDED = 2  # taken off the frontier and expanded (the tutorial's blue)
    CURRENT = 3  # the node expanded by the step just taken
    PATH = 4  # on the path, once the search has found the goal and the run is at its end


class Run(RecordedTree):
    """A recorded search with a movable position (see the module's docstring)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        """The arguments of :class:`~tui_search.engine.recording.Recording`: the grid, the
        algorithm's key, the semantics and the step limit."""
        super().__init__(*args, **kwargs)
        size = len(self.problem.walls)
        # Per-cell counters at the current position: generation events and expansions.  A
        # discarded step is no expansion: visit on expand takes off a cell expanded before, but
        # greedy best-first takes equal h in push order, so a cell's stale (costlier) entry can
        # come off before its cheaper one is ever expanded -- the cell is not expanded yet.
        # (``array * n`` fills in C: a third of the time of copying ``bytes(4 * n)`` in)
        self._n_gen = array("i", [0]) * size
        self._n_exp = array("i", [0]) * size
        # Per cell: the latest event of it at the position, in the current iteration (-1: none).
        self._last = array("i", [-1]) * size
        self._frontier = self._new_frontier()
        self.k = 0
        self._enter_iteration(0)

    def _new_frontier(self) -> FrontierModel:
        return frontier_model(self.algo.frontier, self.priority_keys)

    def _enter_iteration(self, it: int) -> None:
        """Set the position to the start of iteration ``it``: only its root is generated."""
        root = self.rec.iter_root[it]
        node = self.rec.gen_node[root]
        self._n_gen[node] += 1
        self._last[node] = root
        self._frontier.reset(root)

    def _clear_iteration(self, it: int, upto_step: int) -> None:
        """Undo iteration ``it`` as it stands after ``upto_step``: zero its cells' counters."""
        rec = self.rec
        end = rec.step_end[upto_step]
        n_gen, n_exp, last = self._n_gen, self._n_exp, self._last
        for g in range(rec.iter_root[it], end):
            node = rec.gen_node[g]
            n_gen[node] = 0
            n_exp[node] = 0
            last[node] = -1

    def _forward(self) -> None:
        rec = self.rec
        k = self.k + 1
        it = self.iteration_of(k)
        if it and rec.iter_first_step[it] == k:
            self._clear_iteration(it - 1, k - 1)
            self._enter_iteration(it)
        g = rec.exp(k)
        succ = self.succ_range(k)
        if succ or not self.is_discarded(k):  # a discarded step expands nothing (see _n_exp)
            self._n_exp[rec.gen_node[g]] += 1
        n_gen, gen_node, last = self._n_gen, rec.gen_node, self._last
        for h in succ:
            p = gen_node[h]
            n_gen[p] += 1
            last[p] = h
        self._frontier.forward(g, succ)
        self.k = k

    def _backward(self) -> None:
        rec = self.rec
        k = self.k
        n_gen, gen_node, latest = self._n_gen, rec.gen_node, self._last
        succ = self.succ_range(k)
        root = rec.iter_root[self.iteration_of(k)]
        for h in reversed(succ):  # the newest first: each cell back to its event before
            p = gen_node[h]
            n_gen[p] -= 1
            before = self.previous_same(h)
            latest[p] = before if before >= root else -1
        g = rec.exp(k)
        if succ or not self.is_discarded(k):  # a step that added successors was no discard
            self._n_exp[gen_node[g]] -= 1
        self._frontier.backward(g, succ)
        self.k = k - 1
        it = self.iteration_of(k)
        if it and rec.iter_first_step[it] == k:
            # Back across an iteration boundary: show the previous iteration's final state.
            # (Only this iteration's root is generated now.)
            self._n_gen[gen_node[rec.iter_root[it]]] = 0
            latest[gen_node[rec.iter_root[it]]] = -1
            first, last = self._iter_span(it - 1)
            self.k = first - 1
            self._enter_iteration(it - 1)
            while self.k < last:
                self._forward()

    #: A jump longer than this rebuilds the state in bulk instead of stepping.
    REBUILD_AFTER = 512

    def goto(self, k: int) -> None:
        """Move the position to step ``k`` (clamped to the run), recording as needed."""
        k = max(0, k)
        if k > self.rec.steps:
            self.advance(k)
        k = min(k, self.rec.steps)
        if abs(k - self.k) > self.REBUILD_AFTER:
            self._rebuild(k)
        while self.k < k:
            self._forward()
        while self.k > k:
            self._backward()

    def _expanded_events(self, first: int, last: int) -> Sequence[int]:
        """Events expanded by steps ``first .. last``."""
        exp = self.rec.step_exp
        return exp[first : last + 1] if isinstance(exp, array) else range(first - 1, last)

    def _rebuild(self, k: int) -> None:
        """Set the position to step ``k`` in bulk (a long jump: ``end`` or ``home``)."""
        for _ in self.rebuild_pieces(k):
            pass

    #: Events one piece of :meth:`rebuild_pieces` handles: a few milliseconds of work.
    REBUILD_PIECE = 1 << 14

    #: Counters one piece of :meth:`rebuild_pieces` allocates (zeroing 2 MB: a millisecond or two; a
    #: 4096x4096 map's counters are 67 MB each, which took a tenth of a second in one go).
    REBUILD_CELLS = 1 << 19

    def rebuild_pieces(self, k: int) -> Iterator[float]:
        """Move the position to recorded step ``k`` in bulk, one bounded piece of work per
        ``next()`` (at most :attr:`REBUILD_PIECE` events or :attr:`REBUILD_CELLS` counters),
        so that a caller with an event loop (the app's ``end`` on a big map) stays responsive.
        Each piece yields the fraction of the work done.

        The counters are built on the side, from the record alone, and take the run's place
        after the last piece: until then the run stays whole at its old position (it may be
        shown, even moved), and dropping the generator leaves it as it was.  The work is
        linear in the events of ``k``'s iteration; the frontier model rebuilds itself from the
        events expanded (:meth:`~tui_search.engine.frontier.LifoFrontier.rebuild_pieces`)."""
        rec = self.rec
        k = max(0, min(k, rec.steps))
        it = self.iteration_of(k)
        root, first = rec.iter_root[it], rec.iter_first_step[it]
        end = rec.step_end[k] if k >= first else root + 1
        last = max(k, first - 1)  # steps first .. last expanded events of this iteration
        piece = self.REBUILD_PIECE
        frontier = self._new_frontier()
        size, cells = len(self.problem.walls), self.REBUILD_CELLS
        # Progress in events' worth of work: zeroing a counter costs about 1/32 of an event.
        n_exp_events = last - first + 1
        total = (3 * size / 32 + 2 * (end - root) + n_exp_events
                 + frontier.rebuild_work(root, end, n_exp_events))
        done = 0.0
        n_gen, n_exp, latest = array("i"), array("i"), array("i")
        for counters, fill in ((n_gen, 0), (n_exp, 0), (latest, -1)):
            for lo in range(0, size, cells):
                counters.extend(array("i", [fill]) * min(cells, size - lo))
                done += min(cells, size - lo) / 32
                yield done / total
        gen_node = rec.gen_node
        for lo in range(root, end, piece):
            for p in gen_node[lo : min(lo + piece, end)]:
                n_gen[p] += 1
            for g in range(lo, min(lo + piece, end)):
                latest[gen_node[g]] = g
            done += 2 * min(piece, end - lo)
            yield done / total

        def expanded() -> Iterator[Sequence[int]]:
            for lo in range(first, last + 1, piece):
                yield self._expanded_events(lo, min(lo + piece, last + 1) - 1)

        discarded, step_exp = rec.discarded, rec.step_exp
        for lo in range(first, last + 1, piece):
            hi = min(lo + piece, last + 1)
            events = self._expanded_events(lo, hi - 1)
            for g in events:
                n_exp[gen_node[g]] += 1
            for s in discarded[bisect_left(discarded, lo) : bisect_left(discarded, hi)]:
                n_exp[gen_node[step_exp[s]]] -= 1  # taken off, but not expanded
            done += len(events)
            yield done / total
        for work in frontier.rebuild_pieces(root, end, expanded()):
            done += work
            yield done / total
        self._n_gen, self._n_exp, self._last = n_gen, n_exp, latest
        self._frontier, self.k = frontier, k

    def forward(self) -> bool:
        """One step forwards; False when already at the end."""
        if self.k >= self.rec.steps:
            self.advance(self.k + 1)
            if self.k >= self.rec.steps:
                return False
        self._forward()
        return True

    def backward(self) -> bool:
        """One step backwards; False at step 0."""
        if self.k == 0:
            return False
        self._backward()
        return True

    def reset(self) -> None:
        """Back to step 0 (all counters cleared)."""
        it = self.iteration_of(self.k)
        self._clear_iteration(it, self.k)
        self.k = 0
        self._enter_iteration(0)

    @property
    def at_end(self) -> bool:
        return self.rec.done and self.k == self.rec.steps

    def cell_state(self, cell: Cell) -> CellState:
        p = self.problem.pad(cell)
        if self.at_end and self.found and p in self.path_set():
            return CellState.PATH
        if self.k and p == self.rec.gen_node[self.rec.exp(self.k)]:
            return CellState.CURRENT
        if self._n_exp[p]:
            return CellState.EXPANDED
        if self._n_gen[p]:
            return CellState.FRONTIER
        return CellState.UNSEEN

    def row_states(self, y: int, x0: int = 0, x1: int | None = None) -> list[int]:
        """States of cells ``x0 .. x1-1`` of row ``y`` (the fast path for drawing a line)."""
        x1 = self.grid.width if x1 is None else x1
        base = (y + 1) * self.problem.stride + 1
        n_gen, n_exp = self._n_gen, self._n_exp
        out = [
            2 if n_exp[p] else (1 if n_gen[p] else 0) for p in range(base + x0, base + x1)
        ]
        if self.k:
            cur = self.rec.gen_node[self.rec.exp(self.k)]
            if base + x0 <= cur < base + x1:
                out[cur - base - x0] = CellState.CURRENT
        if self.at_end and self.found:
            path = self.path_set()
            for i, p in enumerate(range(base + x0, base + x1)):
                if p in path:
                    out[i] = CellState.PATH
        return out

    def current_node(self) -> Cell | None:
        """The node expanded by the step just taken (None at step 0)."""
        return self.problem.unpad(self.rec.gen_node[self.rec.exp(self.k)]) if self.k else None

    def changed_cells(self, k: int) -> list[Cell]:
        """Cells whose state step ``k`` changes (its node and its successors)."""
        rec = self.rec
        cells = [rec.gen_node[rec.exp(k)]]
        cells.extend(rec.gen_node[h] for h in self.succ_range(k))
        return [self.problem.unpad(p) for p in cells]

    def depth_limit(self, k: int | None = None) -> int | None:
        """Iterative deepening's depth limit at step ``k`` (default: the position)."""
        return super().depth_limit(self.k if k is None else k)

    def peak_frontier(self, k: int | None = None) -> int:
        """The largest frontier size over steps 0..k (default: the position)."""
        return super().peak_frontier(self.k if k is None else k)

    def times_reached(self, cell: Cell) -> tuple[int, int]:
        """How often ``cell`` was generated and expanded (discarded steps not counted), up to
        the position, in the iteration shown."""
        p = self.problem.pad(cell)
        return self._n_gen[p], self._n_exp[p]

    def last_event(self, cell: Cell) -> int | None:
        """The latest generation event of ``cell`` at the position, in the iteration shown
        (None: not reached): the event that decides its came-from arrow and its depth."""
        g = self._last[self.problem.pad(cell)]
        return g if g >= 0 else None

    def is_stale(self, g: int) -> bool:
        """Is event ``g`` (of a cost-ordered search) superseded at the position: its cell
        pushed again since, with a lower g?"""
        nxt = self.pushed_again(g)
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
        return self.succ_range(self.k) if self.k else range(0)

    def children(self, g: int) -> range:
        """Events generated by expanding ``g``, if it has been expanded by the position."""
        step = self.expanded_at(g)
        if step is None or step > self.k:
            return range(0)
        return self.succ_range(step)

    def tree_root(self) -> int:
        """The root event of the tree shown at the position (the current iteration's)."""
        return self.rec.iter_root[self.iteration_of(self.k)]

    def tree_size(self) -> int:
        """Events in the tree at the position."""
        return self.rec.step_end[self.k] - self.tree_root()

    @property
    def expanded(self) -> int:
        """Steps up to the position that expanded a node (discarded ones do not)."""
        return self.k - self.discarded

    @property
    def discarded(self) -> int:
        """Steps up to the position that took off a cell already expanded (visit on expand)."""
        return bisect_right(self.rec.discarded, self.k)

    @property
    def generated(self) -> int:
        return self.rec.step_end[self.k]


__all__ = ["DIR_NAMES", "MAX_STEPS", "ROOT_DIR", "CellState", "Run", "Step"]

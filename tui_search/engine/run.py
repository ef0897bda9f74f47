"""A recorded run: a search's steps, and the state of the search at any step k.

The app and the headless command stand on :class:`Run`.  It records the search in a compact
:class:`~tui_search.engine.search.Record` (computed lazily, in slices: :meth:`Run.advance`) and
keeps one *position* ``k``: after ``k`` expansions.  At that position it answers what every cell
is (unseen, frontier, expanded, being expanded, on the path), what the frontier holds in order,
and what the search tree looks like.

Moving one step either way costs time proportional to that step's successors -- never to the
map or the run -- because the position is kept as counters per cell that a step increments and
its reversal decrements.  The only exception is crossing an iteration boundary of iterative
deepening backwards, which replays the previous iteration.  Memory grows with the steps (the
record) plus two counters per cell of the map.
"""

from __future__ import annotations

from array import array
import operator
from bisect import bisect_right
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from enum import IntEnum
from itertools import accumulate, compress

from tui_search.engine.algorithms import DEFAULT_ALGORITHM, Frontier, get_algorithm
from tui_search.engine.grid import DIRECTIONS, Cell, Grid
from tui_search.engine.outcome import Outcome
from tui_search.engine.search import CHUNK, ROOT_DIR, Problem, Record, loop_for
from tui_search.engine.semantics import DEFAULT_SEMANTICS, Semantics

#: Direction names indexed by stored direction code; a root is shown as START.
DIR_NAMES: tuple[str, ...] = DIRECTIONS + ("START",)


class CellState(IntEnum):
    """What a free cell is at the current step (walls, start and goal come from the grid)."""

    UNSEEN = 0
    FRONTIER = 1  # generated, not yet expanded (the tutorial's black)
    EXPANDED = 2  # taken off the frontier and expanded (the tutorial's blue)
    CURRENT = 3  # the node expanded by the step just taken
    PATH = 4  # on the path, once the search has found the goal and the run is at its end


@dataclass(frozen=True, slots=True)
class Step:
    """One expansion: the node taken off the frontier and the successors it added, in order."""

    index: int
    node: Cell
    successors: tuple[tuple[str, Cell], ...]
    depth_limit: int | None = None
    found_goal: bool = False
    discarded: bool = False


#: The default step limit: expansions recorded before a run gives up (iterative deepening
#: on a 512x512 maze takes ~75 million steps; 20 million take ~400 MB).  A whole number of
#: chunks, so a run stops exactly there; smaller limits (at most a chunk) are exact too.
MAX_STEPS = 5000 * CHUNK

class Run:
    """A search on a snapshot of a grid, recorded, with a movable position.

    The grid is copied: editing the original afterwards never changes this run.
    """

    def __init__(
        self,
        grid: Grid,
        algorithm: str = DEFAULT_ALGORITHM,
        semantics: Semantics = DEFAULT_SEMANTICS,
        max_steps: int = MAX_STEPS,
    ) -> None:
        self.algo = algo = get_algorithm(algorithm)
        semantics.check(algo)
        self.grid = grid.copy()
        self.algorithm = algorithm
        self.semantics = semantics
        self.problem = Problem(self.grid, semantics)
        self.rec = Record()
        if max_steps < 1:
            raise ValueError("max_steps must be at least 1")
        self.max_steps = max_steps
        self._loop = loop_for(algo, semantics)(self.problem, self.rec, min(CHUNK, max_steps))
        self._lifo = algo.frontier is Frontier.LIFO
        size = len(self.problem.walls)
        # Per-cell counters at the current position: generation events and expansions.
        self._n_gen = array("i", bytes(4 * size))
        self._n_exp = array("i", bytes(4 * size))
        self._stack: list[int] = []
        self._peak = array("i")
        self._gen_step = array("i")  # event -> step that expanded it (DFS, IDDFS; lazy)
        self._gen_step_filled = 0
        self._path: set[int] | None = None
        self.k = 0
        self._advance_once()  # records the start (and the answer, when start == goal)
        self._enter_iteration(0)

    # -- computing the record --------------------------------------------------------------
    def _advance_once(self) -> None:
        rec = self.rec
        if not rec.done:
            next(self._loop, None)
            if rec.steps > self.max_steps or (not rec.done and rec.steps == self.max_steps):
                self._give_up()
            self._extend_peak(rec.steps)  # kept as it is recorded: the end costs no scan

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
            del rec.gen_node[events:]
            while rec.discarded and rec.discarded[-1] > n:
                rec.discarded.pop()
            if rec.gen_depth is not None:
                del rec.gen_depth[events:]
            while rec.iter_first_step[-1] > n:
                rec.iter_first_step.pop()
                rec.iter_root.pop()
                rec.iter_limit.pop()
        rec.goal_gen = -1
        rec.done = rec.gave_up = True
        self._loop.close()

    def advance(self, until_step: int | None = None) -> bool:
        """Record more of the search: at least up to ``until_step`` (all of it when None), in
        chunks.  Returns True once the whole search is recorded."""
        rec = self.rec
        while not rec.done and (until_step is None or rec.steps < until_step):
            self._advance_once()
        return rec.done

    def advance_some(self) -> bool:
        """Record one more chunk (for callers that compute in slices); True when done."""
        self._advance_once()
        return self.rec.done

    @property
    def done(self) -> bool:
        """True when the whole search has been recorded."""
        return self.rec.done

    @property
    def found(self) -> bool:
        return self.rec.found

    @property
    def gave_up(self) -> bool:
        """True when the search was stopped at ``max_steps`` expansions, unfinished."""
        return self.rec.gave_up

    @property
    def recorded(self) -> int:
        return self.rec.steps

    @property
    def total(self) -> int | None:
        """Number of steps of the whole run, once known."""
        return self.rec.steps if self.rec.done else None

    # -- iterations ------------------------------------------------------------------------
    def iteration_of(self, k: int) -> int:
        """Index of the iteration that step ``k`` belongs to (step 0 is in iteration 0)."""
        return max(0, bisect_right(self.rec.iter_first_step, k) - 1)

    def depth_limit(self, k: int | None = None) -> int | None:
        return self.rec.iter_limit[self.iteration_of(self.k if k is None else k)]

    def _iter_span(self, it: int) -> tuple[int, int]:
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

    # -- moving the position ---------------------------------------------------------------
    def _enter_iteration(self, it: int) -> None:
        """Set the position to the start of iteration ``it``: only its root is generated."""
        root = self.rec.iter_root[it]
        node = self.rec.gen_node[root]
        self._n_gen[node] += 1
        self._stack = [root]

    def _clear_iteration(self, it: int, upto_step: int) -> None:
        """Undo iteration ``it`` as it stands after ``upto_step``: zero its cells' counters."""
        rec = self.rec
        end = rec.step_end[upto_step]
        n_gen, n_exp = self._n_gen, self._n_exp
        for g in range(rec.iter_root[it], end):
            node = rec.gen_node[g]
            n_gen[node] = 0
            n_exp[node] = 0

    def _forward(self) -> None:
        rec = self.rec
        k = self.k + 1
        it = self.iteration_of(k)
        if it and rec.iter_first_step[it] == k:
            self._clear_iteration(it - 1, k - 1)
            self._enter_iteration(it)
        g = rec.exp(k)
        if self._lifo:
            top = self._stack.pop()
            assert top == g, "the recorded step does not match the stack"
        self._n_exp[rec.gen_node[g]] += 1
        n_gen, gen_node = self._n_gen, rec.gen_node
        succ = self.succ_range(k)
        for h in succ:
            n_gen[gen_node[h]] += 1
        if self._lifo:
            self._stack.extend(succ)
        self.k = k

    def _backward(self) -> None:
        rec = self.rec
        k = self.k
        n_gen, gen_node = self._n_gen, rec.gen_node
        succ = self.succ_range(k)
        for h in succ:
            n_gen[gen_node[h]] -= 1
        g = rec.exp(k)
        self._n_exp[gen_node[g]] -= 1
        if self._lifo:
            del self._stack[len(self._stack) - len(succ):]
            self._stack.append(g)
        self.k = k - 1
        it = self.iteration_of(k)
        if it and rec.iter_first_step[it] == k:
            # Back across an iteration boundary: show the previous iteration's final state.
            # (Only this iteration's root is generated now.)
            self._n_gen[gen_node[rec.iter_root[it]]] = 0
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

    def _expanded_events(self, first: int, last: int) -> Iterable[int]:
        """Events expanded by steps ``first .. last``."""
        exp = self.rec.step_exp
        return exp[first : last + 1] if isinstance(exp, array) else range(first - 1, last)

    def _rebuild(self, k: int) -> None:
        """Set the position to step ``k`` in bulk (a long jump: ``end`` or ``home``)."""
        for _ in self.rebuild_pieces(k):
            pass

    #: Events one piece of :meth:`rebuild_pieces` handles: a few milliseconds of work.
    REBUILD_PIECE = 1 << 15
    #: Counters one piece of :meth:`rebuild_pieces` allocates (zeroing 4 MB: a few ms; a
    #: 4096x4096 map's counters are 67 MB each, which took a tenth of a second in one go).
    REBUILD_CELLS = 1 << 20

    def rebuild_pieces(self, k: int) -> Iterator[float]:
        """Move the position to recorded step ``k`` in bulk, one bounded piece of work per
        ``next()`` (at most :attr:`REBUILD_PIECE` events or :attr:`REBUILD_CELLS` counters),
        so that a caller with an event loop (the app's ``end`` on a big map) stays responsive.
        Each piece yields the fraction of the work done.

        The counters are built on the side, from the record alone, and take the run's place
        after the last piece: until then the run stays whole at its old position (it may be
        shown, even moved), and dropping the generator leaves it as it was.  The work is
        linear in the events of ``k``'s iteration.  Within an iteration every event is pushed
        in generation order and only the top is popped, so the stack at ``k`` is simply the
        events generated and not yet expanded, in generation order."""
        rec = self.rec
        k = max(0, min(k, rec.steps))
        it = self.iteration_of(k)
        root, first = rec.iter_root[it], rec.iter_first_step[it]
        end = rec.step_end[k] if k >= first else root + 1
        last = max(k, first - 1)  # steps first .. last expanded events of this iteration
        piece = self.REBUILD_PIECE
        lifo = self._lifo
        size, cells = len(self.problem.walls), self.REBUILD_CELLS
        # Progress in events' worth of work: zeroing a counter costs about 1/32 of an event.
        total = 2 * size / 32 + (end - root) * (2 if lifo else 1) + (last - first + 1)
        done = 0.0
        n_gen, n_exp = array("i"), array("i")
        for counters in (n_gen, n_exp):
            for lo in range(0, size, cells):
                counters.frombytes(bytes(4 * min(cells, size - lo)))
                done += min(cells, size - lo) / 32
                yield done / total
        gen_node = rec.gen_node
        for lo in range(root, end, piece):
            for p in gen_node[lo : min(lo + piece, end)]:
                n_gen[p] += 1
            done += min(piece, end - lo)
            yield done / total
        open_ = bytearray(b"\x01") * (end - root) if lifo else bytearray()
        for lo in range(first, last + 1, piece):
            hi = min(lo + piece, last + 1)
            expanded = self._expanded_events(lo, hi - 1)
            for g in expanded:
                n_exp[gen_node[g]] += 1
            if lifo:
                for g in expanded:
                    open_[g - root] = 0
            done += hi - lo
            yield done / total
        stack: list[int] = []
        if lifo:
            for lo in range(root, end, piece):
                hi = min(lo + piece, end)
                stack.extend(compress(range(lo, hi), open_[lo - root : hi - root]))
                done += hi - lo
                yield done / total
        self._n_gen, self._n_exp, self._stack, self.k = n_gen, n_exp, stack, k

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

    # -- what is at the position -----------------------------------------------------------
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

    # -- the frontier ----------------------------------------------------------------------
    def frontier_len(self) -> int:
        if self._lifo:
            return len(self._stack)
        return self.rec.step_end[self.k] - self.k

    def frontier(self, start: int = 0, stop: int | None = None) -> list[int]:
        """Generation events on the frontier, the next to be expanded first: queue front to
        back for BFS, stack top to bottom for DFS and iterative deepening."""
        n = self.frontier_len()
        stop = n if stop is None else min(stop, n)
        start = max(0, min(start, stop))
        if self._lifo:
            s = self._stack
            return [s[n - 1 - i] for i in range(start, stop)]
        return list(range(self.k + start, self.k + stop))

    def added_now(self) -> range:
        """Events added by the step just taken (empty at step 0)."""
        return self.succ_range(self.k) if self.k else range(0)

    # -- generation events and the search tree ---------------------------------------------
    def gen_cell(self, g: int) -> Cell:
        return self.problem.unpad(self.rec.gen_node[g])

    def gen_parent(self, g: int) -> int:
        """The event expanded to generate ``g`` (-1 for a root): the expansion of the step
        whose successors include ``g``."""
        rec = self.rec
        it = bisect_right(rec.iter_root, g) - 1
        if rec.iter_root[it] == g:
            return -1
        return rec.exp(bisect_right(rec.step_end, g))

    def gen_dir(self, g: int) -> str:
        parent = self.gen_parent(g)
        if parent < 0:
            return DIR_NAMES[ROOT_DIR]
        node = self.rec.gen_node
        return DIR_NAMES[self.problem.dir_of_offset[node[g] - node[parent]]]

    def gen_depth(self, g: int) -> int:
        if self.rec.gen_depth is not None:
            return self.rec.gen_depth[g]
        return len(self.ancestors(g)) - 1

    def expanded_at(self, g: int) -> int | None:
        """The step at which event ``g`` was expanded, if it was (in the whole record)."""
        if not self._lifo:
            return g + 1 if g + 1 <= self.rec.steps else None
        table = self._gen_step
        if len(table) < len(self.rec.gen_node):  # extend it over what was recorded since
            filled = self._gen_step_filled
            table.extend(array("i", [-1]) * (len(self.rec.gen_node) - len(table)))
            for k in range(filled + 1, self.rec.steps + 1):
                table[self.rec.step_exp[k]] = k
            self._gen_step_filled = self.rec.steps
        step = table[g]
        return step if step > 0 else None

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

    def ancestors(self, g: int) -> list[int]:
        """Events from the root down to ``g``."""
        chain = []
        while g >= 0:
            chain.append(g)
            g = self.gen_parent(g)
        chain.reverse()
        return chain

    # -- counts ----------------------------------------------------------------------------
    @property
    def expanded(self) -> int:
        """Steps up to the position that expanded a node (discarded ones do not)."""
        return self.k - self.discarded

    @property
    def discarded(self) -> int:
        """Steps up to the position that took off a cell already expanded (visit on expand)."""
        return bisect_right(self.rec.discarded, self.k)

    def is_discarded(self, k: int) -> bool:
        """Did step ``k`` take off a cell already expanded, and so do nothing?"""
        d = self.rec.discarded
        i = bisect_right(d, k) - 1
        return i >= 0 and d[i] == k

    @property
    def generated(self) -> int:
        return self.rec.step_end[self.k]

    def frontier_size_at(self, k: int) -> int:
        rec = self.rec
        it = self.iteration_of(k)
        first = rec.iter_first_step[it]
        if k < first:
            return 1
        return (rec.step_end[k] - rec.iter_root[it]) - (k - first + 1)

    def peak_frontier(self, k: int | None = None) -> int:
        """The largest frontier size over steps 0..k (default: the position): a look-up, the
        table being kept as the search is recorded."""
        k = self.k if k is None else k
        self._extend_peak(min(k, self.rec.steps))
        return self._peak[k]

    def _extend_peak(self, k: int) -> None:
        """Extend the running-maximum table of frontier sizes over steps 0..k.  Within one
        iteration the frontier size at step j is the events generated in it minus the
        expansions, ``step_end[j] - j - (root - first + 1)``: one vectorised pass a piece."""
        peak, rec = self._peak, self.rec
        lo = len(peak)
        while lo <= k:
            it = self.iteration_of(lo)
            first = rec.iter_first_step[it]
            if lo < first:  # step 0, before the first expansion: just the start
                sizes: Iterable[int] = [1]
                hi = lo + 1
            else:
                hi = (min(k + 1, rec.iter_first_step[it + 1])
                      if it + 1 < len(rec.iter_first_step) else k + 1)
                c = rec.iter_root[it] - first + 1
                sizes = map(operator.sub, rec.step_end[lo:hi], range(lo + c, hi + c))
            running = accumulate(sizes, max, initial=peak[-1] if peak else 0)
            next(running)  # the initial value is already in the table
            peak.extend(running)
            lo = hi

    # -- the answer ------------------------------------------------------------------------
    def path_gens(self) -> list[int]:
        """Events from the start to the goal (empty when not found or not yet recorded)."""
        return self.ancestors(self.rec.goal_gen) if self.rec.found else []

    def path(self) -> list[Cell] | None:
        if not self.rec.found:
            return None
        return [self.gen_cell(g) for g in self.path_gens()]

    def path_set(self) -> set[int]:
        """Padded cells on the path (empty until the goal is found)."""
        if self._path is None:
            if not self.rec.found:
                return set()
            self._path = {self.rec.gen_node[g] for g in self.path_gens()}
        return self._path

    def moves(self) -> list[str] | None:
        if not self.rec.found:
            return None
        return [self.gen_dir(g) for g in self.path_gens()[1:]]

    # -- steps as data ---------------------------------------------------------------------
    def step(self, k: int) -> Step:
        """Step ``k`` (1-based) as a value."""
        if k > self.rec.steps:
            self.advance(k)
        if not 1 <= k <= self.rec.steps:
            raise IndexError(f"step {k} is outside 1..{self.rec.steps}")
        rec = self.rec
        succ = tuple((self.gen_dir(h), self.gen_cell(h)) for h in self.succ_range(k))
        return Step(
            index=k,
            node=self.gen_cell(rec.exp(k)),
            successors=succ,
            depth_limit=self.depth_limit(k),
            found_goal=rec.found and k == rec.steps,
            discarded=self.is_discarded(k),
        )

    def steps(self) -> Iterator[Step]:
        """Every step, in order, recording the search as it goes: the search as a generator
        of steps."""
        k = 1
        while True:
            if k > self.rec.steps:
                self.advance(k)
                if k > self.rec.steps:
                    return
            yield self.step(k)
            k += 1

    def outcome(self) -> Outcome:
        """The result of the whole search (records it all first)."""
        self.advance()
        rec = self.rec
        return Outcome(
            algorithm=self.algorithm,
            semantics=self.semantics,
            path=self.path(),
            moves=self.moves(),
            expanded=rec.steps - len(rec.discarded),
            discarded=len(rec.discarded),
            generated=len(rec.gen_node),
            max_frontier=self.peak_frontier(rec.steps),
            gave_up=rec.gave_up,
        )


__all__ = ["CellState", "DIR_NAMES", "ROOT_DIR", "Run", "Step"]

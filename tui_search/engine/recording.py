"""Recording a search: the fast loop run in chunks, up to a step limit, into a
:class:`~tui_search.engine.record.Record`, and what the record says of any step.

This is the first of a recorded run's three jobs (:mod:`tui_search.engine.run` is the
position, :mod:`tui_search.engine.queries` the tree and the path): it knows the steps, never
where the run is.
"""

from __future__ import annotations

import operator
import sys
from array import array
from bisect import bisect_right
from collections.abc import Generator, Iterator
from dataclasses import dataclass
from functools import lru_cache
from typing import cast

from tui_search.engine.algorithms import DEFAULT_ALGORITHM, get_algorithm
from tui_search.engine.grid import Cell, Grid
from tui_search.engine.loops.dispatch import loop_for
from tui_search.engine.problem import Problem
from tui_search.engine.record import CHUNK, Record
from tui_search.engine.semantics import DEFAULT_SEMANTICS, Semantics


@dataclass(frozen=True, slots=True)
class Step:
    """One step: the node taken off the frontier and the successors it added, in order (none
    for a discarded step, which took off a cell already expanded)."""

    index: int
    node: Cell
    successors: tuple[tuple[str, Cell], ...]
    depth_limit: int | None = None
    found_goal: bool = False
    discarded: bool = False


#: The default step limit: expansions recorded before a run gives up (iterative deepening
#: on a 512x512 maze takes ~102 million steps; 20 million take ~400 MB).  A whole number of
#: chunks, so a run stops exactly there; smaller limits (at most a chunk) are exact too.
MAX_STEPS = 5000 * CHUNK


class Recording:
    """A search on a snapshot of a grid, recorded lazily in chunks.

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
        if max_steps < 1:
            raise ValueError("max_steps must be at least 1")
        self.grid = grid.copy()
        self.algorithm = algorithm
        self.semantics = semantics.for_algorithm(algo)
        self.problem = Problem(self.grid, semantics, semantics.goal_test_for(algo))
        self.rec = Record()
        self.max_steps = max_steps
        #: The cheapest path's cost when known from elsewhere (a benchmark's optimum for this
        #: map, start, goal and rules), for the app to show beside the path's.
        self.known_lowest: float | None = None
        # The loops are generator functions: close() ends one that gives up.
        self._loop = cast(Generator[int, None, None],
                          loop_for(algo, semantics)(self.problem, self.rec, min(CHUNK, max_steps)))
        self._peak = array("i")
        self._peak_memo: tuple[int, int] | None = None  # the last (k, peak) asked for
        self._advance_once()  # records the start (and the answer, when start == goal)

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
            if rec.step_g is not None:
                del rec.step_g[n + 1 :]
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

    def iteration_of(self, k: int) -> int:
        """Index of the iteration that step ``k`` belongs to (step 0 is in iteration 0)."""
        return max(0, bisect_right(self.rec.iter_first_step, k) - 1)

    def depth_limit(self, k: int) -> int | None:
        """Iterative deepening's depth limit at step ``k`` (None for other searches)."""
        return self.rec.iter_limit[self.iteration_of(k)]

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

    def frontier_size_at(self, k: int) -> int:
        rec = self.rec
        it = self.iteration_of(k)
        first = rec.iter_first_step[it]
        if k < first:
            return 1
        return (rec.step_end[k] - rec.iter_root[it]) - (k - first + 1)

    #: Steps per block of the peak table: a query scans at most one block.
    PEAK_BLOCK = 4096

    def peak_frontier(self, k: int) -> int:
        """The largest frontier size over steps 0..k: the running maximum of whole blocks,
        kept as the search is recorded (so the end costs no scan of the run), and at most
        one block's sizes scanned."""
        k = min(k, self.rec.steps)
        b = k // self.PEAK_BLOCK
        memo = self._peak_memo
        if memo is not None and memo[0] // self.PEAK_BLOCK == b and memo[0] <= k:
            # A step forwards (the app asks once a step): only the new steps are scanned.
            value = self._max_size(memo[0], k + 1, memo[1])
        else:
            self._extend_peak(b * self.PEAK_BLOCK)
            before = self._peak[b - 1] if b else 0
            value = self._max_size(b * self.PEAK_BLOCK, k + 1, before)
        self._peak_memo = (k, value)
        return value

    def _extend_peak(self, k: int) -> None:
        """Extend the table of block maxima over the whole blocks before step ``k``:
        ``_peak[b]`` is the largest frontier size over steps ``0 .. (b + 1) * PEAK_BLOCK - 1``."""
        peak, block = self._peak, self.PEAK_BLOCK
        while (len(peak) + 1) * block <= k:
            lo = len(peak) * block
            peak.append(self._max_size(lo, lo + block, peak[-1] if peak else 0))

    #: Steps per piece of a block that :meth:`_max_size` bounds before it reads them.
    PEAK_PIECE = 1024

    def _max_size(self, lo: int, hi: int, floor: int = 0) -> int:
        """The largest of ``floor`` and the frontier sizes over steps ``lo .. hi - 1``.

        Within one iteration (always, but for iterative deepening) the size at step ``j`` is
        ``step_end[j] - j - c``, and ``step_end`` never decreases, so no size over steps
        ``a .. b - 1`` exceeds ``step_end[b - 1] - a - c``: a piece of :attr:`PEAK_PIECE`
        steps whose bound does not beat the largest so far is not read (a DFS's stack
        draining, a frontier below its old peak); the others are read by
        :func:`_largest_size`, a piece at once.  Counted with callgrind on open 256², this
        took a recorded run's cost above its loop (nearly all of it this table) from 0.12x
        a bare BFS to 0.02x (a full DFS traversal) and from 0.55x to 0.18x (BFS visit on
        expand, 257,000 steps); pieces of 256 or 512 steps, or none, cost more."""
        rec = self.rec
        it = self.iteration_of(lo)
        first = rec.iter_first_step[it]
        if lo < first or self.iteration_of(hi - 1) != it:
            return max(floor, max(self._sizes(lo, hi)))
        c = rec.iter_root[it] - first + 1
        end, piece, best = rec.step_end, self.PEAK_PIECE, floor
        b = hi
        while b > lo:  # from the last piece, where a growing frontier is largest
            a = max(lo, b - piece)
            if end[b - 1] - a - c > best:  # else no size of this piece beats the best
                best = max(best, _largest_size(end, a, b, c))
            b = a
        return best

    def _sizes(self, lo: int, hi: int) -> Iterator[int]:
        """Frontier sizes at steps ``lo .. hi - 1``.  Within one iteration the size at step
        ``j`` is the events generated in it minus the steps taken:
        ``step_end[j] - j - (root - first + 1)`` (step 0, before any, is the start alone)."""
        rec = self.rec
        while lo < hi:
            it = self.iteration_of(lo)
            first = rec.iter_first_step[it]
            if lo < first:
                yield 1
                lo += 1
                continue
            end = (min(hi, rec.iter_first_step[it + 1])
                   if it + 1 < len(rec.iter_first_step) else hi)
            c = rec.iter_root[it] - first + 1
            yield from map(operator.sub, rec.step_end[lo:end], range(lo + c, end + c))
            lo = end

    def is_discarded(self, k: int) -> bool:
        """Did step ``k`` take off a cell already expanded, and so do nothing?"""
        d = self.rec.discarded
        i = bisect_right(d, k) - 1
        return i >= 0 and d[i] == k


@lru_cache(maxsize=64)
def _packed_constants(n: int, width: int) -> tuple[int, int, int, int]:
    """For ``n`` fields of ``width`` bits packed in an int (field ``i`` at bit ``i * width``):
    1 in every field, ``i`` in field ``i``, every bit of the ``n`` fields, and every field's
    top bit."""
    ones = ((1 << (n * width)) - 1) // ((1 << width) - 1)
    size = width // 8  # packed as the array's bytes are, so each field stays one element's
    iota = int.from_bytes(b"".join(i.to_bytes(size, sys.byteorder) for i in range(n)),
                          sys.byteorder)
    return ones, iota, (1 << (n * width)) - 1, ones << (width - 1)


def _largest_size(ends: array, lo: int, hi: int, c: int) -> int:
    """``max(ends[j] - j - c for j in range(lo, hi))`` with every size >= 0, in whole-int
    arithmetic, which CPython runs in C a machine word at a time: ~20 ns a step instead of
    ~100 for a ``max`` over a ``map`` of ``operator.sub`` (which makes three ints a step).

    The ends are packed into one int, a field of ``width`` bits a step; subtracting
    ``j + c`` from every field at once leaves the sizes there (no field borrows: none is
    negative).  Then halves are compared field by field until one field is left: with each
    field's top bit set in one half (sizes are below ``2 ** (width - 1)``), ``(a | top) - b``
    keeps that bit exactly where ``a >= b``, and the bit spread over its field picks ``a``
    there and ``b`` elsewhere."""
    n, width = hi - lo, 8 * ends.itemsize
    ones, iota, _, _ = _packed_constants(n, width)
    x = int.from_bytes(ends[lo:hi].tobytes(), sys.byteorder) - ((lo + c) * ones + iota)
    fields = 1 << (n - 1).bit_length()  # a power of two: the missing fields are 0, no size
    while fields > 1:
        fields //= 2
        _, _, low_mask, tops = _packed_constants(fields, width)
        low, high = x & low_mask, x >> (fields * width)
        a_wins = (((high | tops) - low) & tops) >> (width - 1)  # 1 in each field where a >= b
        x = low ^ ((low ^ high) & ((a_wins << width) - a_wins))
    return x


__all__ = ["MAX_STEPS", "Recording", "Step"]

"""The largest frontier a recorded run meets up to any step, kept as the search is recorded.

A run's statistics show the peak frontier at every position, and the headless summary at the
end: a table of block maxima, extended as each chunk is recorded, keeps that to at most one
block's sizes scanned, in whole-int arithmetic (:func:`_largest_size`), or by the compiled
core's ``largest_size`` when it runs.
"""

from __future__ import annotations

import operator
import sys
from array import array
from collections.abc import Callable, Iterator
from functools import lru_cache

from tui_search.engine.search.loops.compiled import selected
from tui_search.engine.search.record import Record


class PeakTable:
    """The running maximum of a record's frontier sizes, by blocks of steps."""

    #: Steps per block of the peak table: a query scans at most one block.
    PEAK_BLOCK = 4096

    #: Steps per piece of a block that :meth:`_max_size` bounds before it reads them.
    PEAK_PIECE = 1024

    def __init__(self, rec: Record, iteration_of: Callable[[int], int]) -> None:
        """The table of ``rec``, whose steps ``iteration_of`` places in their iterations."""
        self._rec = rec
        self._iteration_of = iteration_of
        self._peak = array("i")  # _peak[b]: the largest size over blocks 0..b
        self._memo: tuple[int, int] | None = None  # the last (k, peak) asked for

    def __len__(self) -> int:
        """Whole blocks in the table."""
        return len(self._peak)

    def peak_frontier(self, k: int) -> int:
        """The largest frontier size over steps 0..k: the running maximum of whole blocks,
        kept as the search is recorded (so the end costs no scan of the run), and at most
        one block's sizes scanned."""
        k = min(k, self._rec.steps)
        b = k // self.PEAK_BLOCK
        memo = self._memo
        if memo is not None and memo[0] // self.PEAK_BLOCK == b and memo[0] <= k:
            # A step forwards (the app asks once a step): only the new steps are scanned.
            value = self._max_size(memo[0], k + 1, memo[1])
        else:
            self.extend(b * self.PEAK_BLOCK)
            before = self._peak[b - 1] if b else 0
            value = self._max_size(b * self.PEAK_BLOCK, k + 1, before)
        self._memo = (k, value)
        return value

    def extend(self, k: int) -> None:
        """Extend the table of block maxima over the whole blocks before step ``k``:
        ``_peak[b]`` is the largest frontier size over steps ``0 .. (b + 1) * PEAK_BLOCK - 1``."""
        peak, block, rec = self._peak, self.PEAK_BLOCK, self._rec
        core = selected()[0]
        # One iteration (every search but iterative deepening): a block past step 0 is one
        # call of the compiled core's scan, which reads 4,096 sizes faster than _max_size
        # decides which of its pieces to read (benchmarks/README.md, "core").
        scan = core.largest_size if core is not None and len(rec.iter_first_step) == 1 else None
        first = rec.iter_first_step[0]
        c = rec.iter_root[0] - first + 1
        while (len(peak) + 1) * block <= k:
            lo = len(peak) * block
            before = peak[-1] if peak else 0
            if scan is not None and lo >= first:
                peak.append(max(before, scan(rec.step_end, lo, lo + block, c)))
            else:
                peak.append(self._max_size(lo, lo + block, before))

    def _max_size(self, lo: int, hi: int, floor: int = 0) -> int:
        """The largest of ``floor`` and the frontier sizes over steps ``lo .. hi - 1``.

        Within one iteration (always, but for iterative deepening) the size at step ``j`` is
        ``step_end[j] - j - c``, and ``step_end`` never decreases, so no size over steps
        ``a .. b - 1`` exceeds ``step_end[b - 1] - a - c``: a piece of :attr:`PEAK_PIECE`
        steps whose bound does not beat the largest so far is not read (a DFS's stack
        draining, a frontier below its old peak); the others are read by
        :func:`_largest_size`, a piece at once.  Nearly all a recorded run cost above its
        loop was this table, and this cut most of it (benchmarks/README.md, "choices");
        pieces of 256 or 512 steps, or none, cost more."""
        rec = self._rec
        it = self._iteration_of(lo)
        first = rec.iter_first_step[it]
        if lo < first:  # the steps before the iteration's first (step 0: the start alone)
            cut = min(first, hi)
            floor, lo = max(floor, max(self._sizes(lo, cut))), cut
            if lo == hi:
                return floor
            it = self._iteration_of(lo)
            first = rec.iter_first_step[it]
        if self._iteration_of(hi - 1) != it:
            return max(floor, max(self._sizes(lo, hi)))
        c = rec.iter_root[it] - first + 1
        end, piece, best = rec.step_end, self.PEAK_PIECE, floor
        core = selected()[0]
        largest = _largest_size if core is None else core.largest_size
        b = hi
        while b > lo:  # from the last piece, where a growing frontier is largest
            a = max(lo, b - piece)
            if end[b - 1] - a - c > best:  # else no size of this piece beats the best
                best = max(best, largest(end, a, b, c))
            b = a
        return best

    def _sizes(self, lo: int, hi: int) -> Iterator[int]:
        """Frontier sizes at steps ``lo .. hi - 1``.  Within one iteration the size at step
        ``j`` is the events generated in it minus the steps taken:
        ``step_end[j] - j - (root - first + 1)`` (step 0, before any, is the start alone)."""
        rec = self._rec
        while lo < hi:
            it = self._iteration_of(lo)
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


def _largest_size(ends: array[int], lo: int, hi: int, c: int) -> int:
    """``max(ends[j] - j - c for j in range(lo, hi))`` with every size >= 0, in whole-int
    arithmetic, which CPython runs in C a machine word at a time: a fraction of a ``max``
    over a ``map`` of ``operator.sub``, which makes three ints a step (benchmarks/README.md,
    "choices").

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


__all__ = ["PeakTable"]

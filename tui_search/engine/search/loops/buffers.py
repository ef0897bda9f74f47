"""The chunk buffers the fast loops write their record through.

A loop appends a chunk's new events, step ends, expanded events and discarded steps to Python
lists, and they go to the :class:`~tui_search.engine.search.record.Record`'s arrays in one pack each
before every pause: an ``array.append`` costs more than a list's.
"""

from __future__ import annotations

from array import array
from struct import pack

from tui_search.engine.search.record import Record


def _flush(arr: array[int], buf: list[int]) -> None:
    """Append ``buf`` to ``arr`` and empty it (a list of the caller's own, or a copy).
    ``array.append`` converts each int through ``PyArg_Parse``; a list append and one
    ``struct.pack`` per chunk cost less (benchmarks/README.md, "engine")."""
    if buf:
        arr.frombytes(pack(f"{len(buf)}i", *buf))
        buf.clear()


class _Buffers:
    """A chunk's new events, step ends, expanded events and discarded steps, as lists (see
    :func:`_flush`)."""

    def __init__(self, rec: Record) -> None:
        self.rec = rec
        self.nodes: list[int] = []
        self.ends: list[int] = []
        self.exps: list[int] = []
        self.discarded: list[int] = []

    def flush(self) -> None:
        rec = self.rec
        _flush(rec.gen_node, self.nodes)
        _flush(rec.step_end, self.ends)
        _flush(rec.discarded, self.discarded)
        if isinstance(rec.step_exp, array):
            _flush(rec.step_exp, self.exps)
        else:  # FIFO: step k expands event k-1, nothing to store
            self.exps.clear()

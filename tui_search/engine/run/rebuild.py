"""The bulk loops of a long jump's rebuild (``end``): each event's cell counted, each
expanded event's cell counted, events struck off a frontier's flags of open ones, and the
open ones listed.

A position (:mod:`~tui_search.engine.run.position`) and the frontier models
(:mod:`~tui_search.engine.run.frontier`) rebuild in pieces through these three loops.  When the
compiled core runs, its C twins (``_core_position.c``) do them; the Python ones here are the
fallback and the specification (``tests/engine/test_rebuild.py`` holds the two equal).
"""

# No future import: CONTRIBUTING.md, "Start-up".
from array import array
from collections.abc import Callable, Sequence
from itertools import compress
from typing import NamedTuple

from tui_search.engine.search.loops.compiled import selected


def count_generated(gen_node: "array[int]", lo: int, hi: int, n_gen: "array[int]",
                    latest: "array[int]") -> None:
    """For each event ``g`` in ``lo .. hi - 1``, in order: its cell's ``n_gen`` += 1 and its
    ``latest`` event is ``g``."""
    for p in gen_node[lo:hi]:
        n_gen[p] += 1
    for g in range(lo, hi):
        latest[gen_node[g]] = g


def count_expanded(gen_node: "array[int]", events: Sequence[int], n_exp: "array[int]") -> None:
    """For each event of ``events`` (an int array or a range): its cell's ``n_exp`` += 1."""
    for g in events:
        n_exp[gen_node[g]] += 1


def clear_events(flags: bytearray, events: Sequence[int], root: int) -> None:
    """``flags[g - root] = 0`` for each event ``g`` of ``events`` (an int array or a range)."""
    for g in events:
        flags[g - root] = 0


def open_events(flags: bytearray, root: int, lo: int, hi: int) -> list[int]:
    """The events ``g`` in ``lo .. hi - 1`` whose ``flags[g - root]`` is set, in order."""
    return list(compress(range(lo, hi), flags[lo - root : hi - root]))


class Kernels(NamedTuple):
    """The four loops, from one core."""

    count_generated: "Callable[[array[int], int, int, array[int], array[int]], None]"
    count_expanded: "Callable[[array[int], Sequence[int], array[int]], None]"
    clear_events: Callable[[bytearray, Sequence[int], int], None]
    open_events: Callable[[bytearray, int, int, int], list[int]]


PYTHON = Kernels(count_generated, count_expanded, clear_events, open_events)


def kernels() -> Kernels:
    """The loops of the core in force: the compiled module's, or the Python ones."""
    core = selected()[0]
    if core is None:
        return PYTHON
    return Kernels(core.count_generated, core.count_expanded, core.clear_events,
                   core.open_events)

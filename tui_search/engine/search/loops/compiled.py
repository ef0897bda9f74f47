"""The compiled search core: which core runs, and the loop that drives a compiled search.

The compiled module (``tui_search/engine/search/_core.c`` and ``_core_loops.c``, built at ``pip
install`` as an optional extension) records every algorithm under every choice into the same
:class:`~tui_search.engine.search.record.Record` the Python loops write, so nothing downstream knows
which core ran; its ``_core_position.c`` reads a record in bulk
(:mod:`~tui_search.engine.run.rebuild`).  It runs unless the environment variable
``TUI_SEARCH_CORE`` says ``python``, the module was not built (no compiler), or the build is stale
(the C source changed since: an editable install that was not rebuilt) -- then the Python loops run,
and a stale build says so on stderr.  ``TUI_SEARCH_CORE=compiled`` makes a missing or stale module
an error (:class:`CoreUnavailable`).  The reference loop stays the specification: a hypothesis test
in ``tests/engine`` holds both cores equal to it, array for array.
"""

from __future__ import annotations

import os
import sys
import zlib
from array import array
from collections.abc import Callable, Generator
from functools import cache, partial
from importlib import import_module
from pathlib import Path
from types import ModuleType

from tui_search.engine.search.heuristics import (
    CHEAPER_BY,
    DIAGONAL_EXTRA,
    HEURISTICS,
    consistent_order,
)
from tui_search.engine.search.loops.best_first import _blocked_sides_refused, _costed_moves
from tui_search.engine.search.problem import Problem
from tui_search.engine.search.record import Record
from tui_search.engine.search.registry import Algorithm, Frontier

#: The environment variable that chooses the core: ``python`` or ``compiled`` (unset: the
#: compiled one when it is built and fresh).
CORE_ENV = "TUI_SEARCH_CORE"
COMPILED, PYTHON = "compiled search core", "Python search core"
#: The C source, in the order ``setup.py`` hashes it.
SOURCES = tuple(Path(__file__).resolve().parents[1] / name
                for name in ("_core.c", "_core_loops.c", "_core_position.c", "_core.h"))

# The C loops (_core.h's enum), the heuristics' codes and advance()'s "paused".
_QUEUE, _IDDFS, _BEST = 0, 1, 2
_HEURISTIC_CODE = {"octile": 0, "euclidean": 1, "manhattan": 2, "chebyshev": 3, "zero": 4}
_PAUSED = -2
assert set(_HEURISTIC_CODE) == set(HEURISTICS)


class CoreUnavailable(RuntimeError):
    """``TUI_SEARCH_CORE=compiled`` asked for a core that is not built, or is stale."""


def source_hash() -> str:
    """The C source's fingerprint as the build takes it (setup.py embeds it in the module):
    the CRC-32 of its files' bytes in order, and their total size.  A staleness check, not a
    seal: any edit of up to 32 bits in a row changes the CRC, any other all but surely.  Not
    SHA-256: ``hashlib`` loads OpenSSL at every start (benchmarks/README.md, "startup"),
    ``zlib`` is already imported by Textual."""
    source = b"".join(path.read_bytes() for path in SOURCES)
    return f"crc32:{zlib.crc32(source):08x}:{len(source)}"


@cache
def selected() -> tuple[ModuleType | None, str]:
    """The compiled module (None for the Python loops) and what ``--version`` calls the core:
    ``compiled search core``, or ``Python search core`` (and why, when not asked for)."""
    choice = os.environ.get(CORE_ENV, "").strip().lower()
    if choice not in ("", "python", "compiled"):
        raise CoreUnavailable(f"{CORE_ENV}={choice!r}: use python or compiled")
    if choice == "python":
        return None, PYTHON
    try:
        core = import_module("tui_search.engine.search._core")
    except ImportError:
        if choice == "compiled":
            raise CoreUnavailable(f"{CORE_ENV}=compiled, but the compiled search core is not "
                                  "built (pip install needs a C compiler)") from None
        return None, f"{PYTHON}; the compiled one is not built"
    if all(path.exists() for path in SOURCES) and source_hash() != core.SOURCE_HASH:
        stale = "the compiled search core is stale (its C source changed since it was " \
                "built: pip install again)"
        if choice == "compiled":
            raise CoreUnavailable(stale)
        print(f"tui-search: {stale}; running the Python search core", file=sys.stderr)
        return None, f"{PYTHON}; the compiled one is stale"
    return core, COMPILED


def core_name() -> str:
    """What ``tui-search --version`` says of the core in force."""
    return selected()[1]


def compiled_loop(algorithm: Algorithm
                  ) -> Callable[[Problem, Record, int], Generator[int, int | None, None]] | None:
    """The compiled loop of ``algorithm`` (any choice), or None when the Python loops run."""
    core = selected()[0]
    return None if core is None else partial(_run, core, algorithm)


def _run(core: ModuleType, algorithm: Algorithm, problem: Problem, rec: Record, chunk: int
         ) -> Generator[int, int | None, None]:
    """Record ``problem`` searched with ``algorithm``: a chunk of steps per ``advance``, with
    a pause after each as the Python loops pause; a number sent in is the next chunk's steps
    (a long advance runs on in C, with no round trip every ``chunk`` steps)."""
    sem = problem.semantics
    loop = _IDDFS if algorithm.iterative else _BEST if algorithm.priority else _QUEUE
    lifo = algorithm.frontier is Frontier.LIFO
    if loop != _QUEUE or lifo:
        rec.step_exp = array("i", [-1])
    if loop == _BEST:
        rec.step_g = array("d", [0.0])
    if loop == _IDDFS:
        rec.gen_depth = array("i")
    priority = algorithm.priority or ""
    use_g, use_h = "g" in priority, "h" in priority
    weight = sem.weight if use_g and use_h else 1.0  # weighted A*: g + W·h
    close = use_g and (not use_h or consistent_order(sem.heuristic, sem.order, weight))
    moves = tuple((off, cost, cost + CHEAPER_BY, a, b)
                  for off, cost, a, b in _costed_moves(problem))
    on_push = problem.goal_test == "generate"
    search = core.Search(
        loop, lifo, sem.tree_search, sem.visit == "expand", use_g, use_h,
        _HEURISTIC_CODE[sem.heuristic], close, _blocked_sides_refused(problem), problem.stride,
        problem.start, problem.goal, DIAGONAL_EXTRA, problem.walls, moves,
        (rec.gen_node, rec.step_end, rec.step_exp if loop != _QUEUE or lifo else None,
         rec.step_g, rec.discarded, rec.gen_depth, rec.iter_first_step, rec.iter_root,
         rec.iter_limit),
        problem.goal if on_push else -1, -1 if on_push else problem.goal, len(moves),
        problem.terrain, problem.lowest, CHEAPER_BY, weight)
    steps = chunk
    while True:
        result = search.advance(steps)
        if result != _PAUSED:
            rec.goal_gen, rec.done = result, True
            return
        steps = (yield rec.steps) or chunk


__all__ = ["CORE_ENV", "CoreUnavailable", "compiled_loop", "core_name", "selected"]

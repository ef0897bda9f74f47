"""Python's cyclic garbage collector paused while objects that live as long as the program are
made: :func:`collector_paused`, around the ``tui-search`` command's imports
(:mod:`tui_search.launch`) and around Textual's import and the app's build
(:func:`tui_search.cli.run_app`).

Importing builds objects that live as long as the process (modules, classes, functions), so
the collector's passes over them free almost nothing: without the pause, importing the app
and Textual ran ~90 young-generation passes, ~4 % of a first frame's instructions and 20-30 ms
of its wall time (``benchmarks/README.md``, "startup").  Refcounting frees objects as usual
meanwhile; only cycles wait for the collector, which is back on before any work is done.
"""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def collector_paused() -> Iterator[None]:
    """The cyclic collector off inside the block, and as it was after it."""
    was_on = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_on:
            gc.enable()

"""Python's cyclic garbage collector paused while objects that live as long as the program are
made: :func:`collector_paused`, around the ``tui-search`` command's imports
(:mod:`tui_search.launch`) and around Textual's import, the app's build and its first frame
(:func:`collector_held`, :func:`tui_search.cli.main.run_app`).

Importing builds objects that live as long as the process (modules, classes, functions), so
the collector's passes over them free almost nothing: without the pause, importing the app
and Textual ran dozens of young-generation passes, a share of a first frame's instructions
and of its wall time (``benchmarks/README.md``, "startup").  Refcounting frees objects as usual
meanwhile; only cycles wait for the collector, which is back on once the first frame is drawn.
"""

from __future__ import annotations

import gc
from collections.abc import Callable, Iterator
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


@contextmanager
def collector_held() -> Iterator[Callable[[], None]]:
    """The cyclic collector off inside the block until the function it yields is called (the
    app calls it once its first frame is drawn: :func:`tui_search.cli.main.run_app`), and as it was
    after the block in any case.  Styling and drawing the first frame make objects that mostly
    live as long as the app, as importing does: with the collector on from ``app.run()``, the
    tutorial's first frame ran dozens more passes over them (counted with ``gc.callbacks``;
    benchmarks/README.md, "startup")."""
    was_on = gc.isenabled()
    gc.disable()

    def resume() -> None:
        if was_on:
            gc.enable()

    try:
        yield resume
    finally:
        resume()

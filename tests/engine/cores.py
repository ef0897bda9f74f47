"""Both search cores under test: the Python loops and the compiled core
(:mod:`tui_search.engine.search.loops.compiled`), forced in turn through ``TUI_SEARCH_CORE``."""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager

import pytest

from tui_search.engine.search.loops import compiled

CORES = ("python", "compiled")


@contextmanager
def using_core(name: str) -> Iterator[None]:
    """Run the body with the core ``name`` ("python" or "compiled") in force.  Where the
    compiled core is not built (no C compiler) its tests are skipped; where a compiler is,
    ``tests/test_build.py`` fails instead."""
    old = os.environ.get(compiled.CORE_ENV)
    os.environ[compiled.CORE_ENV] = name
    compiled.selected.cache_clear()
    try:
        try:
            compiled.selected()
        except compiled.CoreUnavailable as exc:
            pytest.skip(str(exc))
        yield
    finally:
        if old is None:
            del os.environ[compiled.CORE_ENV]
        else:
            os.environ[compiled.CORE_ENV] = old
        compiled.selected.cache_clear()

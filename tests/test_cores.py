"""The two search cores: which one runs and how it is named, and the same headless results
from both (the property tests of ``tests/engine/test_core.py`` hold them equal to the
reference, array for array)."""

from __future__ import annotations

import os
import shutil
import sys
import sysconfig
from array import array

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.engine.cores import using_core
from tests.helpers import MAPS, MOVINGAI
from tui_search.cli.main import main
from tui_search.engine.run.peak import _largest_size
from tui_search.engine.search.loops import compiled
from tui_search.engine.search.registry import ALGORITHMS

SMALL_MAPS = ["tutorial.txt", "exercise1-bfs-wins.txt", "exercise1-goal-moved.txt",
              "exercise2-dfs-longer.txt", "no-path.txt"]
MOVINGAI_MAPS = sorted(p.name for p in MOVINGAI.glob("*.map"))


def _scen(name: str) -> list[str]:
    """The map's first problem of its .scen, MovingAI's rules (no corner cutting)."""
    scen = MOVINGAI / f"{name}.scen"
    if not scen.exists():
        scen = next(MOVINGAI.glob(f"{name.removesuffix('.map')}*.scen"))
    return [str(MOVINGAI / name), "--scen", str(scen), "--scen-row", "0", "--corners", "never"]


def _headless(capsys, core: str, argv: list[str]) -> tuple[int, str, str]:
    with using_core(core):
        code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err


#: Headless iterative deepening streams the reference loop whatever the core (it can take
#: billions of steps): compared on the small maps only, where it takes a few.
RECORDED = sorted(key for key, a in ALGORITHMS.items() if not a.iterative)


@pytest.mark.parametrize(("argv", "key"), [
    *(([str(MAPS / m)], key) for m in SMALL_MAPS for key in sorted(ALGORITHMS)),
    *((_scen(m), key) for m in MOVINGAI_MAPS for key in RECORDED)],
    ids=lambda v: v if isinstance(v, str) else os.path.basename(v[0]))
def test_the_headless_json_is_the_same_under_both_cores(capsys, tmp_path, argv: list[str],
                                                        key: str) -> None:
    """Every algorithm on the tutorial, the exercise maps and the MovingAI maps: the same
    JSON (and, on the small maps, the same trace of every expansion)."""
    trace = tmp_path / "trace.jsonl"
    args = [*argv, "-a", key, "--headless", "--json"]
    if len(argv) == 1:
        args += ["--trace", str(trace)]
    python = _headless(capsys, "python", args), trace.read_text() if trace.exists() else ""
    assert python == (_headless(capsys, "compiled", args),
                      trace.read_text() if trace.exists() else "")
    assert python[0][0] in (0, 1) and python[0][2] == ""


@given(st.lists(st.integers(0, 3), min_size=1, max_size=300), st.data())
def test_the_peak_tables_scan_is_the_same_in_c(steps: list[int], data) -> None:
    """The compiled core's ``largest_size`` (the peak table's scan when it runs) is the
    Python one's: the largest ``ends[j] - j - c`` over a range (c is 0 but for iterative
    deepening), on the ends of a run: they never decrease, no frontier is below 0."""
    core = pytest.importorskip("tui_search.engine.search._core")
    ends, total = array("i", [1]), 1
    for generated in steps:  # each step adds 0-3 events; the frontier never goes below 0
        total += generated
        ends.append(max(total, len(ends)))
    lo = data.draw(st.integers(1, len(ends) - 1))
    hi = data.draw(st.integers(lo + 1, len(ends)))
    assert core.largest_size(ends, lo, hi, 0) == _largest_size(ends, lo, hi, 0)


def test_a_compiler_builds_the_compiled_core(monkeypatch) -> None:
    """Where the build has a C compiler (a fresh clone on CI: ``.ci/run``), ``pip install``
    built the module, and from this source: a missing or stale build fails here rather than
    skipping every test of the compiled core.  Without a compiler the Python core runs and
    the version line says the compiled one is not built."""
    compiler = (sysconfig.get_config_var("CC") or "cc").split()[0]
    monkeypatch.delenv(compiled.CORE_ENV, raising=False)
    compiled.selected.cache_clear()
    try:
        module, name = compiled.selected()
    finally:
        compiled.selected.cache_clear()
    if shutil.which(compiler) is None:
        assert (module, name) == (None, f"{compiled.PYTHON}; the compiled one is not built")
    else:
        assert module is not None and name == compiled.COMPILED, name


def test_the_core_is_named_by_version(capsys) -> None:
    for core, name in (("python", "(Python search core)"),
                       ("compiled", "(compiled search core)")):
        with using_core(core), pytest.raises(SystemExit):
            main(["--version"])
        assert capsys.readouterr().out.strip().endswith(name)


def test_a_missing_core_asked_for_is_one_line_of_error(capsys, monkeypatch) -> None:
    monkeypatch.setitem(sys.modules, "tui_search.engine.search._core", None)  # as if never built
    monkeypatch.setenv(compiled.CORE_ENV, "compiled")
    compiled.selected.cache_clear()
    try:
        assert main(["--version"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "compiled search core is not built" in err
        monkeypatch.setenv(compiled.CORE_ENV, "")
        compiled.selected.cache_clear()
        assert compiled.core_name() == "Python search core; the compiled one is not built"
    finally:
        compiled.selected.cache_clear()


def test_a_stale_build_falls_back_to_python_and_says_so(capsys, monkeypatch, tmp_path) -> None:
    """The C source changed since the build (an editable install not rebuilt): the Python
    loops run, stderr says why, and so does ``--version``."""
    pytest.importorskip("tui_search.engine.search._core")
    edited = tmp_path / "_core_loops.c"
    edited.write_bytes(compiled.SOURCES[1].read_bytes() + b"/* edited */\n")
    monkeypatch.setattr(compiled, "SOURCES", (compiled.SOURCES[0], edited, compiled.SOURCES[2]))
    monkeypatch.delenv(compiled.CORE_ENV, raising=False)
    compiled.selected.cache_clear()
    try:
        assert compiled.selected()[0] is None
        assert compiled.core_name() == "Python search core; the compiled one is stale"
        assert "stale" in capsys.readouterr().err
        monkeypatch.setenv(compiled.CORE_ENV, "compiled")
        compiled.selected.cache_clear()
        with pytest.raises(compiled.CoreUnavailable, match="stale"):
            compiled.selected()
    finally:
        compiled.selected.cache_clear()


def test_an_unknown_core_is_refused(monkeypatch) -> None:
    monkeypatch.setenv(compiled.CORE_ENV, "fortran")
    compiled.selected.cache_clear()
    try:
        with pytest.raises(compiled.CoreUnavailable, match="use python or compiled"):
            compiled.selected()
    finally:
        compiled.selected.cache_clear()
        os.environ.pop(compiled.CORE_ENV, None)

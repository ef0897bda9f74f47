"""Every test runs with its own empty config directory (``TUI_SEARCH_CONFIG_DIR``), so no test
reads or writes the user's real config file, and a theme remembered there cannot change a
snapshot.  Hypothesis checks no timing (no deadline, no "too slow" health check): on a busy
machine generating an example can take seconds, which says nothing about the code.

The suite leaves the clone as it found it: a file or folder that a test made or changed in the
repository (a served app's save folder in ``maps/``, a screenshot in the current folder) fails
the run, named (:func:`pytest_sessionfinish`; not with ``--snapshot-update``, which is meant
to change files).

Tiers (:func:`pytest_collection_modifyitems`, docs/10-testing.md): a test that drives the
app is marked ``app`` by what it uses, not by hand; the tests that build, serve or start whole
programs are marked ``slow``.  ``pytest -m "not app and not slow"`` is the fast tier."""

from __future__ import annotations

import ast
import functools
import inspect
import os
import subprocess
from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

from tui_search.tui.config import CONFIG_DIR_ENV

settings.register_profile("untimed", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("untimed")


@pytest.fixture(autouse=True)
def _own_config_dir(tmp_path_factory: pytest.TempPathFactory,
                    monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(CONFIG_DIR_ENV, str(tmp_path_factory.mktemp("config")))


ROOT = Path(__file__).resolve().parent.parent


def _changed_files() -> set[str] | None:
    """The repository's changed and untracked files (git's porcelain lines; ignored files
    are not among them), or None where there is no git work tree."""
    try:
        out = subprocess.run(["git", "status", "--porcelain", "--untracked-files=all"],
                             cwd=ROOT, capture_output=True, text=True, timeout=60, check=True)
    except (OSError, subprocess.SubprocessError):
        return None
    return set(out.stdout.splitlines())


def _checks_the_clone(config: pytest.Config) -> bool:
    """Only the controlling process checks (not each xdist worker), and not on a snapshot
    update."""
    return (not hasattr(config, "workerinput")
            and not config.getoption("--snapshot-update", default=False))


def pytest_sessionstart(session: pytest.Session) -> None:
    if _checks_the_clone(session.config):
        session.config.stash[_BEFORE] = _changed_files()


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    before = session.config.stash.get(_BEFORE, None)
    if before is None:
        return
    after = _changed_files()
    made = sorted((after or set()) - before)
    if made:
        print("\nThe tests changed the clone (each test must write only in its tmp_path):")
        for line in made:
            print(f"  {line}")
        session.exitstatus = pytest.ExitCode.TESTS_FAILED


_BEFORE = pytest.StashKey[set[str] | None]()


# -- Tiers ------------------------------------------------------------------------------------

#: Fixtures that drive the app: a test using one is marked ``app``.
APP_FIXTURES = frozenset({"snap_compare"})

#: Modules marked ``slow`` whole (their paths from tests/), each for what makes it slow.
SLOW_MODULES = {
    # pip builds the sdist and the wheel, compiles the C core and installs in fresh venvs
    "test_build.py",
    # each test starts the server (``tui-search --serve``) and its apps as processes
    "test_serve.py",
    "test_serve_trust.py",
    "test_serve_teacher.py",
    # every search run to its end on the largest generated maps (seconds a test)
    "tui/test_big_figures.py",
}
#: Tests marked ``slow`` by name (module path from tests/, ``::``, function), each for what
#: makes it slow.
SLOW_TESTS = {
    # a file of a megabyte read in a child process per format, to measure its memory
    "engine/test_untrusted_files.py::test_the_heaviest_files_take_at_most_ten_times_their_size",
    # a student's hostile search.py run in its fenced process until a limit stops it (a loop
    # waits out its time limit)
    "test_cli_search_py.py::test_a_hostile_search_py_is_one_line_exit_2",
    # the class load's floor: a fork server started and its apps timed
    "test_benchmarks_import.py::test_the_class_load_floor_is_measured_on_the_fork_server",
}
#: Modules marked ``app`` whole: an export films the app under Pilot
#: (``tui_search/export/frames.py``), in the test's process or in the command it runs.
APP_MODULES = {
    "export/test_exports.py",
    "export/test_export_cli.py",
}
TESTS = ROOT / "tests"


def drives_the_app(item: pytest.Item) -> bool:
    """Does this test run the app under Pilot?  It uses a fixture of :data:`APP_FIXTURES` (or
    a fixture of the tests' own that does what follows), or it calls ``run_test``, itself or
    through a function of the tests or the benchmarks that it names (``tutorial_in_big_cells``,
    ``least_difference``, ``jump._jump_once``, ... followed from module to module)."""
    if _in_modules(item, APP_MODULES):
        return True
    names = getattr(item, "fixturenames", ())
    if APP_FIXTURES & set(names):
        return True
    fixtures = getattr(getattr(item, "_fixtureinfo", None), "name2fixturedefs", {})
    if any(_runs_the_app(d.func) for name in names for d in fixtures.get(name, ())):
        return True
    function = getattr(item, "function", None)
    return function is not None and _runs_the_app(function)


def _runs_the_app(function: Callable[..., object]) -> bool:
    """Does ``function`` (its nested functions with it) call ``run_test``, or name a function
    of :data:`FOLLOWED` that does?  A function being asked about counts as not (a cycle)."""
    function = _inner(function)
    code = getattr(function, "__code__", None)
    if code is None:
        return False
    if code not in _RUNS_THE_APP:
        _RUNS_THE_APP[code] = False
        calls, names = _functions_in(code.co_filename).get(code.co_firstlineno, (False, ()))
        scope = getattr(function, "__globals__", {})
        named = (_named(scope, name) for name in names)
        _RUNS_THE_APP[code] = calls or any(
            _is_followed(thing) and _runs_the_app(thing) for thing in named)
    return _RUNS_THE_APP[code]


def _named(scope: dict[str, object], name: str) -> object:
    """What ``name`` (``f``, or ``module.f``) is in ``scope``."""
    first, _, attribute = name.partition(".")
    thing = scope.get(first)
    return getattr(thing, attribute, None) if attribute else thing


_RUNS_THE_APP: dict[object, bool] = {}


def _inner(function: Callable[..., object]) -> Callable[..., object]:
    """The function as written: under its decorators (``functools.wraps``), and under
    Hypothesis's ``@given`` (whose wrapper is compiled in a module of its own)."""
    function = inspect.unwrap(function)
    inner = getattr(getattr(function, "hypothesis", None), "inner_test", None)
    return function if inner is None else inspect.unwrap(inner)


#: The packages whose functions are followed: those written to drive the app, the tests' and
#: the benchmarks' (``benchmarks.jump``'s ``end`` under Pilot); not the app's, nor a library's.
FOLLOWED = ("tests", "benchmarks")


def _is_followed(thing: object) -> bool:
    """Is ``thing`` a function of :data:`FOLLOWED`?"""
    module = (getattr(thing, "__module__", None) or "").partition(".")[0]
    return callable(thing) and module in FOLLOWED and inspect.isfunction(_inner(thing))


#: The call that runs the app under Pilot (``App.run_test``).
DRIVER = "run_test"


@functools.cache
def _functions_in(filename: str) -> dict[int, tuple[bool, frozenset[str]]]:
    """Every function in a file (by the line its code starts on: its first decorator's):
    whether its body calls :data:`DRIVER` (or holds a script that does, to run in a process:
    a string, not a docstring, that calls it), and the names it uses, ``f`` and ``module.f``
    (not its decorators': a parametrized test names its cases there)."""
    try:
        tree = ast.parse(Path(filename).read_text(encoding="utf-8"))
    except (OSError, SyntaxError):
        return {}
    docstrings = {id(node.body[0].value) for node in ast.walk(tree)
                  if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef,
                                       ast.AsyncFunctionDef))
                  and node.body and isinstance(node.body[0], ast.Expr)
                  and isinstance(node.body[0].value, ast.Constant)}
    found = {}
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            first = min([node.lineno, *(d.lineno for d in node.decorator_list)])
            inside = [n for statement in node.body for n in ast.walk(statement)]
            calls = any(isinstance(n, ast.Call) and _callee(n.func) == DRIVER for n in inside) \
                or any(isinstance(n, ast.Constant) and isinstance(n.value, str)
                       and DRIVER + "(" in n.value and id(n) not in docstrings for n in inside)
            names = {n.id for n in inside if isinstance(n, ast.Name)} | {
                f"{n.value.id}.{n.attr}" for n in inside
                if isinstance(n, ast.Attribute) and isinstance(n.value, ast.Name)}
            found[first] = (calls, frozenset(names))
    return found


def _callee(func: ast.expr) -> str | None:
    """The name a call calls: ``f(...)``, ``x.f(...)``."""
    return func.attr if isinstance(func, ast.Attribute) else (
        func.id if isinstance(func, ast.Name) else None)


def is_slow(item: pytest.Item) -> bool:
    """Is this test in one of :data:`SLOW_MODULES`, or one of :data:`SLOW_TESTS`?"""
    module = _from_tests(str(item.path))
    if module in SLOW_MODULES:
        return True
    function = getattr(item, "function", None)
    name = getattr(_inner(function), "__name__", "") if function is not None else ""
    return f"{module}::{name}" in SLOW_TESTS


def _in_modules(item: pytest.Item, modules: set[str]) -> bool:
    """Is this test in one of ``modules`` (paths from tests/)?"""
    return _from_tests(str(item.path)) in modules


@functools.cache
def _from_tests(path: str) -> str | None:
    """A test module's path from tests/ (``tui/test_app.py``), None for one outside."""
    resolved = Path(path).resolve()
    return resolved.relative_to(TESTS).as_posix() if resolved.is_relative_to(TESTS) else None


def pytest_xdist_auto_num_workers(config: pytest.Config) -> int:
    """``-n auto`` (``addopts``): four workers when the app's tests run (a Pilot test mostly
    waits for the app to settle, so two cores keep four busy), one a core up to four for the
    fast tier (all CPU: a worker more only collects the tests once more)."""
    cores = os.cpu_count() or 1
    return min(cores, 4) if "not app" in (config.getoption("markexpr") or "") else 4


@pytest.hookimpl(tryfirst=True)  # before ``-m`` deselects by the marks
def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        if drives_the_app(item):
            item.add_marker(pytest.mark.app)
        elif only_app_tests(Path(item.path)):
            raise pytest.UsageError(
                f"{item.nodeid} does not drive the app, yet its module is left uncollected "
                "by the fast tier (tests/conftest.py's only_app_tests): mend the one or the other")
        if is_slow(item):
            item.add_marker(pytest.mark.slow)


def pytest_ignore_collect(collection_path: Path, config: pytest.Config) -> bool | None:
    """Under a tier without the app (``-m "not app ..."``), a module all of whose tests
    surely drive the app is not even imported: importing the app's tests costs each worker
    seconds for no test.  Only a sure answer leaves one out; a full run checks the answer
    (:func:`pytest_collection_modifyitems`)."""
    if "not app" in (config.getoption("markexpr") or "") and only_app_tests(collection_path):
        return True
    return None


@functools.cache
def only_app_tests(path: Path) -> bool:
    """Does the test module at ``path`` hold tests, each of which surely drives the app (it
    is one of :data:`APP_MODULES`, or each ``test_`` function takes the snapshot fixture or
    calls :data:`DRIVER`, itself or through a function of its module)?  Tests made any other
    way (a ``test_`` name assigned, a class) make the answer no."""
    path = path.resolve()
    if path.suffix != ".py" or not path.name.startswith("test_") \
            or not path.is_relative_to(TESTS):
        return False
    if path.relative_to(TESTS).as_posix() in APP_MODULES:
        return True
    try:
        text = path.read_text(encoding="utf-8")
        if DRIVER not in text and not any(fixture in text for fixture in APP_FIXTURES):
            return False  # (most modules: no parse)
        tree = ast.parse(text)
    except (OSError, SyntaxError):
        return False
    functions = {node.name: node for node in tree.body
                 if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))}
    tests = [node for name, node in functions.items() if name.startswith("test_")]
    others = [node for node in tree.body if not isinstance(
        node, (ast.FunctionDef, ast.AsyncFunctionDef)) and _names_a_test(node)]
    if not tests or others:
        return False
    calls = _functions_in(str(path))
    runs: dict[str, bool] = {}

    def runs_app(name: str, seen: frozenset[str] = frozenset()) -> bool:
        if name not in runs:
            node = functions[name]
            first = min([node.lineno, *(d.lineno for d in node.decorator_list)])
            direct, names = calls.get(first, (False, frozenset()))
            runs[name] = direct or any(
                other in functions and other not in seen and runs_app(other, seen | {name})
                for other in names)
        return runs[name]

    return all(any(arg.arg in APP_FIXTURES for arg in test.args.args) or runs_app(test.name)
               for test in tests)


def _names_a_test(node: ast.stmt) -> bool:
    """Does this top-level statement make a test other than by ``def`` (a class, or a
    ``test_`` name assigned or imported)?"""
    if isinstance(node, ast.ClassDef):
        return node.name.startswith("Test")
    names = [n.id for n in ast.walk(node) if isinstance(n, ast.Name)] + [
        (a.asname or a.name) for n in ast.walk(node) if isinstance(n, (ast.Import, ast.ImportFrom))
        for a in n.names]
    return any(name.startswith("test_") for name in names)

"""The tiers (docs/10-testing.md): tests/conftest.py's hook marks ``app`` every test that
drives the app, whatever way it does (a snapshot, ``run_test`` in the test, in a helper of its
module or of another or of the benchmarks, under ``@given``, in a fixture, in a script it
runs), and no test that does not; ``slow`` the build and serve modules.  ``--strict-markers``
makes a misspelt mark an error."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest

from tests import test_benchmarks_import, test_launch, test_readme
from tests.conftest import (
    APP_MODULES,
    ROOT,
    SLOW_MODULES,
    SLOW_TESTS,
    drives_the_app,
    is_slow,
    only_app_tests,
    pytest_collection_modifyitems,
    pytest_ignore_collect,
)
from tests.helpers import TUTORIAL
from tests.tui import (
    test_cells,
    test_file_names,
    test_quiz,
    test_quiz_snapshots,
    test_session,
    test_themes,
)
from tests.tui.test_cells import tutorial_in_big_cells
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp


class FakeItem:
    """What the hook reads of a collected test, and the marks it adds."""

    def __init__(self, function: Any = None, fixtures: dict[str, Any] | None = None,
                 path: Path = ROOT / "tests" / "test_example.py") -> None:
        self.function = function
        self.fixturenames = list(fixtures or {})
        self._fixtureinfo = SimpleNamespace(name2fixturedefs={
            name: [SimpleNamespace(func=func)] for name, func in (fixtures or {}).items()})
        self.path = path
        self.nodeid = f"{path.name}::{getattr(function, '__name__', '?')}"
        self.marks: list[str] = []

    def add_marker(self, mark: pytest.MarkDecorator) -> None:
        self.marks.append(mark.name)


def _not_a_fixture() -> None:
    """A fixture of a library (not the tests'): not looked into."""


async def _runs_the_tutorial() -> None:
    async with SearchApp(load_map(TUTORIAL)).run_test() as pilot:
        await pilot.press("n")


def _example_calling_a_helper_that_runs_the_app() -> None:
    import asyncio

    asyncio.run(_runs_the_tutorial())


async def _example_through_another_modules_helper() -> None:
    async with tutorial_in_big_cells() as (app, _pilot, _view):
        assert app.session.run is not None


def _example_fixture_running_the_app() -> Any:
    return _runs_the_tutorial()


def _example_speaking_of_run_test() -> None:
    """Not ``app.run_test()``: only its words."""


def _example_naming_only_the_app() -> None:
    assert SearchApp(load_map(TUTORIAL)).session.run is not None


@pytest.mark.parametrize("item", [
    # the snapshot fixture
    FakeItem(test_quiz_snapshots.test_the_quiz_after_a_wrong_answer,
             {"snap_compare": _not_a_fixture}),
    # run_test in the test itself, under the tests' @sync
    FakeItem(test_quiz.test_the_quiz_hides_the_order_asks_and_keeps_a_score),
    # in a helper of its module: an async context manager, and a plain coroutine
    FakeItem(test_cells.test_the_tutorial_fills_the_map_area_with_the_largest_cells_that_fit),
    FakeItem(test_themes.test_the_colour_blind_theme_keeps_every_kind_of_cell_apart),
    # under Hypothesis's @given, through a helper
    FakeItem(test_file_names.test_no_typed_name_makes_the_app_raise),
    FakeItem(_example_calling_a_helper_that_runs_the_app),
    FakeItem(_example_through_another_modules_helper),
    # through a benchmark's function, named by its module
    FakeItem(test_benchmarks_import.test_the_compare_section_drives_compare_mode_to_the_end),
    # a script that runs it, in a process of its own
    FakeItem(test_launch.test_the_first_frame_imports_no_module_only_a_key_needs),
    # a fixture of the tests' own
    FakeItem(_example_naming_only_the_app, {"app": _example_fixture_running_the_app}),
], ids=lambda item: item.function.__name__)
def test_a_test_that_drives_the_app_is_marked_app(item: FakeItem) -> None:
    assert drives_the_app(item)  # type: ignore[arg-type]
    pytest_collection_modifyitems([item])  # type: ignore[list-item]
    assert item.marks == ["app"]


@pytest.mark.parametrize("item", [
    FakeItem(test_session.test_one_search_is_one_pane_and_c_compares_the_pick),
    FakeItem(test_themes.test_the_config_dir_is_the_tests_own),
    # reads the app's bindings
    FakeItem(test_readme.test_the_keys_table_names_every_key_the_app_binds),
    FakeItem(_example_naming_only_the_app, {"other": _not_a_fixture}),  # builds, never runs
    FakeItem(_example_speaking_of_run_test),
], ids=lambda item: item.function.__name__)
def test_a_test_that_does_not_drive_the_app_is_not_marked(item: FakeItem) -> None:
    assert not drives_the_app(item)  # type: ignore[arg-type]
    pytest_collection_modifyitems([item])  # type: ignore[list-item]
    assert item.marks == []


def test_the_build_serve_and_biggest_map_modules_are_slow_and_no_other() -> None:
    for name in SLOW_MODULES:
        assert (ROOT / "tests" / name).is_file(), name  # a module renamed is not left out
    for name in ("test_build.py", "test_serve.py", "test_serve_trust.py",
                 "test_serve_teacher.py", "tui/test_big_figures.py"):
        item = FakeItem(_example_naming_only_the_app, path=ROOT / "tests" / name)
        assert is_slow(item)  # type: ignore[arg-type]
        pytest_collection_modifyitems([item])  # type: ignore[list-item]
        assert item.marks == ["slow"]
    for name in ("engine/test_core.py", "tui/test_served_files.py", "test_cli.py"):
        assert not is_slow(FakeItem(path=ROOT / "tests" / name))  # type: ignore[arg-type]


def test_the_export_modules_are_app_whole() -> None:
    for name in APP_MODULES:
        assert (ROOT / "tests" / name).is_file(), name
        item = FakeItem(_example_naming_only_the_app, path=ROOT / "tests" / name)
        assert drives_the_app(item)  # type: ignore[arg-type]
    assert not drives_the_app(FakeItem(  # type: ignore[arg-type]
        _example_naming_only_the_app, path=ROOT / "tests" / "test_cli.py"))


def test_the_marks_are_registered_and_strict(pytestconfig: pytest.Config) -> None:
    assert "--strict-markers" in pytestconfig.getini("addopts")
    assert "-n" in pytestconfig.getini("addopts")  # the full suite still runs on 4 workers
    registered = {line.split(":")[0] for line in pytestconfig.getini("markers")}
    assert {"app", "slow"} <= registered


def test_this_test_was_collected_unmarked(request: pytest.FixtureRequest) -> None:
    assert not drives_the_app(request.node)
    assert request.node.get_closest_marker("app") is None
    assert request.node.get_closest_marker("slow") is None


def test_naming_the_hook_or_parametrizing_over_app_tests_is_not_driving_the_app() -> None:
    """These tests name the hook's functions (their words speak of run_test) and, in their
    decorators, tests that drive the app: neither runs it."""
    for test in (test_a_test_that_drives_the_app_is_marked_app,
                 test_a_test_that_does_not_drive_the_app_is_not_marked,
                 test_the_build_serve_and_biggest_map_modules_are_slow_and_no_other):
        assert not drives_the_app(FakeItem(test))  # type: ignore[arg-type]


def test_the_heaviest_files_memory_test_is_slow_by_name() -> None:
    from tests.engine import test_untrusted_files as untrusted

    module = ROOT / "tests" / "engine" / "test_untrusted_files.py"
    heaviest = FakeItem(untrusted.test_the_heaviest_files_take_at_most_ten_times_their_size,
                        path=module)
    assert is_slow(heaviest)  # type: ignore[arg-type]
    other = FakeItem(untrusted.test_a_line_of_100_mb_is_refused_before_reading, path=module)
    assert not is_slow(other)  # type: ignore[arg-type]
    for name in SLOW_TESTS:
        path, _, test = name.partition("::")
        assert test in (ROOT / "tests" / path).read_text(), name  # a test renamed is not lost


def test_the_fast_tier_leaves_out_only_modules_whose_every_test_drives_the_app() -> None:
    tui = ROOT / "tests" / "tui"
    # snapshots only; Pilot tests only (through helpers of the module); the export modules
    for name in ("test_quiz_snapshots.py", "test_quiz.py", "test_cells.py"):
        assert only_app_tests(tui / name), name
    assert all(only_app_tests(ROOT / "tests" / name) for name in APP_MODULES)
    # a module with one test that needs no app (test_session: Session tests), the engine's,
    # this one, a module that is not a test module
    for path in (tui / "test_session.py", tui / "test_themes.py",
                 ROOT / "tests" / "engine" / "test_core.py", Path(__file__),
                 tui / "conftest.py", ROOT / "tests" / "helpers.py"):
        assert not only_app_tests(path), path


def test_a_module_left_out_by_the_fast_tier_that_holds_a_fast_test_stops_the_full_run() -> None:
    item = FakeItem(_example_naming_only_the_app, path=ROOT / "tests" / "tui" / "test_quiz.py")
    with pytest.raises(pytest.UsageError, match="does not drive the app"):
        pytest_collection_modifyitems([item])  # type: ignore[list-item]


def test_a_module_is_left_out_only_under_a_tier_without_the_app() -> None:
    path = ROOT / "tests" / "tui" / "test_quiz_snapshots.py"
    for expression, left_out in (("not app and not slow", True), ("not app", True),
                                 ("", None), ("app", None), ("not slow", None)):
        config = SimpleNamespace(getoption=lambda name, e=expression: e)
        assert pytest_ignore_collect(path, config) is left_out  # type: ignore[arg-type]
    config = SimpleNamespace(getoption=lambda name: "not app")
    assert pytest_ignore_collect(ROOT / "tests" / "tui" / "test_session.py",
                                 config) is None  # type: ignore[arg-type]

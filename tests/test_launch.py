"""The ``tui-search`` command's entry point: the collector is paused only while modules are
imported, and while the app is built and draws its first frame, and left as it was found."""

from __future__ import annotations

import ast
import functools
import gc
import subprocess
import sys
from pathlib import Path

import pytest

from tui_search.engine.util.collector import collector_paused


@pytest.mark.parametrize("was_on", [True, False])
def test_the_collector_is_off_inside_and_as_it_was_after(was_on: bool) -> None:
    before = gc.isenabled()
    try:
        (gc.enable if was_on else gc.disable)()
        with collector_paused():
            assert not gc.isenabled()
        assert gc.isenabled() is was_on
        with pytest.raises(RuntimeError), collector_paused():
            raise RuntimeError
        assert gc.isenabled() is was_on
    finally:
        (gc.enable if before else gc.disable)()


def test_the_command_runs_the_cli_with_the_collector_back_on(tmp_path) -> None:
    # python -m tui_search goes through launch.main, as the console script does; a headless
    # run reports whether the collector is on once the program's own work begins.
    probe = ("import gc, sys\n"
             "import tui_search.cli.headless as headless\n"
             "real = headless.run_headless\n"
             "def run_headless(*a):\n"
             "    print('collector', gc.isenabled())\n"
             "    return real(*a)\n"
             "headless.run_headless = run_headless\n"
             "sys.argv = ['tui-search', 'maps/tutorial.txt', '--headless']\n"
             "from tui_search.launch import main\n"
             "raise SystemExit(main())\n")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         check=False, cwd=_repo())
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines()[0] == "collector True"
    assert "path found" in out.stdout


def _repo() -> str:
    from pathlib import Path

    return str(Path(__file__).resolve().parents[1])


def test_the_app_starts_with_the_collector_off_and_frozen_and_it_is_on_after(monkeypatch) -> None:
    from tui_search.cli import main as cli
    from tui_search.tui.app import SearchApp

    seen: list[tuple[bool, int]] = []
    monkeypatch.setattr(SearchApp, "run",
                        lambda self, *a, **k: seen.append((gc.isenabled(), gc.get_freeze_count())))
    try:
        assert cli.main([f"{_repo()}/maps/tutorial.txt"]) == 0
    finally:
        gc.unfreeze()
    [(on, frozen)] = seen
    assert not on and frozen > 10_000  # Textual's modules and the app, out of the collector's way
    assert gc.isenabled()  # on again once the app is done, however it ended


def test_the_collector_is_on_again_once_the_first_frame_is_drawn(monkeypatch) -> None:
    import asyncio

    from tui_search.cli import main as cli
    from tui_search.tui.app import SearchApp

    seen: list[bool] = []

    def run(self: SearchApp, *a: object, **k: object) -> None:
        async def first_frame() -> None:
            async with self.run_test() as pilot:
                seen.append(gc.isenabled())  # the first frame is not drawn yet
                for _ in range(50):
                    if gc.isenabled():
                        break
                    await pilot.pause()
                seen.append(gc.isenabled())
        asyncio.run(first_frame())

    monkeypatch.setattr(SearchApp, "run", run)
    try:
        assert cli.main([f"{_repo()}/maps/tutorial.txt"]) == 0
    finally:
        gc.unfreeze()
    assert seen == [False, True]


@functools.cache
def _first_frame_modules() -> frozenset[str]:
    """The package's modules loaded once the tutorial's first frame is drawn, in a fresh
    process."""
    probe = ("import asyncio, sys\n"
             "from tui_search.cli.main import build_app\n"
             "from tui_search.cli.parse import parse_options\n"
             "app = build_app(parse_options(['maps/tutorial.txt']))\n"
             "async def first_frame():\n"
             "    async with app.run_test(size=(160, 50)) as pilot:\n"
             "        await pilot.pause()\n"
             "asyncio.run(first_frame())\n"
             "print(' '.join(sorted(m for m in sys.modules if m.startswith('tui_search'))))\n")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         check=False, cwd=_repo())
    assert out.returncode == 0, out.stderr
    return frozenset(out.stdout.split())


def test_the_first_frame_imports_no_module_only_a_key_needs() -> None:
    """The modules only a key or a flag needs are imported where first used
    (CONTRIBUTING.md, "Start-up"): the tutorial's first frame goes without them."""
    loaded = _first_frame_modules()
    assert "tui_search.tui.app" in loaded
    late = {"tui_search.engine.course.exercise_file", "tui_search.engine.course.grading",
            "tui_search.engine.course.condition", "tui_search.engine.search.pseudocode",
            "tui_search.cli.report",
            # the headless output, the traces' checks and replays, --scen's scenario files
            "tui_search.cli.headless", "tui_search.cli.traces", "tui_search.engine.maps.scenarios",
            # the map generators (ctrl+n, --generate): the help reads recipe_kinds only
            "tui_search.engine.maps.generate", "tui_search.engine.maps.mazes",
            "tui_search.engine.util.prng",
            # saving and opening, the settings dialog's choices
            "tui_search.tui.screens.file_commands", "tui_search.tui.screens.save_questions",
            "tui_search.tui.dialogs.settings_choice",
            # a seek (end, home), the challenge's check
            "tui_search.tui.model.seek", "tui_search.tui.screens.exercise_check"}
    assert not loaded & late


def classes_slow_to_import(source: str) -> list[str]:
    """The classes of ``source`` that cost every start that imports it: a dataclass (it
    compiles its methods at import), and a NamedTuple under ``from __future__ import
    annotations`` (typing compiles each string annotation)."""
    tree = ast.parse(source)
    future = any(isinstance(n, ast.ImportFrom) and n.module == "__future__" for n in tree.body)
    slow = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ClassDef):
            named = any(ast.unparse(b).endswith("NamedTuple") for b in node.bases)
            made = any("dataclass" in ast.unparse(d) for d in node.decorator_list)
            if made or (named and future):
                slow.append(node.name)
    return slow


def test_no_module_of_the_first_frame_defines_a_class_slow_to_import() -> None:
    """No dataclass, and no NamedTuple under ``from __future__ import annotations``, in the
    modules the tutorial's first frame imports: the rule of CONTRIBUTING.md, "Start-up",
    which the modules' one-line comments point to."""
    slow = []
    for name in sorted(_first_frame_modules()):
        base = Path(_repo()) / name.replace(".", "/")
        found = [p for p in (base.with_suffix(".py"), base / "__init__.py") if p.exists()]
        if found:  # else the compiled core
            source = found[0].read_text(encoding="utf-8")
            slow += [f"{name}.{cls}" for cls in classes_slow_to_import(source)]
    assert not slow


def test_the_import_check_sees_what_it_forbids() -> None:
    named = "from typing import NamedTuple\nclass P(NamedTuple):\n    x: int\n"
    future = "from __future__ import annotations\n"
    assert classes_slow_to_import(future + named) == ["P"]
    assert classes_slow_to_import(named) == []
    assert classes_slow_to_import("import dataclasses\n@dataclasses.dataclass\nclass D:\n"
                                  "    x: int\n") == ["D"]
    assert classes_slow_to_import(future + "class C:\n    x: int\n") == []

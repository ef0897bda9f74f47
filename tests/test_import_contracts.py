"""Who may import whom (read from the sources with :mod:`ast`, tests/import_graph.py):

* the engine never imports the app, the command line, Textual or Rich: it is the teaching
  model, run headless, by scripts and by the benchmarks;
* the widgets never import the app or its screens: a widget is given what it shows;
* a module that says it does without Textual (its docstring, or :data:`TEXTUAL_FREE`) never
  imports Textual or Rich, nor does any module of the package its imports run (in functions
  too) at import: the session model is tested without an app.  A module it reaches may
  import Textual in a function of its own, for the app to call (the themes do);
* no import circles in the package (imports in functions count, ``if TYPE_CHECKING:`` ones
  do not).

Each check is also shown to fail on a made-up violation.
"""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Callable

from tests.helpers import ROOT
from tests.import_graph import (
    Module,
    cycles,
    parse_modules,
    reach,
    read_package,
    runtime_graph,
    targets,
)

PACKAGE = ROOT / "tui_search"
UI_LIBRARIES = ("textual", "rich")
#: What a module without Textual may still use of Rich: the cell widths, a pure function, so
#: that its text is measured as Textual draws it.
WIDTHS = "rich.cells"
#: Held to no Textual whatever their docstrings say: the session model and what it stands on.
TEXTUAL_FREE = ("tui_search.tui.model.session", "tui_search.tui.model.seek",
                "tui_search.tui.view.layout", "tui_search.tui.model.quiz")
ENGINE_MAY_NOT = ("tui_search.tui", "tui_search.cli.main", *UI_LIBRARIES)
WIDGETS_MAY_NOT = ("tui_search.tui.app", "tui_search.tui.screens")


def forbidden_imports(modules: dict[str, Module], importer: Callable[[str], bool],
                      forbidden: tuple[str, ...]) -> list[str]:
    """Where a module ``importer`` accepts imports one of ``forbidden`` (or a module under
    one), ``if TYPE_CHECKING:`` imports included."""
    return [f"{m.path}:{imp.line}: imports {imp.module}"
            + (f" ({', '.join(imp.names)})" if imp.names else "")
            for m in modules.values() if importer(m.name)
            for imp in m.imports if any(imp.mentions(f) for f in forbidden)]


def textual_free(modules: dict[str, Module]) -> list[str]:
    """The modules held to no Textual: named in :data:`TEXTUAL_FREE` or saying so."""
    return sorted(name for name, m in modules.items()
                  if name in TEXTUAL_FREE or m.textual_free_by_docstring)


def ui_reached(modules: dict[str, Module], start: str) -> list[str]:
    """How ``start`` comes to import Textual or Rich: its own imports (``if TYPE_CHECKING:``
    ones included), and those at import of every module of the package its imports run."""
    found = [line for line in forbidden_imports(modules, lambda name: name == start,
                                                UI_LIBRARIES) if f"imports {WIDTHS}" not in line]
    for name, chain in reach(runtime_graph(modules), start).items():
        ui = [imp for imp in modules[name].imports if not (imp.type_checking or imp.deferred)
              and any(imp.mentions(u) for u in UI_LIBRARIES) and not imp.mentions(WIDTHS)]
        if name != start and ui:
            found.append(f"{' -> '.join(chain)}: {modules[name].path}:{ui[0].line}: imports "
                         + ", ".join(imp.module for imp in ui))
    return found


def in_engine(name: str) -> bool:
    return name == "tui_search.engine" or name.startswith("tui_search.engine.")


def in_widgets(name: str) -> bool:
    return name.startswith("tui_search.tui.widgets.")


def package() -> dict[str, Module]:
    modules = parse_modules(read_package(PACKAGE))
    assert len([m for m in modules if in_engine(m)]) > 20, "the engine is not where this looks"
    return modules


# -- the contracts, on the package ------------------------------------------------------------
def test_the_engine_imports_no_app_no_command_line_no_textual_or_rich() -> None:
    bad = forbidden_imports(package(), in_engine, ENGINE_MAY_NOT)
    assert not bad, "the engine must not depend on the app or the UI libraries:\n" + "\n".join(bad)


def test_the_widgets_import_neither_the_app_nor_its_screens() -> None:
    modules = package()
    assert len([m for m in modules if in_widgets(m)]) > 5, "the widgets are not where this looks"
    bad = forbidden_imports(modules, in_widgets, WIDGETS_MAY_NOT)
    assert not bad, "a widget is given what it shows; it does not reach for the app:\n" + "\n".join(
        bad)


def test_the_modules_without_textual_import_none_even_indirectly() -> None:
    modules = package()
    held = textual_free(modules)
    assert len(held) > 5, "no module says it does without Textual: the check looks wrong"
    bad = [line for name in held for line in ui_reached(modules, name)]
    assert not bad, "a module without Textual (its docstring says so) imports it:\n" + "\n".join(
        bad)


def test_no_import_circles() -> None:
    found = cycles(runtime_graph(package()))
    assert not found, "import circles (imports in functions count):\n" + "\n".join(
        " -> ".join(c) for c in found)


def test_no_circles_through_type_checking_imports_either() -> None:
    """A dependency goes one way even for the type checker: a module a ``TYPE_CHECKING``
    import names does not import its importer back (files/save_questions, app/commands were
    tied so)."""
    modules = package()
    graph = {name: set().union(*(targets(m, imp, modules) for imp in m.imports))
             for name, m in modules.items()}
    found = cycles(graph)
    assert not found, "import circles (TYPE_CHECKING imports included):\n" + "\n".join(
        " -> ".join(c) for c in found)


def test_the_engine_and_the_command_line_load_without_textual_or_rich() -> None:
    """What the AST checks say, at run time: every engine module and the command line
    imported, in a fresh interpreter, load neither."""
    names = sorted(m for m in package() if in_engine(m)) + ["tui_search.cli.main"]
    code = ("import sys\n"
            f"for name in {names!r}: __import__(name)\n"
            f"bad = [m for m in sys.modules if m.split('.')[0] in {UI_LIBRARIES!r}]\n"
            "print(bad); sys.exit(1 if bad else 0)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=False, cwd=ROOT)
    assert out.returncode == 0, out.stdout + out.stderr


# -- each check fails on a violation ------------------------------------------------------------
SYNTHETIC = {
    "pkg": "",
    "pkg.engine": "",
    "pkg.engine.grid": '"""Cells."""\nimport os\n',
    "pkg.engine.run": ("from typing import TYPE_CHECKING\nfrom pkg.engine import grid\n"
                       "if TYPE_CHECKING:\n    from textual.app import App\n"
                       "def show():\n    from pkg import tui\n"),
    "pkg.tui": "",
    "pkg.tui.app": "from pkg.tui.widgets.grid_view import GridView\n",
    "pkg.tui.widgets": "",
    "pkg.tui.widgets.grid_view": "from textual.widget import Widget\nfrom ..app import X\n",
    "pkg.tui.model": '"""The state (no Textual)."""\nfrom . import helper, lazy\n',
    "pkg.tui.helper": "import rich.cells\nimport rich.text\n",
    "pkg.tui.lazy": "def themes():\n    import textual.theme\n",
    "pkg.tui.plain": '"""No Textual here."""\ndef draw():\n    import textual.widget\n',
    "pkg.tui.typed": ('"""Without Textual at run time."""\nif TYPE_CHECKING:\n'
                      "    import pkg.tui.app\nelse:\n    import pkg.engine.grid\n"),
}


def test_the_checks_see_every_violation() -> None:
    modules = parse_modules(SYNTHETIC)
    engine = forbidden_imports(modules, lambda n: n.startswith("pkg.engine"),
                               ("pkg.tui", *UI_LIBRARIES))
    assert engine == ["pkg/engine/run.py:4: imports textual.app (App)",
                      "pkg/engine/run.py:6: imports pkg (tui)"]
    widgets = forbidden_imports(modules, lambda n: n.startswith("pkg.tui.widgets."),
                                ("pkg.tui.app",))
    assert widgets == ["pkg/tui/widgets/grid_view.py:2: imports pkg.tui.app (X)"]
    assert textual_free(modules) == ["pkg.tui.model", "pkg.tui.plain", "pkg.tui.typed"]
    # a module reached may import Textual in a function (lazy); the module held may not
    assert ui_reached(modules, "pkg.tui.model") == [
        "pkg.tui.model -> pkg.tui.helper: pkg/tui/helper.py:2: imports rich.text"]
    assert ui_reached(modules, "pkg.tui.plain") == ["pkg/tui/plain.py:3: imports textual.widget"]
    # a TYPE_CHECKING import runs nothing; its else branch does
    assert ui_reached(modules, "pkg.tui.typed") == []
    assert runtime_graph(modules)["pkg.tui.typed"] == {"pkg.engine", "pkg.engine.grid"}
    # the app and its widget import each other: a circle, found through the relative import
    assert cycles(runtime_graph(modules)) == [
        ["pkg.tui.app", "pkg.tui.widgets.grid_view", "pkg.tui.app"]]


def test_an_import_runs_the_packages_above_the_module() -> None:
    sources = {"a": "import a.b.c\n", "a.b": "", "a.b.c": "", "x": "", "x.y": "import a.b.c\n",
               "x.z": "from x import y\n"}
    graph = runtime_graph(parse_modules(sources))
    # importing a.b.c runs a and a.b; x.y's own package x has run before x.y: no edge
    assert graph == {"a": {"a.b", "a.b.c"}, "a.b": set(), "a.b.c": set(), "x": set(),
                     "x.y": {"a", "a.b", "a.b.c"}, "x.z": {"x.y"}}
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"d"}, "e": {"a"}}) == [
        ["a", "b", "c", "a"], ["d", "d"]]

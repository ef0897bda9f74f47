"""The folders are the layers (read from the sources with :mod:`ast`, tests/import_graph.py):

* no module lies loose in ``engine/``; the package's top and ``tui/`` hold at most five
  modules each, and no folder more than sixteen (the widgets aside);
* each folder's modules import only from their own folder and the folders below it
  (:data:`LAYERS`), ``if TYPE_CHECKING:`` imports included;
* nothing under ``engine/``, ``tui/model/``, ``tui/view/`` or ``plain/`` imports Textual or
  Rich (Rich's cell widths aside), even in a function;
* no module's name repeats its folder's;
* each ``__init__.py`` is a docstring naming its folder's job with a line for each of its
  modules, and nothing else (the package's version aside).

Each check is also shown to fail on a made-up violation.
"""

from __future__ import annotations

import ast
from pathlib import Path

from tests.helpers import ROOT
from tests.import_graph import Module, parse_modules, read_package, targets

PACKAGE = ROOT / "tui_search"
#: The folders, lowest first: a module may import from its own folder and those before it.
LAYERS = (
    "tui_search.engine.util", "tui_search.engine.maps", "tui_search.engine.search",
    "tui_search.engine.run", "tui_search.engine.traces", "tui_search.engine.course",
    "tui_search.tui.model", "tui_search.tui.view", "tui_search.tui.widgets",
    "tui_search.tui.dialogs", "tui_search.tui.screens", "tui_search.tui",
    "tui_search.plain", "tui_search.export", "tui_search.serve", "tui_search.cli", "tui_search",
)
#: Held to no Textual or Rich, in any function either.
TEXTUAL_FREE = ("tui_search.engine", "tui_search.tui.model", "tui_search.tui.view",
                "tui_search.plain")
UI_LIBRARIES = ("textual", "rich")
WIDTHS = "rich.cells"  # a pure function: text measured as Textual draws it
MAX_TOP, MAX_FOLDER = 5, 16


def layer_of(name: str, layers: tuple[str, ...] = LAYERS) -> int:
    """The rank of the folder module ``name`` is in: its deepest folder in ``layers``."""
    ranks = [i for i, folder in enumerate(layers) if name.startswith(folder + ".")]
    return max(ranks, key=lambda i: len(layers[i]))


def upward_imports(modules: dict[str, Module], layers: tuple[str, ...] = LAYERS) -> list[str]:
    """Imports from a lower folder of a module in a higher one (a package's ``__init__``, a
    docstring, is no module to import from)."""
    found = []
    for m in modules.values():
        if m.is_package:
            continue
        rank = layer_of(m.name, layers)
        for imp in m.imports:
            for target in sorted(targets(m, imp, modules)):
                if not modules[target].is_package and layer_of(target, layers) > rank:
                    found.append(f"{m.path}:{imp.line}: imports {target}")
    return found


def ui_imports(modules: dict[str, Module], free: tuple[str, ...] = TEXTUAL_FREE) -> list[str]:
    return [f"{m.path}:{imp.line}: imports {imp.module}" for m in modules.values()
            if any(m.name == f or m.name.startswith(f + ".") for f in free)
            for imp in m.imports
            if any(imp.mentions(u) for u in UI_LIBRARIES) and not imp.mentions(WIDTHS)]


def package() -> dict[str, Module]:
    return parse_modules(read_package(PACKAGE))


def folders() -> list[Path]:
    return sorted(p.parent for p in PACKAGE.rglob("__init__.py"))


def modules_in(folder: Path) -> list[str]:
    return sorted(p.stem for p in folder.glob("*.py") if p.name != "__init__.py")


def repeats_folder(folder: str, module: str) -> bool:
    """``traces/trace_read``, ``maps/mapfile``, ``serve/server``: the module's name says
    its folder again."""
    roots = {folder, folder.removesuffix("s")}
    words = module.split("_")
    return any(module.startswith(r) or module.endswith(r) or r in words for r in roots)


def init_problems(folder: Path, source: str) -> list[str]:
    """What a folder's ``__init__`` lacks: a docstring naming each of its modules and
    subfolders, and nothing beside it (a version string aside)."""
    tree = ast.parse(source)
    doc = ast.get_docstring(tree) or ""
    problems = [] if doc else ["no docstring"]
    extra = [node for node in (tree.body[1:] if doc else tree.body) if not (
        isinstance(node, ast.Assign) and [getattr(t, "id", "") for t in node.targets]
        == ["__version__"])]
    problems += [f"line {node.lineno}: not the docstring" for node in extra]
    parts = modules_in(folder) + sorted(p.name for p in folder.iterdir()
                                        if (p / "__init__.py").exists())
    problems += [f"no line for {part}" for part in parts
                 if f".{part}`" not in doc and f"``{part}``" not in doc]
    return problems


# -- the rules, on the package ------------------------------------------------------------------
def test_no_module_lies_loose_in_the_engine() -> None:
    assert modules_in(PACKAGE / "engine") == []


def test_the_tops_hold_five_modules_at_most_and_a_folder_sixteen() -> None:
    assert len(modules_in(PACKAGE)) <= MAX_TOP, modules_in(PACKAGE)
    assert len(modules_in(PACKAGE / "tui")) <= MAX_TOP, modules_in(PACKAGE / "tui")
    big = {str(f.relative_to(PACKAGE)): len(modules_in(f)) for f in folders()
           if f.name != "widgets" and len(modules_in(f)) > MAX_FOLDER}
    assert big == {}


def test_every_folder_is_a_layer() -> None:
    """A module in no folder of :data:`LAYERS` would be in no layer: each folder is one (or
    inside one)."""
    names = {".".join(f.relative_to(ROOT).parts) for f in folders()}
    assert {n for n in names if not any(n == f or n.startswith(f + ".") for f in LAYERS)
            } == set()
    assert len(package()) > 100, "the package is not where this looks"


def test_no_import_runs_from_a_lower_folder_to_a_higher_one() -> None:
    found = upward_imports(package())
    assert found == [], "an import up the layers:\n" + "\n".join(found)


def test_the_engine_the_model_and_the_view_import_no_textual_or_rich() -> None:
    found = ui_imports(package())
    assert found == [], "Textual or Rich where none may be:\n" + "\n".join(found)


def test_no_module_name_repeats_its_folder() -> None:
    found = [f"{f.name}/{m}" for f in folders() for m in modules_in(f)
             if repeats_folder(f.name, m)]
    assert found == []


def test_each_init_names_its_folder_s_job_and_each_module() -> None:
    found = {str(f.relative_to(PACKAGE)): problems for f in folders()
             if (problems := init_problems(f, (f / "__init__.py").read_text("utf-8")))}
    assert found == {}


# -- each check fails on a violation ------------------------------------------------------------
SYNTHETIC = {
    "pkg": "",
    "pkg.low": "",
    "pkg.low.a": ("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
                  "    from pkg.high import b\n"),
    "pkg.low.c": "def later():\n    import rich.text\n    import rich.cells\n",
    "pkg.high": "",
    "pkg.high.b": "from pkg.low import a\nfrom pkg import low\n",
}


def test_the_checks_see_every_violation(tmp_path: Path) -> None:
    modules = parse_modules(SYNTHETIC)
    layers = ("pkg.low", "pkg.high", "pkg")
    assert layer_of("pkg.low.a", layers) == 0 and layer_of("pkg.high.b", layers) == 1
    # up the layers, even for the type checker; down them (and to a package) is fine
    assert upward_imports(modules, layers) == ["pkg/low/a.py:3: imports pkg.high.b"]
    # in a function too; Rich's cell widths aside
    assert ui_imports(modules, ("pkg.low",)) == ["pkg/low/c.py:2: imports rich.text"]
    assert [repeats_folder(f, m) for f, m in [("traces", "trace_read"), ("maps", "mapfile"),
                                              ("serve", "server"), ("traces", "read"),
                                              ("run", "recorded"), ("maps", "grid")]] == [
        True, True, True, False, False, False]
    (tmp_path / "one.py").write_text("")
    (tmp_path / "inner").mkdir()
    (tmp_path / "inner" / "__init__.py").write_text("")
    assert init_problems(tmp_path, '"""Job.\n\n* :mod:`~p.one`: one."""\n') == [
        "no line for inner"]
    assert init_problems(tmp_path, "from .one import x\n") == [
        "no docstring", "line 1: not the docstring", "no line for one", "no line for inner"]

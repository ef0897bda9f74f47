"""``tui_search/`` uses Textual's public API only: no private name of the Textual classes the app
builds on is read, set, called or overridden anywhere in its Textual app, ``tui_search/tui/``
(a private name changes without notice from one Textual release to the next; the engine and
the command line import no Textual at all)."""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

from textual import app, containers, dom, message_pump, screen, scroll_view, scrollbar, widget

ROOT = Path(__file__).resolve().parents[1]
TUI = ROOT / "tui_search" / "tui"
#: The modules of the classes the app subclasses or whose objects it touches.
MODULES = (app, containers, dom, message_pump, screen, scroll_view, scrollbar, widget)


def is_private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def textual_private_names() -> set[str]:
    """Every private attribute and method of the classes in :data:`MODULES`: those in their
    class dictionaries and those their code sets or reads on an object."""
    names: set[str] = set()
    for module in MODULES:
        for _, cls in inspect.getmembers(module, inspect.isclass):
            if cls.__module__ != module.__name__:
                continue
            names |= {name for name in vars(cls) if is_private(name)}
        for node in ast.walk(ast.parse(inspect.getsource(module))):
            if isinstance(node, ast.Attribute) and is_private(node.attr):
                names.add(node.attr)
    return names


def private_uses(source: str) -> list[tuple[int, str]]:
    """Private names ``source`` reads, sets or defines (attributes, methods, and names given
    to ``getattr``/``setattr`` as strings)."""
    uses = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Attribute):
            name = node.attr
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            name = node.name
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            name = node.value
        else:
            continue
        if is_private(name) and name.isidentifier():
            uses.append((node.lineno, name))
    return uses


def test_the_private_name_check_sees_textual_internals() -> None:
    """The check itself: the names a review found in the package are known private names."""
    known = textual_private_names()
    for name in ("_border_title", "_vertical_scrollbar", "_start_widget", "_dirty_regions",
                 "_scroll_update", "_refresh_scrollbars", "_compositor", "_render_content"):
        assert name in known
    assert private_uses("view._refresh_scrollbars()\nsetattr(w, '_border_title', t)\n") == [
        (1, "_refresh_scrollbars"), (2, "_border_title")]


def test_tui_search_uses_no_private_textual_name() -> None:
    known = textual_private_names()
    found = [f"{path.relative_to(ROOT)}:{line}: {name}"
             for path in sorted(TUI.rglob("*.py"))
             for line, name in private_uses(path.read_text(encoding="utf-8"))
             if name in known]
    assert found == []

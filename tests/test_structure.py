"""The structure issue 20 asked for, held by tests: files by job (none over 450 lines), a thin
app (at most 300 lines, no mixins), and no "compare or not" flag in the app: every search is a
pane."""

from __future__ import annotations

import ast
from pathlib import Path

import tui_search
from tui_search.tui.app import SearchApp

PACKAGE = Path(tui_search.__file__).parent
MAX_LINES, APP_LINES = 450, 300


def sources() -> list[Path]:
    return sorted(PACKAGE.rglob("*.py"))


def test_no_module_is_over_450_lines() -> None:
    long = {str(p.relative_to(PACKAGE)): n for p in sources()
            if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_LINES}
    assert long == {}, f"files over {MAX_LINES} lines (split them by job): {long}"


def test_the_app_is_thin_and_has_no_mixins() -> None:
    app = PACKAGE / "tui" / "app.py"
    assert len(app.read_text(encoding="utf-8").splitlines()) <= APP_LINES
    own_bases = [base for base in SearchApp.__mro__[1:] if base.__module__.startswith("tui_search")]
    assert own_bases == [], f"the app inherits from the project's classes: {own_bases}"
    assert not (PACKAGE / "tui" / "mixin.py").exists()


def compare_flags(source: str) -> list[int]:
    """Lines that read or set ``self.compare``: the old flag of "comparing or not"."""
    return [node.lineno for node in ast.walk(ast.parse(source))
            if isinstance(node, ast.Attribute) and node.attr == "compare"
            and isinstance(node.value, ast.Name) and node.value.id == "self"]


def test_no_module_keeps_a_compare_or_not_flag() -> None:
    found = {str(p.relative_to(PACKAGE)): lines for p in sources()
             if (lines := compare_flags(p.read_text(encoding="utf-8")))}
    assert found == {}, f"'self.compare' (every search is a pane; no mode flag): {found}"
    assert not any("self.compare" in p.read_text(encoding="utf-8") for p in sources())


def test_the_checks_see_what_they_forbid() -> None:
    assert compare_flags("class A:\n    def f(self):\n        return self.compare\n") == [3]
    assert compare_flags("x = other.compare\nself.comparison = 1\n") == []

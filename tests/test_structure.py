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


def all_sources() -> list[Path]:
    """Every source file of the package: Python and the compiled core's C."""
    return sorted(p for ext in ("py", "c", "h") for p in PACKAGE.rglob(f"*.{ext}"))


def test_no_module_is_over_450_lines() -> None:
    assert any(p.suffix == ".c" for p in all_sources())
    long = {str(p.relative_to(PACKAGE)): n for p in all_sources()
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


TESTS = Path(__file__).parent


def fixed_waits(source: str) -> list[int]:
    """Lines that wait a fixed time outside a loop: ``time.sleep(...)``, ``asyncio.sleep(...)``
    or a ``pause(...)`` given a time.  Inside a ``while`` or ``for`` a short pause is a
    polling loop's turn (it waits for a condition); anywhere else it is a guess at how long
    the machine takes."""
    found: list[int] = []

    def visit(node: ast.AST, in_loop: bool) -> None:
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and not in_loop:
            name = node.func.attr
            if name == "sleep" or (name == "pause" and (node.args or node.keywords)):
                found.append(node.lineno)
        for child in ast.iter_child_nodes(node):
            nested = isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
            visit(child, (in_loop or isinstance(node, (ast.While, ast.For, ast.AsyncFor)))
                  and not nested)

    visit(ast.parse(source), False)
    return found


#: Not tests, so not held to it: the load maker, and the browser check's screenshot (its pass
#: waits for the page's first frame; the picture waits for the start card to fade).
NOT_TESTS = {"under_load.py", "browser_check.py"}


def test_ui_tests_wait_for_what_they_check_and_never_sleep_a_fixed_time() -> None:
    found = {str(p.relative_to(TESTS)): lines for p in sorted(TESTS.rglob("*.py"))
             if p.name not in NOT_TESTS and (lines := fixed_waits(p.read_text("utf-8")))}
    assert found == {}, f"a fixed wait outside a polling loop: {found}"


def test_the_wait_check_sees_a_fixed_wait() -> None:
    assert fixed_waits("async def f(p):\n    await p.pause(0.5)\n") == [2]
    assert fixed_waits("import time\ntime.sleep(1)\n") == [2]
    assert fixed_waits("async def f(p):\n    await p.pause()\n") == []
    assert fixed_waits("while x:\n    time.sleep(0.05)\n") == []
    assert fixed_waits("while x:\n    def g():\n        time.sleep(1)\n") == [3]

"""The structure issue 20 asked for, held by tests: files by job (none over 450 lines), a thin
app (at most 300 lines, no mixins), and no "compare or not" asked in the app, however spelled:
every search is a pane, and the few rules over the number of panes say so.  And comments that
say why: no history and no measured figure in the package (CONTRIBUTING.md, "Comments")."""

from __future__ import annotations

import ast
import io
import re
import tokenize
from pathlib import Path

import tui_search
from tui_search.tui.app import SearchApp
from tui_search.tui.model.session import Session

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


def own_bases(cls: type) -> list[type]:
    """The project's classes ``cls`` inherits from (a mixin stack): none, for a class whose
    parts are attributes it has."""
    return [base for base in cls.__mro__[1:] if base.__module__.startswith("tui_search")]


def test_the_app_is_thin() -> None:
    app = PACKAGE / "tui" / "app.py"
    assert len(app.read_text(encoding="utf-8").splitlines()) <= APP_LINES
    assert not (PACKAGE / "tui" / "mixin.py").exists()


def test_the_app_and_the_session_have_parts_not_bases() -> None:
    """No mixins, in the app or in the session it drives: the map's edits and the replay's
    jumps are parts the session has (``session.edits``, ``session.jumps``)."""
    for cls in (SearchApp, Session):
        assert own_bases(cls) == [], f"{cls.__name__} inherits from the project's classes"

    class Mixin:
        pass

    Mixin.__module__ = "tui_search.tui.mixin"
    assert own_bases(type("Stacked", (Mixin,), {})) == [Mixin]  # the check sees a mixin


#: Attributes that would be a "compare or not" flag, whatever reads them.
MODE_FLAGS = {"compare", "comparing", "several", "single"}
#: What holds the panes, their runs or their searches: asking how many (one? two?) of these
#: is asking "compare or not".
PANE_LISTS = {"runs", "panes", "labels", "names", "contenders", "views", "parts", "searches"}
#: A comparison asked this way is a rule over the number of panes only on a line that says so.
RULE_OVER_N = "# rule over N:"


def _named(node: ast.AST) -> str:
    if isinstance(node, ast.Attribute):
        return node.attr
    return node.id if isinstance(node, ast.Name) else ""


def _counts_panes(node: ast.AST) -> bool:
    """``len(runs)``, ``len(self.panes)``, ...: how many panes."""
    return (isinstance(node, ast.Call) and _named(node.func) == "len" and len(node.args) == 1
            and _named(node.args[0]) in PANE_LISTS)


def _asks_for_a_comma(node: ast.Compare) -> bool:
    """``"," in spec``: whether a spec names several searches."""
    return (any(isinstance(op, ast.In | ast.NotIn) for op in node.ops)
            and isinstance(node.left, ast.Constant) and node.left.value == ","
            and any(_named(side).endswith("spec") for side in node.comparators))


def _asks_how_many_panes(node: ast.Compare) -> bool:
    """``len(self.runs) > 1``, ``2 <= len(labels)``: how many panes, against none, one or two."""
    sides = [node.left, *node.comparators]
    return (any(_counts_panes(side) for side in sides)
            and any(isinstance(side, ast.Constant) and side.value in (0, 1, 2) for side in sides))


def compare_flags(source: str) -> list[int]:
    """Lines that ask "compare or not", however spelled: a mode attribute (``self.compare``,
    ``screen.several``); whether a spec names several searches (``"," in self.spec``); how
    many panes there are against one or two (``len(self.runs) > 1``, ``len(labels) == 1``),
    unless the line says why that is a rule over the number of panes (:data:`RULE_OVER_N`)."""
    lines = source.splitlines()

    def asks(node: ast.AST) -> bool:
        if isinstance(node, ast.Attribute):
            return node.attr in MODE_FLAGS
        return isinstance(node, ast.Compare) and (
            _asks_for_a_comma(node)
            or (_asks_how_many_panes(node) and RULE_OVER_N not in lines[node.lineno - 1]))

    return sorted({node.lineno for node in ast.walk(ast.parse(source)) if asks(node)})


def ui_sources() -> list[Path]:
    """The app's modules (the command line's ``args.compare`` is a flag's value, not a mode)."""
    return sorted((PACKAGE / "tui").rglob("*.py"))


def test_no_module_keeps_a_compare_or_not_flag() -> None:
    assert len(ui_sources()) > 30
    found = {str(p.relative_to(PACKAGE)): lines for p in ui_sources()
             if (lines := compare_flags(p.read_text(encoding="utf-8")))}
    assert found == {}, f"'compare or not' asked (every search is a pane; no mode): {found}"
    assert not any("self.compare" in p.read_text(encoding="utf-8") for p in sources())


def test_the_rules_over_the_number_of_panes_are_few_and_said() -> None:
    """Where the number of panes matters it is said, and there are four such rules: the
    layout's (a pane's own lines and the table), the names a line gives the runs, what a
    number key does, and what c goes between."""
    rules = {f"{p.relative_to(PACKAGE)}:{n}": line.split(RULE_OVER_N)[1].strip()
             for p in ui_sources()
             for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
             if RULE_OVER_N in line}
    assert len(rules) == 4 and all(rules.values()), rules


def test_the_checks_see_what_they_forbid() -> None:
    assert compare_flags("class A:\n    def f(self):\n        return self.compare\n") == [3]
    assert compare_flags("x = other.compare\nself.comparison = 1\n") == [1]
    assert compare_flags("y = screen.several\n") == [1]
    assert compare_flags('a = "," in self.spec\nb = "," not in spec\n') == [1, 2]
    assert compare_flags("if len(self.runs) > 1:\n    pass\nz = 2 <= len(labels)\n") == [1, 3]
    assert compare_flags("w = len(parts) == 1\nv = len(self.panes) != 0\n") == [1, 2]
    # not asked: what a string holds, how many of something else, against a named bound,
    # and a rule over N that says so
    assert compare_flags('a = "," in text\nb = len(word) == 1\nc = len(parts) == MAX\n'
                         'd = self.comparison\n') == []
    assert compare_flags("e = len(labels) > 1  # rule over N: naming\n") == []


TESTS = Path(__file__).parent


def fixed_waits(source: str) -> list[int]:
    """Lines that wait a fixed time outside a loop: ``time.sleep(...)``, ``asyncio.sleep(...)``
    or a ``pause(...)`` given a time.  Inside a ``while`` or ``for`` a short pause is a
    polling loop's turn (it waits for a condition); anywhere else it is a guess at how long
    the machine takes."""
    found: list[int] = []

    def visit(node: ast.AST, in_loop: bool) -> None:
        if isinstance(node, ast.Call) and not in_loop:
            func = node.func  # time.sleep(1), pilot.pause(0.5), or sleep(1) imported bare
            name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
            paused = isinstance(func, ast.Attribute) and name == "pause"
            if name == "sleep" or (paused and (node.args or node.keywords)):
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
    assert fixed_waits("from time import sleep\nsleep(1)\n") == [2]
    assert fixed_waits("from asyncio import sleep\nasync def f():\n    await sleep(1)\n") == [3]
    assert fixed_waits("async def f(p):\n    await p.pause()\n") == []
    assert fixed_waits("while x:\n    time.sleep(0.05)\n") == []
    assert fixed_waits("while x:\n    def g():\n        time.sleep(1)\n") == [3]


# -- comments say why: no history, no figures (CONTRIBUTING.md, "Comments") ------------------

ROOT = PACKAGE.parent
#: A session or an issue named by its number: history, which git keeps.
HISTORY = re.compile(r"\b(?:sessions?|issues?)\s+#?\d+\b", re.IGNORECASE)
#: A measured figure: a time, an instruction count, a ratio, or a size or share given as
#: roughly so much.  A constant's value ("64 MB", "4 bytes a line", "40 % of the pane") is a
#: definition, not a measurement, and is not matched.
FIGURE = re.compile(
    r"\d[\d.,]*\s?(?:ms|µs|ns|s)\b"  # 0.7 ms, 16 ms, 0.6 µs, 5 s
    r"|\d[\d.,]*\s?[KMG] instructions\b"  # ~5 M instructions
    r"|(?<![\w.])\d+(?:\.\d+)?[x×](?!\w)"  # 1.28x, 5x
    r"|(?:~|about |some )\d[\d.,]*\s?(?:%|bytes\b|[KMG]B\b)"  # ~7 %, about 50 bytes, ~400 MB
    r"|\b(?:about|some|under|over) (?:a|an|half an?|a tenth of an?) (?:second|minute|hour)\b"
)
#: Prose blocks of a C or CSS file: its comments.
C_COMMENT = re.compile(r"/\*.*?\*/|//[^\n]*", re.DOTALL)
#: Where the code names a section of a note: the section must exist.
CITES = {ROOT / "benchmarks" / "README.md": re.compile(r'benchmarks/README\.md`*,\s+"([^"]+)"'),
         ROOT / "CONTRIBUTING.md": re.compile(r'CONTRIBUTING\.md`*,\s+"([^"]+)"')}
#: Files another branch is rewriting, checked once it lands: remove each as it does.
#: TEMPORARY: each file's history and figures are listed for that branch.
PENDING: set[str] = set()


def prose(path: Path, source: str) -> list[tuple[int, str]]:
    """The comments and docstrings of ``source`` (``path`` says its language), each block
    with its first line and its words joined by single spaces (a figure may wrap)."""
    if path.suffix != ".py":
        return [(source.count("\n", 0, m.start()) + 1, " ".join(m.group().split()))
                for m in C_COMMENT.finditer(source)]
    blocks: list[tuple[int, str]] = []
    last = -1
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type == tokenize.COMMENT:
            text = tok.string.lstrip("#:").strip()
            if blocks and tok.start[0] == last + 1:
                blocks[-1] = (blocks[-1][0], f"{blocks[-1][1]} {text}")
            else:
                blocks.append((tok.start[0], text))
            last = tok.start[0]
    for node in ast.walk(ast.parse(source)):
        if (isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)
                and isinstance(node.value.value, str)):
            blocks.append((node.lineno, " ".join(node.value.value.split())))
    return sorted(blocks)


def figures_and_history(path: Path, source: str) -> list[str]:
    """``line: what`` for each figure in the prose of ``source`` and each session or issue
    named anywhere in it."""
    found = [f"{line}: {m.group()}" for line, text in prose(path, source)
             for m in FIGURE.finditer(text)]
    found += [f"{source.count(chr(10), 0, m.start()) + 1}: {m.group()}"
              for m in HISTORY.finditer(source)]
    return found


def package_texts() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*") if p.is_file()
                  and p.suffix in {".py", ".c", ".h", ".tcss", ".md", ".toml", ".txt"})


def test_no_comment_keeps_history_or_a_figure() -> None:
    """Nothing under ``tui_search/`` names a session or an issue, and no comment or
    docstring carries a measured figure: it lives in benchmarks/README.md, which the comment
    names (CONTRIBUTING.md, "Comments")."""
    assert len(package_texts()) > 150
    found = {name: hits for p in package_texts()
             if (name := str(p.relative_to(PACKAGE))) not in PENDING
             and (hits := figures_and_history(p, p.read_text(encoding="utf-8")))}
    assert found == {}, f"history or figures in the code (move them): {found}"
    done = {name for name in PENDING
            if not figures_and_history(PACKAGE / name, (PACKAGE / name).read_text("utf-8"))}
    assert not done, f"checked now: take them out of PENDING: {done}"


def test_the_sections_the_code_names_exist() -> None:
    cited = 0
    for note, cite in CITES.items():
        text = note.read_text(encoding="utf-8")
        headings = {line.lstrip("#").split(" — ")[0].strip()
                    for line in text.splitlines() if line.startswith("## ")
                    or line.startswith("### ")}
        for p in [*package_texts(), *TESTS.rglob("*.py")]:
            for name in cite.findall(p.read_text(encoding="utf-8")):
                cited += 1
                assert name in headings, f"{p.name} names {note.name}'s \"{name}\": no such section"
    assert cited > 30


def test_the_history_check_sees_what_it_forbids() -> None:
    py = Path("m.py")
    assert figures_and_history(py, "x = 1  # fixed in session 14\n") == ["1: session 14"]
    assert figures_and_history(py, '"""See issue #20."""\n') == ["1: issue #20"]
    assert figures_and_history(py, "# ~7.7 M\n# instructions of every start\nx = 1\n") == [
        "1: 7.7 M instructions"]
    assert figures_and_history(py, 'def f():\n    """One costs ~0.7 ms."""\n') == ["2: 0.7 ms"]
    assert figures_and_history(py, "# the loop went from 1.28x to 1.21x\n") == [
        "1: 1.28x", "1: 1.21x"]
    assert figures_and_history(py, "#: about 50 bytes a line\nN = 1\n") == ["1: about 50 bytes"]
    assert figures_and_history(py, '"""Reads in about a second."""\n') == ["1: about a second"]
    assert figures_and_history(Path("a.c"), "/* spent\n * 5 ms of its 30 */\nint x;\n") == [
        "1: 5 ms"]
    assert figures_and_history(Path("a.tcss"), "/* ~22 M instructions */\n") == [
        "1: 22 M instructions"]
    # not figures: a constant's value, a map's size, code, a string that is not a docstring
    assert figures_and_history(py, "# at most 64 MB; 4 bytes a line; 40 % of the pane\n") == []
    assert figures_and_history(py, "# a 4096x4096 map, maze 21x15, 0x1F\n") == []
    assert figures_and_history(py, 'x = f"{n:.0%} {t} ms"  # the session of the app\n') == []

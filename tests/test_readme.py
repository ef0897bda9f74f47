"""The README and the pages of ``docs/`` stay in step with the program.

Every ``$ tui-search ...`` line in a ```console block of README.md or a ``docs/`` page is run
(through :func:`tui_search.cli.main.main`, from the repository's root, as a person on a fresh
clone would type it) and what it prints must be the lines the page shows under it, figure for
figure.  Every command of a ```bash block names only files a fresh clone has (or that an earlier
line of the block writes) and flags the command line knows; the sample maps, the exercise file,
the lesson and the traces shown are read as the app reads them.  The Quick start must be its
two commands, the second the one CI runs, and the keys table must name every key the app
binds.  The README stays short (at most 250 lines), every page starts with a heading and is
linked, every link leads to a file and a heading that exist, every path in backquotes exists,
no command needs a folder beside the clone without saying how to get it, and the web extra is
installed from the clone.  So a change to the output, a key, a file or CI without the docs
fails here.
"""

from __future__ import annotations

import asyncio
import contextlib
import importlib.util
import io
import json
import re
import shlex
from pathlib import Path

import pytest
from textual.binding import Binding
from textual.screen import Screen

from tests.helpers import MOVINGAI, ROOT
from tui_search.cli.flags import EXIT_BAD_INPUT, EXIT_FOUND, EXIT_NO_PATH
from tui_search.cli.main import main
from tui_search.engine.course.exercise_file import toml_parser
from tui_search.engine.course.lesson import read_lesson
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.tui.app import SearchApp

DOCS = ROOT / "docs"
#: The README and every page of docs/, by their path from the clone's root.
PAGES = {path.relative_to(ROOT).as_posix(): path.read_text(encoding="utf-8")
         for path in [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]}
README = PAGES["README.md"]
#: The numbered pages (docs/README.md is their index).
NUMBERED = sorted(name for name in PAGES if re.fullmatch(r"docs/\d\d-[a-z-]+\.md", name))
MAX_README_LINES = 250
SUMMARY = re.compile(r"^(\d+) of (\d+) solved")
HEAD = re.compile(r"^(.*?)\s*\|\s*head -(\d+)$")
FENCE = re.compile(r"^(`{3,})([\w-]*)\s*$")
#: A path to a map file of the repository, as a page names one before a sample.
MAP_NAMED = re.compile(r"maps/[\w-]+\.txt")
#: A file the docs name (in backquotes) that another branch of issue 35 adds: the options value.


def page(name: str) -> str:
    return PAGES[f"docs/{name}"]


def section(title: str) -> str:
    """The README's text under the heading ``## title``, up to the next ``## `` heading."""
    match = re.search(rf"^## {re.escape(title)}\n(.*?)(?=^## |\Z)", README,
                      re.DOTALL | re.MULTILINE)
    assert match, f"README has no section '## {title}'"
    return match.group(1)


def fenced_blocks(text: str) -> list[tuple[str, str, str]]:
    """(info string, body, the text before the block) of every fenced block of ``text``; a
    block closes at a fence of its own length, so a ````markdown block may hold ``` ones."""
    blocks: list[tuple[str, str, str]] = []
    lines = text.splitlines(keepends=True)
    i = 0
    while i < len(lines):
        opened = FENCE.match(lines[i])
        if not opened:
            i += 1
            continue
        ticks, info = opened.groups()
        j = i + 1
        while j < len(lines) and lines[j].rstrip("\n") != ticks:
            j += 1
        assert j < len(lines), f"a fence left open: {lines[i]!r}"
        blocks.append((info, "".join(lines[i + 1:j]), "".join(lines[:i])))
        i = j + 1
    return blocks


def blocks(info: str) -> list[tuple[str, str, str]]:
    """(page, body, text before) of every block with this info string, on every page."""
    return [(name, body, before) for name, text in PAGES.items()
            for kind, body, before in fenced_blocks(text) if kind == info]


def prose(text: str) -> str:
    """``text`` without its fenced blocks (so a heading or link shown in a sample is none)."""
    out, fence = [], None
    for line in text.splitlines():
        opened = FENCE.match(line)
        if fence is None and opened:
            fence = opened.group(1)
        elif fence is not None and line == fence:
            fence = None
        elif fence is None:
            out.append(line)
    return "\n".join(out)


def console_examples(text: str) -> list[tuple[str, list[str]]]:
    """(command, the lines shown under it) for every ``$ `` line of the console blocks."""
    examples: list[tuple[str, list[str]]] = []
    for info, block, _ in fenced_blocks(text):
        if info != "console":
            continue
        for line in block.splitlines():
            if line.startswith("$ "):
                examples.append((line[2:], []))
            else:
                assert examples, f"console block output before any command: {line!r}"
                examples[-1][1].append(line)
    return examples


EXAMPLES = [(name, command, shown) for name, text in PAGES.items()
            for command, shown in console_examples(text)]


def expected_exit(shown: list[str]) -> int:
    """The exit code the docs' exit-code paragraph promises for what an example shows."""
    first = shown[0]
    # the class report: 0 when every map is solved (its summary last, or before the hint)
    report = next((m for m in map(SUMMARY.match, shown[-2:][::-1]) if m), None)
    if report:
        return EXIT_FOUND if report.group(1) == report.group(2) else EXIT_NO_PATH
    if first.startswith("file,verdict,"):  # the class report as CSV
        solved = all(row.split(",")[1] == "solved" for row in shown[1:])
        return EXIT_FOUND if solved else EXIT_NO_PATH
    if first.startswith("tui-search:"):
        return EXIT_BAD_INPUT
    if ": no path" in first or '"found": false' in first or first.startswith("step "):
        return EXIT_NO_PATH
    if re.match(r"your \w+: step \d+: ", first) or "disagrees with the .solution" in shown[-1]:
        return EXIT_NO_PATH  # a student's search.py parting from the search; a test's verdict
    return EXIT_FOUND


def test_the_pages_have_console_examples_to_check() -> None:
    """The parser finds the examples (a page reshaped out of its reach would pass silently)."""
    assert len(EXAMPLES) >= 20
    assert {name for name, _, _ in EXAMPLES} >= {"README.md", "docs/02-command-line.md",
                                                 "docs/03-traces.md", "docs/04-exercises.md",
                                                 "docs/07-maps-and-formats.md"}
    assert all(command.startswith("tui-search ") for _, command, _ in EXAMPLES)
    assert all(shown for _, _, shown in EXAMPLES)


@pytest.mark.parametrize(("name", "command", "shown"), EXAMPLES,
                         ids=[f"{name}: {c}" for name, c, _ in EXAMPLES])
def test_console_example_prints_what_the_page_shows(
    name: str, command: str, shown: list[str], capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.chdir(ROOT)  # the examples' paths are from the clone's root
    head = HEAD.match(command)
    argv = shlex.split(head.group(1) if head else command)
    assert argv[0] == "tui-search"
    code = main(argv[1:])
    out, err = capsys.readouterr()
    printed = out.splitlines()[: int(head.group(2))] if head else (out + err).splitlines()
    assert printed == shown
    assert code == expected_exit(shown)


QUICK_START_APP = ("python3 -m venv .venv && .venv/bin/pip install -e '.[web]' && "
                   ".venv/bin/tui-search maps/tutorial.txt")


def ci_steps() -> list[str]:
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    return [line.strip() for line in ci if line.strip() and not line.lstrip().startswith("#")]


def test_quick_start_is_two_commands_and_the_second_is_what_ci_runs() -> None:
    """The first installs the app with the web extra (so --serve works) and opens the
    tutorial's map; the second is .ci/run's test command, which the testing page repeats with
    the linters and the browser check that follow it."""
    commands = [body.strip() for info, body, _ in fenced_blocks(section("Quick start"))
                if info == "bash"]
    assert len(commands) == 2 and all("\n" not in c for c in commands), commands
    app, tests = commands
    assert app == QUICK_START_APP
    assert (ROOT / "maps" / "tutorial.txt").is_file()
    steps = ci_steps()
    assert tests in steps  # exactly the README's command, then the linters, then Chromium
    after = steps[steps.index(tests) + 1 :]
    assert [step.split()[0] for step in after[:2]] == [".venv/bin/ruff", ".venv/bin/mypy"]
    assert after[-1] == ".venv/bin/python -m tests.browser_check"
    testing = page("10-testing.md")
    assert tests in testing and after[0] in testing and after[1] in testing
    assert after[-1] in testing  # the testing page says how to run each


def test_the_sample_maps_are_the_maps_they_name() -> None:
    """A sample map (a plain fenced block starting with a ``;`` comment) parses, and is the
    grid of the last map file the page names before it (``maps/tutorial.txt``, its comment
    shortened; ``maps/terrain-mud.txt`` with its terrain line)."""
    samples = [(name, body, before) for name, body, before in blocks("")
               if body.startswith(";")]
    assert len(samples) >= 2
    for name, body, before in samples:
        named = MAP_NAMED.findall(before)
        assert named, f"{name}: a sample map with no map file named before it"
        assert parse_map_text(body) == load_map(ROOT / named[-1]), (name, named[-1])


def test_the_sample_graphs_read() -> None:
    """A graph shown (a ``graph`` fenced block) reads as the app reads a .graph file, its table
    admissible and consistent."""
    from tui_search.engine.maps.graph_file import parse_graph
    from tui_search.engine.search.estimate_check import estimate_faults

    samples = blocks("graph")
    assert samples
    for name, body, _ in samples:
        graph = parse_graph(body, name)
        assert graph.start is not None and graph.goals, name
        assert estimate_faults(graph, "table") == [], name


def test_the_sample_exercise_is_the_file_it_names() -> None:
    """The exercise shown reads as the file it names (its comments aside)."""
    toml = toml_parser()
    samples = blocks("toml")
    assert samples
    for name, body, before in samples:
        named = re.findall(r"[\w/.-]+\.toml", before)
        assert named, f"{name}: a sample exercise with no file named before it"
        assert toml.loads(body) == toml.loads((ROOT / named[-1]).read_text()), name


def test_the_sample_lesson_reads(tmp_path: Path) -> None:
    """The lesson shown, saved at the top of a clone as the page says, opens: its map is
    found and every key of its block is valid."""
    (sample,) = [body for name, body, _ in blocks("markdown") if name == "docs/05-lessons.md"]
    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "tutorial.txt").write_bytes((ROOT / "maps" / "tutorial.txt").read_bytes())
    (tmp_path / "visit.md").write_text(sample, encoding="utf-8")
    lesson = read_lesson(tmp_path / "visit.md")
    (only,) = lesson.sections
    assert only.state.visit == "expand" and only.state.step == 7


def trace_blocks() -> list[tuple[str, str, str]]:
    """(page, trace, the map it is for) of every jsonl block: the map named nearest before it
    in the page's prose."""
    found = []
    for name, body, before in blocks("jsonl"):
        named = MAP_NAMED.findall(prose(before))
        assert named, f"{name}: a trace with no map named before it"
        found.append((name, body, named[-1]))
    return found


@pytest.mark.parametrize(("name", "trace", "map_name"), trace_blocks())
def test_a_trace_shown_is_a_well_formed_trace(
    name: str, trace: str, map_name: str, tmp_path: Path,
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A trace a page shows is read by --check-trace without error (exit 2 is a malformed
    trace); one it says matches a search does, the verdict is the one the page quotes, and it
    matches as well with its start and path lines and its optional keys left out."""
    monkeypatch.chdir(ROOT)
    shown = tmp_path / "trace.jsonl"
    shown.write_text(trace, encoding="utf-8")
    code = main([map_name, "--headless", "--check-trace", str(shown)])
    out, err = capsys.readouterr()
    assert code != EXIT_BAD_INPUT, err
    if code == EXIT_FOUND:
        verdict = " ".join(out.splitlines()[0].split())
        assert verdict in " ".join(PAGES[name].split())
        bare = tmp_path / "bare.jsonl"
        lines = [json.loads(line) for line in trace.splitlines() if line.strip()]
        bare.write_text("".join(
            json.dumps({"node": obj["node"], "successors": [
                s["node"] if isinstance(s, dict) else s for s in obj.get("successors", [])]})
            + "\n" for obj in lines if "node" in obj), encoding="utf-8")
        assert main([map_name, "--headless", "--check-trace", str(bare)]) == EXIT_FOUND
        assert capsys.readouterr().out.splitlines()[0] == out.splitlines()[0]


#: How the keys tables name the keys Textual calls otherwise.
README_NAMES = {"up": "arrows", "down": "arrows", "left": "arrows", "right": "arrows",
                "plus": "+", "minus": "-", "question_mark": "?", "comma": ",",
                "escape": "esc", "right_square_bracket": "]", "left_square_bracket": "[",
                "pageup": "pgup", "pagedown": "pgdn", "S": "shift+s", "G": "shift+g"}


def table_keys(text: str) -> set[str]:
    """The keys a ``| key | action |`` table lists (its first column), lower case."""
    table = text.split("| key | action |", 1)[1]
    keys: set[str] = set()
    for row in table.splitlines()[2:]:
        if not row.startswith("|"):
            break
        first = row.split("|")[1]
        keys.update(k.lower() for k in re.findall(r"`([^`]+)`", first))
        if "arrows" in first:
            keys.add("arrows")
    return keys


def test_the_keys_table_names_every_key_the_app_binds() -> None:
    """The keys page's table: the app's own keys, and Textual's focus keys (tab / shift+tab
    move between the map and the panels), each have a row; ctrl+q (Textual's quit, which asks
    like q does) too.  The README's first session names a dozen of them, and only keys the app
    has."""
    listed = table_keys(page("01-keys.md"))
    bindings = Binding.make_bindings([*SearchApp.BINDINGS, *Screen.BINDINGS])
    wanted = {README_NAMES.get(b.key, b.key) for b in bindings if not b.key.startswith("super+")}
    wanted.discard("ctrl+c")  # Screen's copy key; the q row says what ctrl+c does
    assert wanted <= listed, sorted(wanted - listed)
    assert {"tab", "shift+tab", "ctrl+q"} <= listed
    first_session = table_keys(section("A first session"))
    assert len(first_session) >= 12 and first_session <= listed, sorted(first_session - listed)


async def _tab_row_holds() -> None:
    grid = load_map(MOVINGAI / "arena.map", start=(44, 45), goal=(5, 5))
    app = SearchApp(grid, path=MOVINGAI / "arena.map")
    async with app.run_test(size=(120, 36)) as pilot:
        # (a queue longer than its panel: one that fits is given the rows to show it whole)
        app.session.goto(149)
        await pilot.press("n")
        run, queue, tree = app.session.run, app.main.panes[0].frontier, app.main.panes[0].tree_panel
        assert run is not None and app.focused is app.main.views[0]
        await pilot.press("tab", "pagedown", "down")  # the queue scrolls, the step stays
        assert app.focused is queue and queue.scroll_offset.y > 1 and run.k == 150
        await pilot.press("n")  # the next step brings the queue back to its front
        assert run.k == 151 and queue.scroll_offset.y == 0
        await pilot.press("tab", "end")  # end scrolls the tree: not the last step
        assert app.focused is tree and run.k == 151
        assert tree.max_scroll_y > 0 and tree.scroll_offset.y == tree.max_scroll_y
        await pilot.press("home", "l")  # home scrolls back up; l still moves the cursor
        assert tree.scroll_offset.y == 0 and run.k == 151 and app.session.cursor == (45, 45)
        await pilot.press("tab")
        assert app.focused is app.main.views[0]
        await pilot.press("shift+tab", "shift+tab")
        assert app.focused is queue
        await pilot.click(tree)
        assert app.focused is tree


def test_tab_moves_the_focus_to_the_panels_as_the_keys_table_says() -> None:
    """The README's Tab row: map, queue, tree in turn (a click too); in a panel the arrows,
    page keys and home/end scroll it, never the step; the next step scrolls it back."""
    asyncio.run(_tab_row_holds())


# -- the shape of the docs: short README, pages with headings, links that lead somewhere -----

def test_the_readme_is_short() -> None:
    assert len(README.splitlines()) <= MAX_README_LINES


def test_every_page_starts_with_a_heading() -> None:
    assert len(NUMBERED) >= 11
    for name in ["docs/README.md", *NUMBERED]:
        assert PAGES[name].startswith("# "), f"{name} does not start with a '# ' heading"


LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def links(name: str) -> list[str]:
    """The relative targets of a page's Markdown links (images too), outside code."""
    text = re.sub(r"`[^`\n]*`", "", prose(PAGES[name]))
    return [target for target in LINK.findall(text) if "://" not in target]


def slug(heading: str) -> str:
    """A heading's anchor as GitHub makes it: lower case, punctuation but ``-`` and ``_``
    dropped, spaces made ``-``."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(text: str) -> set[str]:
    return {slug(line.lstrip("#")) for line in prose(text).splitlines()
            if re.match(r"#{1,6} ", line)}


def test_every_page_is_linked_from_the_readme_or_the_index() -> None:
    linked = {(ROOT / target.split("#")[0]).resolve() for target in links("README.md")}
    linked |= {(DOCS / target.split("#")[0]).resolve() for target in links("docs/README.md")}
    assert (DOCS / "README.md").resolve() in linked
    missing = [name for name in NUMBERED if (ROOT / name).resolve() not in linked]
    assert missing == []


def test_every_link_leads_to_a_file_and_a_heading_that_exist() -> None:
    bad = []
    for name in PAGES:
        for target in links(name):
            path, _, anchor = target.partition("#")
            file = (ROOT / name).parent / path if path else ROOT / name
            if not file.exists():
                bad.append(f"{name}: {target} (no such file)")
            elif anchor and anchor not in anchors(file.read_text(encoding="utf-8")):
                bad.append(f"{name}: {target} (no such heading)")
    assert bad == []


#: A path in backquotes: folders and a file name with an extension (a ``*`` allowed).
QUOTED_PATH = re.compile(r"`((?:[\w.-]+/)+(?:[\w*.-]+\.\w+)?)`")
#: Where a page's paths are read from: the clone's root, or the package's folders (the design
#: page names modules under ``tui_search/``, ``engine/`` and ``engine/search/``).
PATH_BASES = [ROOT, ROOT / "tui_search", ROOT / "tui_search" / "engine",
              ROOT / "tui_search" / "engine" / "search", ROOT / "tui_search" / "tui"]


def test_every_path_in_backquotes_exists() -> None:
    """A file or folder a page names (``tui_search/engine/traces/read.py``,
    ``engine/run/rebuild.py``, ``tests/data/movingai/``) is there: a module moved is a page
    to fix."""
    bad = []
    for name, text in PAGES.items():
        for path in QUOTED_PATH.findall(prose(text)):
            if path.split("/")[0].isupper():
                continue  # a placeholder in capitals, the reader's own: SUBMISSIONS/*.txt
            if not any(list(base.glob(path.rstrip("/"))) for base in PATH_BASES):
                bad.append(f"{name}: {path}")
    assert bad == []


# -- the commands: each works from a fresh clone --------------------------------------------

def help_text() -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit):
        main(["--help"])
    return out.getvalue()


TUI_SEARCH = {"tui-search", ".venv/bin/tui-search"}
PYTHON = {"python", "python3", ".venv/bin/python"}
#: Flags whose value is a file the command writes, not one it reads.
WRITES = {"--output", "--out", "--save-dir", "--export", "--trace", "--gradescope"}
FILE_LIKE = re.compile(r"\.(txt|map|scen|toml|md|jsonl|json|py)$")


def bash_commands() -> list[tuple[str, list[str], set[str]]]:
    """(page, one simple command's words, the files earlier lines of its block write) for
    every command of every bash block, its comments dropped and split at ``&&``, ``|``, ``>``."""
    found = []
    for name, body, _ in blocks("bash"):
        written: set[str] = set()
        for line in body.splitlines():
            lexer = shlex.shlex(line, posix=True, punctuation_chars="&|>")
            lexer.whitespace_split, lexer.commenters = True, "#"
            words, command = list(lexer), []
            for word in [*words, "&&"]:
                if word in {"&&", "|", "||"}:
                    if command:
                        found.append((name, command, set(written)))
                    command = []
                elif command and command[-1] == ">":
                    written.add(word)
                    command.pop()
                else:
                    if command and command[-1] in WRITES:  # a file the command writes
                        written.add(word)
                    command.append(word)
    return found


BASH = bash_commands()


def path_args(words: list[str]) -> list[str]:
    """The arguments of a command that name a file or folder it reads."""
    paths = []
    for before, word in zip(["", *words], words, strict=False):
        if before in WRITES or word.startswith("-") or "://" in word:
            continue
        if "/" in word or FILE_LIKE.search(word):
            paths.append(word)
    return paths


@pytest.mark.parametrize(("name", "words", "written"), BASH,
                         ids=[f"{n}: {' '.join(w)}" for n, w, _ in BASH])
def test_a_command_shown_works_from_a_fresh_clone(name: str, words: list[str],
                                                  written: set[str]) -> None:
    """The files it reads are in the repository (or written by a line before it), the flags
    it gives are the command line's, a script or module it runs is there, and an extra it
    installs is one the package has, installed from the clone."""
    program, args = words[0], words[1:]
    if program in TUI_SEARCH:
        known = set(re.findall(r"--[\w-]+|-\w\b", help_text()))
        unknown = [a for a in args if a.startswith("-") and a.split("=")[0] not in known]
        assert unknown == [], f"{name}: flags the command line does not have"
    elif program in PYTHON:
        if args[:1] == ["-m"]:
            module, args = args[1], args[2:]
            if (ROOT / module.split(".")[0]).is_dir():  # the project's own: tests.under_load
                assert (ROOT / (module.replace(".", "/") + ".py")).is_file(), module
            else:  # the standard library's or an extra's: venv, pytest
                assert importlib.util.find_spec(module) is not None, module
    elif program.endswith("pip") and args[:1] == ["install"]:
        extras = re.findall(r"^\.\[([\w,]+)\]$", args[-1])
        assert "-e" in args and extras, f"{name}: install the clone: pip install -e '.[extra]'"
        table = toml_parser().loads((ROOT / "pyproject.toml").read_text())
        assert set(extras[0].split(",")) <= set(table["project"]["optional-dependencies"])
        return
    else:
        return  # another program (sudo ufw, apt-get): not the project's to check
    missing = [p for p in path_args(args) if p not in written and not (ROOT / p).exists()]
    assert missing == [], f"{name}: files a fresh clone does not have"


def test_the_commands_are_found() -> None:
    programs = {words[0] for _, words, _ in BASH}
    assert len(BASH) >= 30 and {"tui-search", ".venv/bin/python", "python3"} <= programs


#: The MovingAI sets' page, which must be named near any path to a folder beside the clone.
MOVINGAI_SETS = "https://movingai.com/benchmarks/"


def test_no_path_beside_the_clone_without_saying_how_to_get_it() -> None:
    """A clone has no ``../shared`` folder: a page that names one says, in the five lines
    before, where the maps come from."""
    bad = []
    for name, text in PAGES.items():
        lines = text.splitlines()
        for number, line in enumerate(lines):
            if re.search(r"(\.\./|/work/)shared\b", line):
                near = "\n".join(lines[max(0, number - 5):number + 1])
                if MOVINGAI_SETS not in near:
                    bad.append(f"{name}:{number + 1}: {line.strip()}")
    assert bad == []


def test_the_web_extra_is_installed_from_the_clone() -> None:
    """tui-search is not on PyPI: ``pip install 'tui-search[web]'`` fails; the line is
    ``pip install -e '.[web]'``, run in the clone."""
    for name, text in PAGES.items():
        assert not re.search(r"pip install[^\n]*tui-search\[", text), name
    assert "pip install -e '.[web]'" in README
    assert "pip install -e '.[web]'" in page("06-browser.md")

"""The README stays in step with the program.

Every ``$ tui-search ...`` line in a ```console block of README.md is run (through
:func:`tui_search.cli.main.main`, from the repository's root, as a person on a fresh clone would
type it) and what it prints must be the lines the README shows under it, figure for figure.
The Quick start must be its two commands, the second the one CI runs, and the keys table must
name every key the app binds.  So a change to the output, a key or CI without the README fails
here.
"""

from __future__ import annotations

import asyncio
import re
import shlex

import pytest
from textual.binding import Binding
from textual.screen import Screen

from tests.helpers import MOVINGAI, ROOT
from tui_search.cli.flags import EXIT_BAD_INPUT, EXIT_FOUND, EXIT_NO_PATH
from tui_search.cli.main import main
from tui_search.engine.maps.load import load_map, parse_map_text
from tui_search.tui.app import SearchApp

README = (ROOT / "README.md").read_text(encoding="utf-8")
CONSOLE = re.compile(r"^```console\n(.*?)^```$", re.DOTALL | re.MULTILINE)
BASH = re.compile(r"^```bash\n(.*?)^```$", re.DOTALL | re.MULTILINE)
SUMMARY = re.compile(r"^(\d+) of (\d+) solved")
HEAD = re.compile(r"^(.*?)\s*\|\s*head -(\d+)$")


def section(title: str) -> str:
    """The README's text under the heading ``## title``, up to the next ``## `` heading."""
    match = re.search(rf"^## {re.escape(title)}\n(.*?)(?=^## |\Z)", README,
                      re.DOTALL | re.MULTILINE)
    assert match, f"README has no section '## {title}'"
    return match.group(1)


def console_examples(text: str) -> list[tuple[str, list[str]]]:
    """(command, the lines shown under it) for every ``$ `` line of the console blocks."""
    examples: list[tuple[str, list[str]]] = []
    for block in CONSOLE.findall(text):
        for line in block.splitlines():
            if line.startswith("$ "):
                examples.append((line[2:], []))
            else:
                assert examples, f"console block output before any command: {line!r}"
                examples[-1][1].append(line)
    return examples


EXAMPLES = console_examples(README)


def expected_exit(shown: list[str]) -> int:
    """The exit code the README's exit-code paragraph promises for what an example shows."""
    first = shown[0]
    report = SUMMARY.match(shown[-1])
    if report:  # the class report: 0 when every map is solved
        return EXIT_FOUND if report.group(1) == report.group(2) else EXIT_NO_PATH
    if first.startswith("file,verdict,"):  # the class report as CSV
        solved = all(row.split(",")[1] == "solved" for row in shown[1:])
        return EXIT_FOUND if solved else EXIT_NO_PATH
    if first.startswith("tui-search:"):
        return EXIT_BAD_INPUT
    if ": no path" in first or '"found": false' in first or first.startswith("step "):
        return EXIT_NO_PATH
    return EXIT_FOUND


def test_the_readme_has_console_examples_to_check() -> None:
    """The parser finds the examples (a README reshaped out of its reach would pass silently)."""
    assert len(EXAMPLES) >= 7
    assert all(command.startswith("tui-search ") for command, _ in EXAMPLES)
    assert all(shown for _, shown in EXAMPLES)


@pytest.mark.parametrize(("command", "shown"), EXAMPLES, ids=[c for c, _ in EXAMPLES])
def test_console_example_prints_what_the_readme_shows(
    command: str, shown: list[str], capsys: pytest.CaptureFixture[str],
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


def test_quick_start_is_two_commands_and_the_second_is_what_ci_runs() -> None:
    commands = [block.strip() for block in BASH.findall(section("Quick start"))]
    assert len(commands) == 2 and all("\n" not in c for c in commands), commands
    app, tests = commands
    assert app.endswith(".venv/bin/tui-search maps/tutorial.txt")
    assert (ROOT / "maps" / "tutorial.txt").is_file()
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    steps = [line.strip() for line in ci if line.strip() and not line.lstrip().startswith("#")]
    assert tests in steps  # exactly the README's command, then the linters, then Chromium
    after = steps[steps.index(tests) + 1 :]
    assert [step.split()[0] for step in after[:2]] == [".venv/bin/ruff", ".venv/bin/mypy"]
    assert after[-1] == ".venv/bin/python -m tests.browser_check"
    assert after[-1] in section("Command line")  # the README says how to run it


def test_the_text_map_example_is_the_tutorial_map() -> None:
    """The README's sample text map parses, and is the grid of maps/tutorial.txt it says."""
    block = re.search(r"^```\n(;.*?)^```$", section("Maps"), re.DOTALL | re.MULTILINE)
    assert block, "no text map example under ## Maps"
    assert parse_map_text(block.group(1)) == load_map(ROOT / "maps" / "tutorial.txt")


#: How the README's keys table names the keys Textual calls otherwise.
README_NAMES = {"up": "arrows", "down": "arrows", "left": "arrows", "right": "arrows",
                "plus": "+", "minus": "-", "question_mark": "?", "comma": ",",
                "escape": "esc", "right_square_bracket": "]", "left_square_bracket": "[",
                "pageup": "pgup", "pagedown": "pgdn", "S": "shift+s", "G": "shift+g"}


def readme_keys() -> set[str]:
    """The keys the README's keys table lists (its first column), lower case."""
    table = section("Using the app").split("| key | action |", 1)[1]
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
    """The app's own keys, and Textual's focus keys (tab / shift+tab move between the map and
    the panels), each have a row; ctrl+q (Textual's quit, which asks like q does) too."""
    listed = readme_keys()
    bindings = Binding.make_bindings([*SearchApp.BINDINGS, *Screen.BINDINGS])
    wanted = {README_NAMES.get(b.key, b.key) for b in bindings if not b.key.startswith("super+")}
    wanted.discard("ctrl+c")  # Screen's copy key; the q row says what ctrl+c does
    assert wanted <= listed, sorted(wanted - listed)
    assert {"tab", "shift+tab", "ctrl+q"} <= listed


async def _tab_row_holds() -> None:
    grid = load_map(MOVINGAI / "arena.map", start=(44, 45), goal=(5, 5))
    app = SearchApp(grid, path=MOVINGAI / "arena.map")
    async with app.run_test(size=(120, 36)) as pilot:
        await pilot.press(*"n" * 60)
        run, queue, tree = app.session.run, app.main.panes[0].frontier, app.main.panes[0].tree_panel
        assert run is not None and app.focused is app.main.views[0]
        await pilot.press("tab", "pagedown", "down")  # the queue scrolls, the step stays
        assert app.focused is queue and queue.scroll_offset.y > 1 and run.k == 60
        await pilot.press("n")  # the next step brings the queue back to its front
        assert run.k == 61 and queue.scroll_offset.y == 0
        await pilot.press("tab", "end")  # end scrolls the tree: not the last step
        assert app.focused is tree and run.k == 61
        assert tree.max_scroll_y > 0 and tree.scroll_offset.y == tree.max_scroll_y
        await pilot.press("home", "l")  # home scrolls back up; l still moves the cursor
        assert tree.scroll_offset.y == 0 and run.k == 61 and app.session.cursor == (45, 45)
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

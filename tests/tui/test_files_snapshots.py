"""Pictures of the file prompts and questions (SVG snapshots); the docstring says what each
must show."""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.widgets import Input

from tests.tui.test_app import tutorial_app
from tui_search.tui.widgets.map_tree import MapTree

SIZE = (100, 30)


def prompt_with(key: str, name: str):
    """A ``run_before`` that opens the prompt of ``key`` and types ``name`` into it."""

    async def run_before(pilot) -> None:
        await pilot.press(key)
        await pilot.app.screen.query_one(MapTree).reload()  # the picker's files, all listed
        field = pilot.app.screen.query_one("#filename", Input)
        field.value = name
        field.cursor_position = len(name)  # at its end, wherever the clone is (the value
        # replaced was a folder's path, as long as the clone's)

    return run_before


def test_save_as_onto_an_existing_file_asks(
    snap_compare, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The built-in map, ctrl+s, 'old.txt' (which exists), enter: over the save-as prompt
    (its picker on the left listing old.txt in the current folder),
    the 'File exists' question, 'old.txt already exists. Replace it with this map?', with
    Overwrite (y) in red and Choose another name (n) focused."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "old.txt").write_text("keep me\n")
    app = tutorial_app(path=None)
    assert snap_compare(app, terminal_size=SIZE, run_before=prompt_with("ctrl+s", "old.txt"),
                        press=["enter"])
    assert (tmp_path / "old.txt").read_text() == "keep me\n"


def test_open_a_broken_map_shows_why_in_the_prompt(
    snap_compare, monkeypatch: pytest.MonkeyPatch
) -> None:
    """ctrl+o, 'maps/broken.txt', enter: the 'Open a map' prompt stays open with the name
    typed and, in red under it, "maps/broken.txt:4:7: unknown cell character 'q'"; on its
    left the picker lists the map files of maps/, the tutorial's folder."""
    monkeypatch.chdir(Path(__file__).parents[2])
    app = tutorial_app()
    assert snap_compare(app, terminal_size=SIZE,
                        run_before=prompt_with("ctrl+o", "maps/broken.txt"), press=["enter"])

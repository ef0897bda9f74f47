"""The file picker beside the open and save-as prompts' name field, driven by Pilot: the
field keeps the focus (typing a path works as before), the picker lists folders and map
files only, choosing a file fills the field and choosing it again acts; served with a save
folder it lists that folder's map files only."""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.widgets import Input

from tests.tui.test_app import SIZE, screen_shown, sync, wait_until
from tests.tui.test_files import TUTORIAL, answer, app_on, copy, untitled
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.confirm_overwrite import ConfirmOverwriteScreen
from tui_search.tui.dialogs.open_map import OpenMapScreen
from tui_search.tui.dialogs.path_prompt import PathPrompt
from tui_search.tui.dialogs.save_as import SaveAsScreen
from tui_search.tui.model.file_rules import FileAccess
from tui_search.tui.widgets.map_tree import MapTree


def a_folder(tmp_path: Path) -> Path:
    """Maps, a folder, and what the picker leaves out (a picture, a hidden map)."""
    copy(TUTORIAL, tmp_path, "a.txt")
    copy(Path(__file__).parents[1] / "data" / "movingai" / "arena.map", tmp_path, "b.map")
    (tmp_path / "sub").mkdir()
    (tmp_path / "c.png").write_bytes(b"")
    copy(TUTORIAL, tmp_path, ".hidden.txt")
    return tmp_path


async def picker_of(pilot, kind: type[PathPrompt]) -> tuple[PathPrompt, MapTree]:
    """The prompt on top and its picker, every file of its folder listed."""
    prompt = await screen_shown(pilot, kind)
    tree = prompt.query_one(MapTree)
    await tree.reload()
    return prompt, tree


def listed(tree: MapTree) -> list[str]:
    return [str(node.label) for node in tree.root.children]


async def choose(pilot, tree: MapTree, name: str) -> None:
    """Put the picker's cursor on ``name`` and press enter."""
    (node,) = [n for n in tree.root.children if str(n.label) == name]
    tree.focus()
    tree.move_cursor(node)
    await wait_until(pilot, lambda: tree.cursor_node is node and tree.has_focus)
    await pilot.press("enter")


@sync
async def test_the_name_field_keeps_the_focus_and_typing_works(tmp_path: Path) -> None:
    path = copy(TUTORIAL, a_folder(tmp_path), "m.txt")
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        prompt, tree = await picker_of(pilot, OpenMapScreen)
        field = prompt.query_one("#filename", Input)
        assert field.has_focus and field.value == f"{tmp_path}/"
        assert listed(tree) == ["sub", "a.txt", "b.map", "m.txt"]
        assert str(tree.root.label) == tmp_path.name
        await pilot.press("end", "a", "full_stop", "t", "x", "t")  # after the folder offered
        await wait_until(pilot, lambda: field.value == f"{tmp_path}/a.txt")
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.session.map_path == tmp_path / "a.txt")


@pytest.mark.parametrize("how", ["enter", "click"])
@sync
async def test_choosing_a_file_fills_the_name_and_choosing_it_again_opens(
    tmp_path: Path, how: str
) -> None:
    """With enter on the picker's cursor, or with the mouse: once fills, twice opens."""
    a_folder(tmp_path)
    app = app_on(tmp_path / "a.txt")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        prompt, tree = await picker_of(pilot, OpenMapScreen)
        field = prompt.query_one("#filename", Input)
        line = 1 + listed(tree).index("b.map")  # the root is line 0
        if how == "enter":
            await choose(pilot, tree, "b.map")
        else:
            await pilot.click(MapTree, offset=(6, line))
        await wait_until(pilot, lambda: field.value == str(tmp_path / "b.map"))
        assert app.screen is prompt
        if how == "enter":
            await pilot.press("enter")  # the same file again
        else:
            await pilot.click(MapTree, offset=(6, line))
        await wait_until(pilot, lambda: app.session.map_path == tmp_path / "b.map")
        assert app.session.grid == load_map(tmp_path / "b.map")


@sync
async def test_choosing_a_folder_starts_the_name_with_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The built-in map (no file): the picker shows the current folder."""
    monkeypatch.chdir(a_folder(tmp_path))
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("w")
        prompt, tree = await picker_of(pilot, SaveAsScreen)
        assert tree.path == tmp_path
        await choose(pilot, tree, "sub")
        field = prompt.query_one("#filename", Input)
        await wait_until(pilot, lambda: field.value == f"{tmp_path / 'sub'}/")


@sync
async def test_save_as_a_file_chosen_asks_before_replacing_it(tmp_path: Path) -> None:
    a_folder(tmp_path)
    app = app_on(copy(TUTORIAL, tmp_path, "m.txt"))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("w")
        prompt, tree = await picker_of(pilot, SaveAsScreen)
        await choose(pilot, tree, "a.txt")
        await pilot.press("enter")
        await answer(pilot, ConfirmOverwriteScreen, "n")
        assert app.screen is prompt and app.session.map_path == tmp_path / "m.txt"


@sync
async def test_served_the_picker_is_confined_to_the_save_folder(tmp_path: Path) -> None:
    """Only the folder's map files, no folders; choosing one fills its plain name."""
    a_folder(tmp_path)
    (tmp_path / "link.txt").symlink_to(tmp_path / "a.txt")
    app = SearchApp(load_map(TUTORIAL), path=None, file_access=FileAccess.served_in(tmp_path))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        prompt, tree = await picker_of(pilot, OpenMapScreen)
        assert tree.path == tmp_path and listed(tree) == ["a.txt", "b.map"]
        await choose(pilot, tree, "a.txt")
        field = prompt.query_one("#filename", Input)
        await wait_until(pilot, lambda: field.value == "a.txt")
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.session.map_path == tmp_path / "a.txt")

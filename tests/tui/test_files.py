"""The app's files, driven by Pilot: saving keeps the file (comments, MovingAI header), save-as
never replaces a file without asking and keeps its prompt open on errors, ctrl+o opens a map
and asks first when the current one has unsaved edits."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from textual.widgets import Input

from tests.textual_internals import notifications
from tests.tui.test_app import MAPS, SIZE, click_shown, screen_shown, sync, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.write import format_text_map
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.confirm_overwrite import ConfirmOverwriteScreen
from tui_search.tui.dialogs.confirm_quit import ConfirmQuitScreen
from tui_search.tui.dialogs.open_map import OpenMapScreen
from tui_search.tui.dialogs.path_prompt import PathPrompt
from tui_search.tui.dialogs.save_as import SaveAsScreen

DATA = Path(__file__).parents[1] / "data" / "movingai"
TUTORIAL = MAPS / "tutorial.txt"


def copy(source: Path, folder: Path, name: str | None = None) -> Path:
    target = folder / (name or source.name)
    target.write_bytes(source.read_bytes())
    return target


def app_on(path: Path) -> SearchApp:
    return SearchApp(load_map(path), path=path)


def differing(a: bytes, b: bytes) -> list[int]:
    assert len(a) == len(b)
    return [i for i, (x, y) in enumerate(zip(a, b, strict=True)) if x != y]


async def type_name(pilot, name: str) -> None:
    """Once the name prompt is up, replace its text with ``name`` (as typed) and press enter;
    back when the prompt has answered (closed, and what it was for done, or an error shown)."""
    prompt = await screen_shown(pilot, PathPrompt)
    field = prompt.query_one(Input)
    if field.value != name:
        field.value = name
        await wait_until(pilot, lambda: not prompt.error)  # the change seen: no old error
    await pilot.press("enter")
    await wait_until(pilot, lambda: pilot.app.screen is not prompt or bool(prompt.error))
    await pilot.pause()  # the answer's callback, queued when the prompt closed


async def answer(pilot, kind: type, key: str) -> None:
    """Press ``key`` once the question ``kind`` is on top; back when it has closed and what
    it answered is done."""
    question = await screen_shown(pilot, kind)
    await pilot.press(key)
    await wait_until(pilot, lambda: pilot.app.screen is not question)
    await pilot.pause()


def untitled() -> SearchApp:
    """The app on the tutorial's map with no file (as ``tui-search`` with no argument)."""
    return SearchApp(load_map(TUTORIAL), path=None)


async def save_as(pilot, name: str) -> None:
    """ctrl+s on a map without a file, then ``name`` in its prompt."""
    await pilot.press("ctrl+s")
    await type_name(pilot, name)


def messages(app: SearchApp) -> list[str]:
    return [n.message for n in notifications(app)]


# -- saving keeps the file --------------------------------------------------------------


@sync
async def test_ctrl_s_keeps_the_comments_and_changes_only_the_moved_goal(tmp_path: Path) -> None:
    """The issue's case: a copy of maps/tutorial.txt, the goal moved, ctrl+s."""
    path = copy(TUTORIAL, tmp_path)
    original = path.read_bytes()
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+s")  # no edit: the same bytes
        await pilot.pause()
        assert path.read_bytes() == original
        app.session.cursor = (5, 1)
        await pilot.press("g")
        await wait_until(pilot, lambda: app.session.dirty)
        await pilot.press("ctrl+s")
        await wait_until(pilot, lambda: not app.session.dirty)
    saved = path.read_bytes()
    assert saved.count(b"\n;") == original.count(b"\n;") and saved.startswith(b"; The tutorial")
    # Two characters differ: the old G is now '.', the cell above it is 'G'.
    assert [saved[i : i + 1] for i in differing(original, saved)] == [b"G", b"."]
    assert load_map(path).goal == (5, 1)


@sync
async def test_ctrl_s_on_a_movingai_map_saves_it_in_place_as_a_map(tmp_path: Path) -> None:
    """arena.map: ctrl+s writes arena.map in MovingAI format (header kept, only the edited
    cell changed, to '@'), and says the start and goal are not saved in it."""
    path = copy(DATA / "arena.map", tmp_path)
    original = path.read_bytes()
    grid = load_map(path, start=(19, 26), goal=(19, 29))
    app = SearchApp(grid, path=path)
    async with app.run_test(size=SIZE) as pilot:
        app.session.cursor = (20, 26)
        assert not grid.is_blocked((20, 26))
        await pilot.press("o")
        await wait_until(pilot, lambda: app.session.dirty)
        await pilot.press("ctrl+s")
        await wait_until(pilot, lambda: not app.session.dirty)
        assert not isinstance(app.screen, SaveAsScreen) and app.session.map_path == path
        assert any("start and goal are not part of a .map file" in m for m in messages(app))
    saved = path.read_bytes()
    assert saved.split(b"\n")[:4] == original.split(b"\n")[:4]
    (i,) = differing(original, saved)
    assert saved[i : i + 1] == b"@" and i == original.index(b"map\n") + 4 + 26 * 50 + 20
    assert sorted(os.listdir(tmp_path)) == ["arena.map"]


@sync
async def test_save_as_txt_from_a_movingai_map_writes_the_text_format(tmp_path: Path) -> None:
    path = copy(DATA / "arena.map", tmp_path)
    app = SearchApp(load_map(path, start=(19, 26), goal=(19, 29)), path=path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("w")
        prompt = await screen_shown(pilot, SaveAsScreen)
        assert prompt.query_one("Input").value == str(tmp_path / "arena.txt")
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.screen is not prompt)
        await pilot.pause()
        assert app.session.map_path == tmp_path / "arena.txt"
    text_map = load_map(tmp_path / "arena.txt")
    assert text_map == app.session.grid and text_map.start == (19, 26)
    assert path.read_bytes() == (DATA / "arena.map").read_bytes()


# -- save-as never replaces a file without asking -----------------------------------------


@sync
async def test_save_as_onto_an_existing_file_asks_first(tmp_path: Path) -> None:
    """The built-in map, ctrl+s, the name of a file that exists: asked; 'choose another
    name' goes back to the prompt with the name; 'overwrite' replaces it."""
    other = tmp_path / "notes.txt"
    other.write_text("my notes\n")
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        await save_as(pilot, str(other))
        await screen_shown(pilot, ConfirmOverwriteScreen)
        assert other.read_text() == "my notes\n"
        await answer(pilot, ConfirmOverwriteScreen, "n")  # choose another name
        assert isinstance(app.screen, SaveAsScreen)
        assert app.screen.query_one("Input").value == str(other)
        assert other.read_text() == "my notes\n" and app.session.map_path is None
        await pilot.press("enter")
        await answer(pilot, ConfirmOverwriteScreen, "y")  # overwrite
        await wait_until(pilot, lambda: not isinstance(app.screen, SaveAsScreen))
        await pilot.pause()
        assert app.session.map_path == other
    assert other.read_text() == format_text_map(load_map(TUTORIAL))


@sync
async def test_the_overwrite_question_answers_the_mouse(tmp_path: Path) -> None:
    other = tmp_path / "keep.txt"
    other.write_text("keep\n")
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        await save_as(pilot, str(other))
        await click_shown(pilot, "#another")
        await screen_shown(pilot, SaveAsScreen)
        assert other.read_text() == "keep\n"
        await pilot.press("enter")
        await click_shown(pilot, "#overwrite")
        await wait_until(pilot, lambda: app.session.map_path == other)
        assert app.session.map_path == other and other.read_text() != "keep\n"


@sync
async def test_save_as_onto_the_maps_own_file_does_not_ask(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("down", "o")
        await wait_until(pilot, lambda: app.session.dirty)
        await pilot.press("w")
        await type_name(pilot, str(path))
        assert not isinstance(app.screen, (SaveAsScreen, ConfirmOverwriteScreen))
        assert not app.session.dirty and load_map(path).is_blocked((0, 1))


@sync
async def test_save_as_onto_a_folder_keeps_the_prompt_open_with_the_reason(
    tmp_path: Path,
) -> None:
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        await save_as(pilot, str(tmp_path))
        assert isinstance(app.screen, SaveAsScreen)
        assert app.screen.error == f"{tmp_path} is a folder: type a file name"
        assert app.screen.query_one("Input").value == str(tmp_path)
        assert os.listdir(tmp_path) == []


@sync
async def test_an_unwritable_target_keeps_the_prompt_open_with_the_reason(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Simulated (root, as in CI, may write anywhere): the rename onto the target fails."""
    target = tmp_path / "mine.txt"
    app = untitled()

    def refuse(src: str, dst: str) -> None:
        raise PermissionError(13, "Permission denied")

    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+s")
        monkeypatch.setattr(os, "replace", refuse)
        await type_name(pilot, str(target))
        assert isinstance(app.screen, SaveAsScreen)
        assert app.screen.error == f"{target}: cannot save: permission denied"
        assert app.session.map_path is None and os.listdir(tmp_path) == []
        monkeypatch.undo()
        await pilot.press("enter")  # the name is still there: try again
        await wait_until(pilot, lambda: app.session.map_path == target)
        assert not isinstance(app.screen, SaveAsScreen)
    assert load_map(target) == load_map(TUTORIAL)


# -- opening a map ------------------------------------------------------------------------


@sync
async def test_ctrl_o_opens_a_map(tmp_path: Path) -> None:
    app = untitled()
    other = MAPS / "exercise1-bfs-wins.txt"
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "ctrl+o")
        await screen_shown(pilot, OpenMapScreen)
        await type_name(pilot, str(other))
        assert not isinstance(app.screen, OpenMapScreen)
        assert app.session.map_path == other and app.session.grid == load_map(other)
        assert app.session.run.k == 0 and app.session.cursor == app.session.grid.start
        assert app.main.views[0].grid is app.session.grid
        assert app.main.views[0].border_title == "exercise1-bfs-wins.txt"


@sync
async def test_a_file_that_is_not_a_map_keeps_the_open_prompt_open(tmp_path: Path) -> None:
    broken = MAPS / "broken.txt"
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        await type_name(pilot, str(broken))
        assert isinstance(app.screen, OpenMapScreen)
        assert app.screen.error == f"{broken}:4:7: unknown cell character 'q'"
        await type_name(pilot, str(tmp_path / "missing.txt"))
        assert app.screen.error == f"{tmp_path / 'missing.txt'}: no such file"
        await pilot.press("escape")
        await wait_until(pilot, lambda: not isinstance(app.screen, OpenMapScreen))
        assert app.session.map_path is None and app.session.grid == load_map(TUTORIAL)


@sync
async def test_opening_a_map_over_unsaved_edits_asks_first(tmp_path: Path) -> None:
    """Cancel keeps the edited map; discard opens the new one; save saves, then opens."""
    path = copy(TUTORIAL, tmp_path)
    other = MAPS / "no-path.txt"
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("down", "o")
        await wait_until(pilot, lambda: app.session.dirty)
        await pilot.press("ctrl+o")
        await type_name(pilot, str(other))
        question = await screen_shown(pilot, ConfirmQuitScreen)
        assert "Open no-path.txt anyway?" in str(question.query_one("Label").content)
        await answer(pilot, ConfirmQuitScreen, "n")  # cancel
        assert app.session.map_path == path and app.session.dirty
        assert app.session.grid.is_blocked((0, 1))
        await pilot.press("ctrl+o")
        await type_name(pilot, str(other))
        await answer(pilot, ConfirmQuitScreen, "s")  # save, then open
        await wait_until(pilot, lambda: app.session.map_path == other)
        assert not app.session.dirty
        assert load_map(path).is_blocked((0, 1))
        app.session.cursor = (0, 1)
        await pilot.press("o")
        await wait_until(pilot, lambda: app.session.dirty)
        await pilot.press("ctrl+o")
        await type_name(pilot, str(path))
        await answer(pilot, ConfirmQuitScreen, "y")  # discard the edit
        await wait_until(pilot, lambda: app.session.map_path == path)
        assert not app.session.dirty
    assert (MAPS / "no-path.txt").read_bytes() == other.read_bytes()


@sync
async def test_replace_map_is_what_an_exercise_calls(tmp_path: Path) -> None:
    """``replace_map`` asks when there are edits; an untitled map made in code then asks for
    a name on 'save', and opens the new map once saved."""
    app = untitled()
    exercise = load_map(MAPS / "exercise2-dfs-longer.txt")
    async with app.run_test(size=SIZE) as pilot:
        app.main.files.replace_map(exercise, None, "Exercise 2")
        await pilot.pause()
        # nothing unsaved: no question
        assert app.session.grid is exercise and app.session.map_path is None
        await pilot.press("down", "o")  # the cursor is on the start (1,1): blocks (1,2)
        await wait_until(pilot, lambda: app.session.dirty)
        app.main.files.replace_map(load_map(TUTORIAL), None, "the tutorial")
        question = await screen_shown(pilot, ConfirmQuitScreen)
        assert "Open the tutorial anyway?" in str(question.query_one("Label").content)
        await answer(pilot, ConfirmQuitScreen, "s")
        await type_name(pilot, str(tmp_path / "ex2.txt"))
        assert app.session.grid == load_map(TUTORIAL) and not app.session.dirty
    saved = load_map(tmp_path / "ex2.txt")
    assert saved.is_blocked((1, 2))
    saved.set_blocked((1, 2), False)
    assert saved == load_map(MAPS / "exercise2-dfs-longer.txt")

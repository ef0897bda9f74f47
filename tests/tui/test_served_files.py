"""The served app's files, driven by Pilot: with saving off, ctrl+s, w and ctrl+o each say so
in one line and open nothing; with a save folder, the save-as and open prompts take only
plain names in it (a name that would leave it, or holds a control or bidi character, is
refused in the prompt), and ctrl+s never writes the map the teacher served; a theme chosen
in the served app writes no config file."""

from __future__ import annotations

from pathlib import Path

from tests.tui.test_app import SIZE, screen_shown, sync, wait_until
from tests.tui.test_files import TUTORIAL, copy, messages, type_name
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.config import Config, config_path
from tui_search.tui.dialogs.confirm_quit import ConfirmQuitScreen
from tui_search.tui.dialogs.open_map import OpenMapScreen
from tui_search.tui.dialogs.save_as import SaveAsScreen
from tui_search.tui.model.file_rules import OFF_MESSAGE, FileAccess


def served_app(path: Path | None, folder: Path | None) -> SearchApp:
    return SearchApp(load_map(TUTORIAL), path=path, config=Config.in_memory(),
                     file_access=FileAccess.served_in(folder))


@sync
async def test_with_saving_off_each_file_key_says_so_and_opens_nothing(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    before = path.read_bytes()
    app = served_app(path, None)
    async with app.run_test(size=SIZE) as pilot:
        app.session.cursor = (5, 1)
        await pilot.press("g")  # an edit: ctrl+s would save it
        await wait_until(pilot, lambda: app.session.dirty)
        for said, key in enumerate(("ctrl+s", "w", "ctrl+o"), 1):
            await pilot.press(key)
            await wait_until(pilot, lambda n=said: len(messages(app)) == n)
            await pilot.pause()
            assert len(app.screen_stack) == 1, key
        assert messages(app) == [OFF_MESSAGE] * 3
        assert "\n" not in OFF_MESSAGE
        # Quitting with edits still asks; "save" then says saving is off and stays.
        await pilot.press("q")
        await screen_shown(pilot, ConfirmQuitScreen)
        await pilot.press("s")
        await wait_until(pilot, lambda: len(messages(app)) == 4)
        assert app.session.dirty and messages(app)[-1] == OFF_MESSAGE
    assert path.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tutorial.txt"]


@sync
async def test_save_as_takes_plain_names_in_the_folder_only(tmp_path: Path) -> None:
    folder = tmp_path / "saves"
    folder.mkdir()
    served = copy(TUTORIAL, tmp_path)
    before = served.read_bytes()
    app = served_app(served, folder)
    async with app.run_test(size=SIZE) as pilot:
        app.session.cursor = (5, 1)
        await pilot.press("g", "ctrl+s")  # the served map is not in the folder: a name first
        prompt = await screen_shown(pilot, SaveAsScreen)
        assert prompt.query_one("Input").value == "tutorial.txt"  # a name, not a path
        for name, says in (("../escape.txt", "without a folder part"),
                           (str(tmp_path / "abs.txt"), "without a folder part"),
                           (".profile.txt", "may not start with '.'"),
                           ("run.sh", "ends in .txt or .map"),
                           ("evil\u202etxt.map", "control, bidi or invisible characters (\\u202e)"),
                           ("red\x1b[31m.txt", "control, bidi or invisible characters (\\x1b)")):
            await type_name(pilot, name)
            assert app.screen is prompt and says in prompt.error, (name, prompt.error)
        await type_name(pilot, "mine.txt")
        assert app.screen is not prompt
        assert app.session.map_path == folder.resolve() / "mine.txt" and not app.session.dirty
        app.session.cursor = (2, 1)  # ctrl+s now saves over the folder's file without asking
        await pilot.press("g")
        await wait_until(pilot, lambda: app.session.dirty)
        await pilot.press("ctrl+s")
        await wait_until(pilot, lambda: not app.session.dirty)
        assert len(app.screen_stack) == 1
    assert served.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["saves", "tutorial.txt"]
    assert [p.name for p in folder.iterdir()] == ["mine.txt"]
    assert load_map(folder / "mine.txt").goal == (2, 1)


@sync
async def test_the_open_prompt_reads_only_names_in_the_folder(tmp_path: Path) -> None:
    folder = tmp_path / "saves"
    folder.mkdir()
    copy(TUTORIAL, tmp_path, "outside.txt")
    (folder / "link.txt").symlink_to(tmp_path / "outside.txt")
    copy(TUTORIAL, folder, "class.txt")
    app = served_app(None, folder)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        prompt = await screen_shown(pilot, OpenMapScreen)
        assert prompt.query_one("Input").value == ""
        for name, says in (("../outside.txt", "without a folder part"),
                           (str(tmp_path / "outside.txt"), "without a folder part"),
                           ("link.txt", "a link out of")):
            await type_name(pilot, name)
            assert app.screen is prompt and says in prompt.error, (name, prompt.error)
        await type_name(pilot, "class.txt")
        assert app.screen is not prompt and app.session.map_path == folder.resolve() / "class.txt"


@sync
async def test_a_theme_chosen_in_the_served_app_is_not_written() -> None:
    app = served_app(None, None)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("t")
        await wait_until(pilot, lambda: app.theme != "dark")
        await pilot.pause()
        assert app.config.theme == app.theme
    assert not config_path().exists()

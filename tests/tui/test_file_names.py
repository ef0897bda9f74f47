"""No file name makes the app raise, driven by Pilot: in the open prompt, save-as and ``w``,
a name too long for the file system, a NUL, Rich-like markup (``[/]``, ``[bold]``), control
and bidi characters are each an action or a one-line error, and every name the app shows
(title, notification, question, prompt) is shown as typed, control characters escaped."""

from __future__ import annotations

import asyncio
import os
import tempfile
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from textual.content import Content
from textual.widgets import Input

from tests.textual_internals import notifications
from tests.tui.test_app import SIZE, screen_shown, sync, wait_until
from tests.tui.test_files import TUTORIAL, answer, app_on, copy, type_name, untitled
from tui_search.engine.maps.load import load_map
from tui_search.engine.util.filenames import describe_name
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.confirm_overwrite import ConfirmOverwriteScreen
from tui_search.tui.dialogs.confirm_quit import ConfirmQuitScreen
from tui_search.tui.dialogs.open_map import OpenMapScreen
from tui_search.tui.dialogs.path_prompt import PathPrompt
from tui_search.tui.dialogs.save_as import SaveAsScreen
from tui_search.tui.model.file_rules import FileAccess, name_or_problem

ODD = ["[bold]m.txt", "[@click=app.quit]m.txt", "x\x1b[31mred.txt", "a\u202etxt.txt",
       "tab\there.txt", "back\\slash.txt", "é 地図.txt"]


def pane_title(app: SearchApp) -> str:
    """The map pane's title as shown (its border title is markup)."""
    return Content.from_markup(app.main.views[0].border_title or "").plain


async def edited(pilot, app: SearchApp) -> None:
    app.session.cursor = (0, 1)
    await pilot.press("o")
    await wait_until(pilot, lambda: app.session.dirty)


# -- names no file can have: an error in the prompt, nothing lost ---------------------------


@sync
async def test_w_with_a_300_character_name_is_an_error_in_the_prompt(tmp_path: Path) -> None:
    """The issue's case: unsaved edits, ``w``, 300 characters, enter: the app stays, the
    prompt says why, the edits are still there; a good name then saves them."""
    app = app_on(copy(TUTORIAL, tmp_path))
    async with app.run_test(size=SIZE) as pilot:
        await edited(pilot, app)
        await pilot.press("w")
        await type_name(pilot, str(tmp_path / ("n" * 300 + ".txt")))
        assert isinstance(app.screen, SaveAsScreen)
        assert app.screen.error == "the name is too long (at most 255 bytes between slashes)"
        await type_name(pilot, str(tmp_path / "a\x00b.txt"))
        assert app.screen.error == "a file name cannot hold a NUL character (\\x00)"
        assert app.session.dirty and app.is_running
        await type_name(pilot, str(tmp_path / "ok.txt"))
        await wait_until(pilot, lambda: not app.session.dirty)
    assert load_map(tmp_path / "ok.txt").is_blocked((0, 1))


@sync
async def test_the_open_prompt_refuses_such_names_in_one_line(tmp_path: Path) -> None:
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        for name, error in [("n" * 300, "the name is too long (at most 255 bytes between slashes)"),
                            ("a\x00b", "a file name cannot hold a NUL character (\\x00)"),
                            (str(tmp_path / "x[/]y.txt"), f"{tmp_path}/x[/]y.txt: no such file"),
                            (str(tmp_path / "\x1b[2J.txt"),
                             f"{tmp_path}/\\x1b[2J.txt: no such file")]:
            await type_name(pilot, name)
            assert isinstance(app.screen, OpenMapScreen) and app.screen.error == error


# -- odd names: saved, and shown as typed ----------------------------------------------------


@sync
async def test_odd_names_save_and_show_as_typed(tmp_path: Path) -> None:
    """Each name saves; the pane's title, the 'Saved' note and the quit question show it with
    control and bidi characters escaped and markup as plain text (no MarkupError, no action
    run from a '[@click=...]')."""
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        for name in ODD:
            await pilot.press("w")
            await type_name(pilot, str(tmp_path / name))
            await wait_until(pilot, lambda name=name: app.session.map_path == tmp_path / name)
            shown = describe_name(name)
            await wait_until(pilot, lambda shown=shown: pane_title(app) == shown)
            assert notifications(app)[-1].message == f"Saved {describe_name(str(tmp_path / name))}"
            assert load_map(tmp_path / name) == app.session.grid
        await edited(pilot, app)
        await pilot.press("q")
        question = await screen_shown(pilot, ConfirmQuitScreen)
        assert f"The map {describe_name(ODD[-1])} has edits" in str(
            question.query_one("Label").content)
        await answer(pilot, ConfirmQuitScreen, "n")
        app.session.map_path = tmp_path / ODD[2]  # an odd name in the overwrite question
        await pilot.press("w")
        await type_name(pilot, str(tmp_path / ODD[3]))
        question = await screen_shown(pilot, ConfirmOverwriteScreen)
        assert str(question.query_one("Label").content).startswith(
            f"{tmp_path}/a\\u202etxt.txt already exists")
    assert sorted(os.listdir(tmp_path)) == sorted(ODD)


# -- any name: hypothesis --------------------------------------------------------------------


@given(st.text(), st.booleans())
def test_any_name_is_a_path_or_one_line(typed: str, served: bool) -> None:
    """What a prompt makes of a name never raises: a path, or one printable line."""
    with tempfile.TemporaryDirectory() as folder:
        access = FileAccess.served_in(folder) if served else FileAccess()
        result = name_or_problem(typed, access.path_for)
        assert isinstance(result, Path) or (result and result.isprintable())


#: Names that stay in the folder they are typed in (no '/'), or go nowhere ('~' alone is
#: the home folder: refused as a folder).
NAMES = st.text(st.characters(blacklist_characters="/"), min_size=1, max_size=40) | st.sampled_from(
    ["n" * 300, "a\x00b", "[/]", "[bold]", "\x1b[2J", "\u202e.txt", ".", "..", "~", " "])


async def try_names(names: list[str], folder: Path) -> None:
    """Type each name into the save-as prompt (``w``) and then the open prompt (ctrl+o) of
    one app: each ends as an action or a one-line error; the app never raises."""
    app = untitled()
    async with app.run_test(size=SIZE) as pilot:
        for name in names:
            for key in ("w", "ctrl+o"):
                await pilot.press(key)
                prompt = await screen_shown(pilot, PathPrompt)
                prompt.query_one("#filename", Input).value = name
                await pilot.press("enter")
                blank = not name.strip()  # enter does nothing
                await wait_until(pilot, lambda prompt=prompt, blank=blank: blank
                                 or app.screen is not prompt or bool(prompt.error))
                if app.screen is prompt:
                    assert prompt.error == "" or prompt.error.isprintable()
                    await pilot.press("escape")
                else:  # saved or opened, or a question: its escape is the safe answer
                    while app.screen is not app.main:
                        top = app.screen
                        await pilot.press("escape")
                        await wait_until(pilot, lambda top=top: app.screen is not top)
                await wait_until(pilot, lambda: app.screen is app.main)
        assert app.is_running
    assert app.return_code is None or app.return_code == 0


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(NAMES, min_size=1, max_size=5))
def test_no_typed_name_makes_the_app_raise(names: list[str]) -> None:
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as folder:
        os.chdir(folder)
        try:
            asyncio.run(try_names(names, Path(folder)))
        finally:
            os.chdir(here)

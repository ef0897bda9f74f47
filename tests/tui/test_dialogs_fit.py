"""Every dialog fits the terminal, from 80x24 up: each button (and a prompt's field and hint)
is on screen without scrolling, and a click on it acts.

Each dialog is opened as a user opens it (keys), the test waits until its widgets stay in
place between two looks, then checks every one lies inside the screen and inside the visible
part of every container around it (a scrolling one, or one that clips).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from textual.geometry import Region
from textual.screen import Screen
from textual.widget import Widget
from textual.widgets import Button, Input

from tests.tui.test_app import MAPS, TUTORIAL, click_shown, sync, tutorial_app, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.confirm_overwrite import ConfirmOverwriteScreen
from tui_search.tui.dialogs.confirm_quit import ConfirmQuitScreen
from tui_search.tui.dialogs.help import HelpScreen
from tui_search.tui.dialogs.open_map import OpenMapScreen
from tui_search.tui.dialogs.save_as import SaveAsScreen
from tui_search.tui.dialogs.save_refused import ChangedOnDiskScreen, DropEditsScreen, InPlaceScreen
from tui_search.tui.dialogs.settings import SettingsScreen
from tui_search.tui.widgets.map_tree import MapTree

SIZES = [(80, 24), (100, 30), (120, 40), (160, 48), (200, 60)]


def shown_widgets(screen: Screen[object]) -> list[Widget]:
    """What must be on screen without scrolling: the buttons, a prompt's field, its file
    picker, the hints."""
    return [*screen.query(Button), *screen.query(Input).filter("#filename"),
            *screen.query(MapTree), *screen.query(".hint")]


def problems(screen: Screen[object]) -> list[str]:
    """Each widget that is not wholly visible, and where it is cut off."""
    found = []
    for widget in shown_widgets(screen):
        region = widget.region
        if not region.area:
            found.append(f"{widget!r} is not laid out")
            continue
        for outer in widget.ancestors_with_self[1:]:
            if not isinstance(outer, Widget):
                continue
            seen = outer.region if isinstance(outer, Screen) else outer.scrollable_content_region
            if seen.intersection(region) != region:
                found.append(f"{widget!r} at {region} is cut off by {outer!r} ({seen})")
    return found


async def settle_on(pilot, kind: type[Screen[object]]) -> Screen[object]:
    """Wait for ``kind`` on top, laid out: every widget checked in the same place twice."""
    await wait_until(pilot, lambda: isinstance(pilot.app.screen, kind))
    screen = pilot.app.screen
    seen: list[list[Region]] = []

    def steady() -> bool:
        regions = [w.region for w in shown_widgets(screen)]
        ok = bool(regions) and all(r.area for r in regions) and seen[-1:] == [regions]
        seen.append(regions)
        return ok

    await wait_until(pilot, steady)
    return screen


async def assert_fits(pilot, kind: type[Screen[object]]) -> Screen[object]:
    screen = await settle_on(pilot, kind)
    assert problems(screen) == []
    return screen


def on_copy(tmp_path: Path) -> tuple[SearchApp, Path]:
    path = tmp_path / "tutorial.txt"
    shutil.copyfile(TUTORIAL, path)
    return tutorial_app(path=path), path


# -- settings ------------------------------------------------------------------------------


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_settings_buttons_show_and_act(size: tuple[int, int]) -> None:
    """Apply applies the corners picked; Defaults shows the defaults; Cancel keeps what was
    applied."""
    app = tutorial_app()
    async with app.run_test(size=size) as pilot:
        await pilot.press("n", "comma")
        screen = await assert_fits(pilot, SettingsScreen)
        await pilot.press("right", "right", "enter")  # corners has the focus: never
        await wait_until(pilot, lambda: screen.query_one("#corners-never").value)
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        assert app.session.semantics == Semantics(corners="never")
        await pilot.press("comma")
        screen = await assert_fits(pilot, SettingsScreen)
        await click_shown(pilot, "#defaults")
        await wait_until(pilot, lambda: screen.query_one("#corners-always").value)
        await click_shown(pilot, "#cancel")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        assert app.session.semantics == Semantics(corners="never")


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_settings_in_compare_mode_fit_and_cancel(size: tuple[int, int]) -> None:
    """In compare mode (more choices apply), Cancel is on screen and changes nothing."""
    app = tutorial_app()
    async with app.run_test(size=size) as pilot:
        await pilot.press("c")
        await wait_until(pilot, lambda: len(app.session.runs) > 1)
        runs = list(app.session.runs)
        await pilot.press("comma")
        screen = await assert_fits(pilot, SettingsScreen)
        assert "BFS · DFS" in str(screen.query_one("VerticalScroll").border_title)
        await click_shown(pilot, "#cancel")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        assert list(app.session.runs) == runs and app.session.semantics == Semantics()


@pytest.mark.parametrize("keys", [["comma"], ["c", "comma"]])
@sync
async def test_settings_at_80x24_show_every_choice_and_the_notes(keys: list[str]) -> None:
    """At 80x24 the choices fit without scrolling: the explanations are hidden, save the note
    that the heuristic does not apply to BFS (or DFS)."""
    app = tutorial_app()
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press(*keys)
        screen = await assert_fits(pilot, SettingsScreen)
        box = screen.query_one("VerticalScroll")
        assert box.max_scroll_y == 0
        assert not screen.query_one("#visit-explain").display
        note = screen.query_one("#heuristic-explain")
        assert note.display and "does not apply" in str(note.content)


# -- help ----------------------------------------------------------------------------------


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_help_shows_how_to_close_it(size: tuple[int, int]) -> None:
    """The box, and its title saying escape closes it, are wholly on screen; escape does."""
    app = tutorial_app()
    async with app.run_test(size=size) as pilot:
        await pilot.press("question_mark")
        await wait_until(pilot, lambda: isinstance(app.screen, HelpScreen))
        box = app.screen.query_one("VerticalScroll")
        await wait_until(pilot, lambda: box.region.area > 0)
        assert app.screen.region.intersection(box.region) == box.region
        title = str(box.border_title)
        assert "escape to close" in title and len(title) + 4 <= box.region.width
        await pilot.press("escape")
        await wait_until(pilot, lambda: not isinstance(app.screen, HelpScreen))


@sync
async def test_help_wraps_a_key_s_description_under_itself_not_under_the_keys() -> None:
    """At 80x24 the longer descriptions wrap: each row of the keys' table starts with a key
    the app binds, or with blanks as wide as the keys' column (the description goes on)."""
    from tests.textual_internals import repainted
    from tui_search.tui.dialogs.help import KEYS

    app = tutorial_app()
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("question_mark")
        await wait_until(pilot, lambda: isinstance(app.screen, HelpScreen))
        table = app.screen.query_one("#help-keys")
        await wait_until(pilot, lambda: table.region.area > 0)
        region = table.region.intersection(
            app.screen.query_one("VerticalScroll").scrollable_content_region)
        screen = ["".join(text for text, _ in line) for line in await repainted(pilot)]
        rows = [screen[y][region.x:region.right] for y in range(region.y, region.bottom)]
        column = max(len(key) for key, _ in KEYS) + 2
        starts = {key for key, _ in KEYS}
        wrapped = [row for row in rows if not row[:column].strip()]
        assert wrapped and rows[0][:column].strip() in starts  # some wrap at 80 columns
        for row in rows:
            assert row[:column].strip() in starts | {""}, row


# -- questions -----------------------------------------------------------------------------


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_quit_question_fits_and_stay_stays(size: tuple[int, int], tmp_path: Path) -> None:
    app, _ = on_copy(tmp_path)
    async with app.run_test(size=size) as pilot:
        await pilot.press("down", "o", "q")
        await assert_fits(pilot, ConfirmQuitScreen)
        await click_shown(pilot, "#stay")
        await wait_until(pilot, lambda: not isinstance(app.screen, ConfirmQuitScreen))
        assert app.session.dirty and app.is_running


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_open_over_edits_question_fits_and_cancel_keeps(
    size: tuple[int, int], tmp_path: Path
) -> None:
    """The longest buttons: 'Save, then open (s)', 'Discard edits (y)', 'Cancel (n)'."""
    app, path = on_copy(tmp_path)
    async with app.run_test(size=size) as pilot:
        await pilot.press("down", "o", "ctrl+o")
        prompt = await settle_on(pilot, OpenMapScreen)
        prompt.query_one(Input).value = str(MAPS / "no-path.txt")
        await pilot.press("enter")
        await assert_fits(pilot, ConfirmQuitScreen)
        await click_shown(pilot, "#stay")
        await wait_until(pilot, lambda: not isinstance(app.screen, ConfirmQuitScreen))
        assert app.session.map_path == path and app.session.dirty


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_overwrite_question_fits_and_acts(size: tuple[int, int], tmp_path: Path) -> None:
    """'Choose another name' goes back to the prompt; 'Overwrite' replaces the file."""
    app, _ = on_copy(tmp_path)
    other = tmp_path / "other.txt"
    other.write_text("keep me\n")
    async with app.run_test(size=size) as pilot:
        await pilot.press("w")
        prompt = await assert_fits(pilot, SaveAsScreen)
        prompt.query_one(Input).value = str(other)
        await pilot.press("enter")
        await assert_fits(pilot, ConfirmOverwriteScreen)
        await click_shown(pilot, "#another")
        await wait_until(pilot, lambda: app.screen is prompt)
        assert other.read_text() == "keep me\n"
        await pilot.press("enter")
        await assert_fits(pilot, ConfirmOverwriteScreen)
        await click_shown(pilot, "#overwrite")
        await wait_until(pilot, lambda: not isinstance(app.screen, SaveAsScreen))
        assert other.read_text() != "keep me\n"


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_changed_on_disk_questions_fit_and_act(size: tuple[int, int], tmp_path: Path) -> None:
    """The four buttons of 'Changed on disk' (the widest row), then reload's second
    question: 'Keep my edits' keeps them, 'Cancel' keeps both versions."""
    _, path = on_copy(tmp_path)
    app = SearchApp(load_map(path), path=path)  # the copy read: its stamp is the copy's
    async with app.run_test(size=size) as pilot:
        await pilot.press("down", "o")
        await wait_until(pilot, lambda: app.session.dirty)
        theirs = b"; theirs\n" + path.read_bytes()
        path.write_bytes(theirs)
        await pilot.press("ctrl+s")
        await assert_fits(pilot, ChangedOnDiskScreen)
        await click_shown(pilot, "#reload")
        await assert_fits(pilot, DropEditsScreen)
        await click_shown(pilot, "#cancel")
        await wait_until(pilot, lambda: app.screen is app.main)
        await pilot.press("ctrl+s")
        await assert_fits(pilot, ChangedOnDiskScreen)
        await click_shown(pilot, "#cancel")
        await wait_until(pilot, lambda: app.screen is app.main)
        assert app.session.dirty and path.read_bytes() == theirs


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_hard_link_question_fits_and_acts(size: tuple[int, int], tmp_path: Path) -> None:
    app, path = on_copy(tmp_path)
    (tmp_path / "alias.txt").hardlink_to(path)
    async with app.run_test(size=size) as pilot:
        await pilot.press("down", "o")
        await wait_until(pilot, lambda: app.session.dirty)
        await pilot.press("ctrl+s")
        await assert_fits(pilot, InPlaceScreen)
        await click_shown(pilot, "#yes")
        await wait_until(pilot, lambda: not app.session.dirty)
        assert (tmp_path / "alias.txt").read_bytes() == path.read_bytes()


# -- prompts -------------------------------------------------------------------------------


@pytest.mark.parametrize("size", SIZES)
@sync
async def test_prompts_fit_with_an_error_shown(size: tuple[int, int], tmp_path: Path) -> None:
    """Save as (w) and open (ctrl+o): the field and the hint are on screen, also with a
    long error shown; escape cancels."""
    app, _ = on_copy(tmp_path)
    async with app.run_test(size=size) as pilot:
        for key, kind in (("w", SaveAsScreen), ("ctrl+o", OpenMapScreen)):
            await pilot.press(key)
            prompt = await assert_fits(pilot, kind)
            prompt.query_one(Input).value = str(tmp_path / ("no-such-folder-" * 4) / "map.txt")
            await pilot.press("enter")
            error = prompt.query_one("#error")
            await wait_until(pilot, lambda error=error: error.has_class("-shown"))
            await assert_fits(pilot, kind)
            await pilot.press("escape")
            await wait_until(pilot, lambda: app.screen is app.main)

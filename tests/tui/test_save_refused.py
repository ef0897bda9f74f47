"""A save the engine refuses is never a lost edit, driven by Pilot: a file changed on disk
asks (overwrite, reload after a second question, save as, cancel), a read-only file opens
save-as with the reason, a file with hard links asks before writing in place, a map that
would not load again is refused in one line; after any save or reload the next save does
not ask again."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest
from textual.widgets import Input

from tests.textual_internals import notifications
from tests.tui.test_app import SIZE, screen_shown, sync, wait_until
from tests.tui.test_files import TUTORIAL, answer, app_on, copy, type_name
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MapError
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.confirm_overwrite import ConfirmOverwriteScreen
from tui_search.tui.dialogs.save_as import SaveAsScreen
from tui_search.tui.dialogs.save_refused import ChangedOnDiskScreen, DropEditsScreen, InPlaceScreen

OTHERS = "; another program was here\n"


async def edit(pilot, app: SearchApp, cell: tuple[int, int] = (0, 1)) -> None:
    """Toggle the obstacle at ``cell``; back once the map says it is modified."""
    app.session.cursor = cell
    await pilot.press("o")
    await wait_until(pilot, lambda: app.session.dirty)


def change_on_disk(path: Path) -> bytes:
    """What another program does: a comment added at the top.  Returns the new bytes."""
    data = OTHERS.encode() + path.read_bytes()
    path.write_bytes(data)
    return data


async def ctrl_s_after_a_change_on_disk(pilot, app: SearchApp, path: Path) -> bytes:
    """Edit the map, let another program change its file, press ctrl+s; the file's bytes."""
    await edit(pilot, app)
    theirs = change_on_disk(path)
    await pilot.press("ctrl+s")
    return theirs


async def saved_without_asking(pilot, app: SearchApp) -> None:
    """ctrl+s saves at once: no question, the title no longer says modified."""
    await pilot.press("ctrl+s")
    await wait_until(pilot, lambda: not app.session.dirty)
    assert app.screen is app.main


# -- changed on disk ------------------------------------------------------------------------


@sync
async def test_changed_on_disk_cancel_keeps_both_then_overwrite_replaces(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        theirs = await ctrl_s_after_a_change_on_disk(pilot, app, path)
        question = await screen_shown(pilot, ChangedOnDiskScreen)
        assert "changed on disk since it was opened or saved" in str(
            question.query_one("Label").content)
        assert [b.id for b in question.query("Button")] == ["overwrite", "reload", "save-as",
                                                              "cancel"]
        await answer(pilot, ChangedOnDiskScreen, "c")
        assert path.read_bytes() == theirs and app.session.dirty
        await pilot.press("ctrl+s")
        await answer(pilot, ChangedOnDiskScreen, "o")
        await wait_until(pilot, lambda: not app.session.dirty)
        assert load_map(path).is_blocked((0, 1)) and not path.read_text().startswith(OTHERS)
        await edit(pilot, app, (1, 0))  # the stamp is the file just written: no question
        await saved_without_asking(pilot, app)
    assert load_map(path).is_blocked((1, 0)) != load_map(TUTORIAL).is_blocked((1, 0))


@sync
async def test_reload_with_edits_asks_again_before_dropping_them(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        theirs = await ctrl_s_after_a_change_on_disk(pilot, app, path)
        await answer(pilot, ChangedOnDiskScreen, "r")
        question = await screen_shown(pilot, DropEditsScreen)
        assert "drops the edits made in the app" in str(question.query_one("Label").content)
        await answer(pilot, DropEditsScreen, "n")  # keep them
        assert app.session.dirty and app.session.grid.is_blocked((0, 1))
        await pilot.press("ctrl+s")
        await answer(pilot, ChangedOnDiskScreen, "r")
        await answer(pilot, DropEditsScreen, "y")
        await wait_until(pilot, lambda: not app.session.dirty)
        assert app.session.grid == load_map(path) and not app.session.grid.is_blocked((0, 1))
        assert path.read_bytes() == theirs
        await edit(pilot, app)
        await saved_without_asking(pilot, app)
    assert path.read_text().startswith(OTHERS) and load_map(path).is_blocked((0, 1))


@sync
async def test_reload_without_edits_does_not_ask_again(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        theirs = change_on_disk(path)
        await pilot.press("ctrl+s")  # no edits: the file would be written the same
        await answer(pilot, ChangedOnDiskScreen, "r")
        await wait_until(pilot, lambda: app.session.grid.source is not None
                         and app.session.grid.source.lines[0] == OTHERS.strip())
        assert app.screen is app.main and path.read_bytes() == theirs


@sync
async def test_changed_on_disk_save_as_writes_another_file(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    other = tmp_path / "mine.txt"
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        theirs = await ctrl_s_after_a_change_on_disk(pilot, app, path)
        await answer(pilot, ChangedOnDiskScreen, "a")
        await type_name(pilot, str(other))
        await wait_until(pilot, lambda: app.session.map_path == other)
        assert not app.session.dirty and path.read_bytes() == theirs
    assert load_map(other).is_blocked((0, 1))


@sync
async def test_save_as_onto_the_own_file_changed_on_disk_asks(tmp_path: Path) -> None:
    """w, the map's own name: its file changed, so the overwrite question says so; 'choose
    another name' goes back to the prompt, 'overwrite' replaces it."""
    path = copy(TUTORIAL, tmp_path)
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await edit(pilot, app)
        theirs = change_on_disk(path)
        await pilot.press("w")
        await type_name(pilot, str(path))
        question = await screen_shown(pilot, ConfirmOverwriteScreen)
        assert "changed on disk" in str(question.query_one("Label").content)
        await answer(pilot, ConfirmOverwriteScreen, "n")
        assert isinstance(app.screen, SaveAsScreen) and path.read_bytes() == theirs
        await pilot.press("enter")
        await answer(pilot, ConfirmOverwriteScreen, "y")
        await wait_until(pilot, lambda: not app.session.dirty)
        assert app.screen is app.main
    assert load_map(path).is_blocked((0, 1))


# -- read-only ----------------------------------------------------------------------------


@sync
async def test_a_read_only_file_opens_save_as_with_the_reason(tmp_path: Path) -> None:
    """Mode 0444: refused to anyone (root too: the file's mode says it is not to be
    changed, see tests/engine/test_savesafety.py), the file untouched, save-as open with
    the name and the reason; another name saves."""
    path = copy(TUTORIAL, tmp_path)
    path.chmod(0o444)
    before = path.read_bytes()
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await edit(pilot, app)
        await pilot.press("ctrl+s")
        prompt = await screen_shown(pilot, SaveAsScreen)
        await wait_until(pilot, lambda: bool(prompt.error))
        assert prompt.error == f"{path}: cannot save: the file is read-only"
        assert prompt.query_one("#filename", Input).value == str(path)
        assert path.read_bytes() == before and app.session.dirty
        await type_name(pilot, str(tmp_path / "copy.txt"))
        await wait_until(pilot, lambda: not app.session.dirty)
    assert stat.S_IMODE(path.stat().st_mode) == 0o444 and path.read_bytes() == before
    assert load_map(tmp_path / "copy.txt").is_blocked((0, 1))


@sync
async def test_save_as_onto_a_read_only_file_keeps_the_prompt_open(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    locked = tmp_path / "locked.txt"
    locked.write_text("keep\n")
    locked.chmod(0o444)
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await edit(pilot, app)
        await pilot.press("w")
        await type_name(pilot, str(locked))
        await answer(pilot, ConfirmOverwriteScreen, "y")
        prompt = await screen_shown(pilot, SaveAsScreen)
        await wait_until(pilot, lambda: bool(prompt.error))
        assert prompt.error == f"{locked}: cannot save: the file is read-only"
        assert prompt.query_one("#filename", Input).value == str(locked)
    assert locked.read_text() == "keep\n" and app.session.dirty


# -- hard links ---------------------------------------------------------------------------


@sync
async def test_a_file_with_hard_links_is_written_in_place_only_when_asked(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    alias = tmp_path / "alias.txt"
    os.link(path, alias)
    before = path.read_bytes()
    app = app_on(path)
    async with app.run_test(size=SIZE) as pilot:
        await edit(pilot, app)
        await pilot.press("ctrl+s")
        question = await screen_shown(pilot, InPlaceScreen)
        assert "this file has 1 other name; write it in place so they all change?" in str(
            question.query_one("Label").content)
        await answer(pilot, InPlaceScreen, "n")
        assert path.read_bytes() == before and app.session.dirty
        await pilot.press("ctrl+s")
        await answer(pilot, InPlaceScreen, "y")
        await wait_until(pilot, lambda: not app.session.dirty)
    assert os.path.samefile(path, alias) and path.stat().st_nlink == 2
    assert load_map(alias).is_blocked((0, 1))


# -- would not load, any other refusal ----------------------------------------------------


@sync
async def test_a_map_that_would_not_load_is_not_written(tmp_path: Path) -> None:
    """``--goal 0,0`` on the tutorial (start = goal): ctrl+s says why in one line, save-as
    keeps its prompt open with it; nothing is written, nothing lost."""
    path = copy(TUTORIAL, tmp_path)
    before = path.read_bytes()
    app = SearchApp(load_map(path, goal=(0, 0)), path=path)
    async with app.run_test(size=SIZE) as pilot:
        await edit(pilot, app)
        await pilot.press("ctrl+s")
        await wait_until(pilot, lambda: any(n.title == "Not saved" for n in notifications(app)))
        (note,) = [n for n in notifications(app) if n.title == "Not saved"]
        assert "cannot save: the file would not open again" in note.message
        assert "\n" not in note.message and app.screen is app.main
        await pilot.press("w")
        await type_name(pilot, str(tmp_path / "new.txt"))
        assert isinstance(app.screen, SaveAsScreen)
        assert "cannot save: the file would not open again" in app.screen.error
        assert app.session.dirty and sorted(os.listdir(tmp_path)) == ["tutorial.txt"]
    assert path.read_bytes() == before


@sync
async def test_any_other_refusal_is_one_line_and_keeps_the_prompt(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def refuse(*args: object, **kwargs: object) -> None:
        raise MapError("x\x1b[2J.txt", "cannot save: no\nreason [/]")

    monkeypatch.setattr("tui_search.tui.screens.file_commands.save_map", refuse)
    app = app_on(copy(TUTORIAL, tmp_path))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("w")
        await type_name(pilot, str(tmp_path / "b.txt"))
        assert isinstance(app.screen, SaveAsScreen)
        assert app.screen.error == "x\\x1b[2J.txt: cannot save: no\\nreason [/]"


@sync
async def test_opening_a_fifo_says_not_a_regular_file(tmp_path: Path) -> None:
    """ctrl+o on a FIFO: one line in the prompt, no hang (and the picker does not list it)."""
    fifo = tmp_path / "pipe.txt"
    os.mkfifo(fifo)
    app = app_on(copy(TUTORIAL, tmp_path))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+o")
        await type_name(pilot, str(fifo))
        assert app.screen.error == f"{fifo}: not a regular file"


@sync
async def test_reload_reads_the_map_with_the_terrain_table_it_was_opened_with(
        tmp_path: Path) -> None:
    from tui_search.engine.maps.terrain import parse_terrain

    path = tmp_path / "swamp.txt"
    path.write_text("S.f\n..G\n")
    app = SearchApp(load_map(path, terrain=parse_terrain("f 5")), path=path)
    async with app.run_test(size=SIZE) as pilot:
        path.write_text("S.f\nf.G\n")  # someone adds a second f
        await pilot.press("ctrl+s")
        await answer(pilot, ChangedOnDiskScreen, "r")
        await wait_until(pilot, lambda: app.session.grid.costs is not None
                         and app.session.grid.costs[3] == 5.0)
        assert not [n for n in notifications(app) if "Not reloaded" in str(n.title)]

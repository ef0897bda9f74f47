"""Undo and redo driven by Pilot: ctrl+z and ctrl+y on the tutorial map, the title's
"modified", the key bar's hints, a mouse stroke as one edit, and a save as the clean point."""

from __future__ import annotations

import shutil
from pathlib import Path

from textual.app import App
from textual.binding import Binding

from tests.tui.test_app import SIZE, TUTORIAL, at, sync, tutorial_app, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar


def undo_keys(app: SearchApp) -> dict[str, bool]:
    """The key bar's undo and redo keys, each with whether it can act (absent: hidden)."""
    bar = app.query_one(KeyBar)
    return {key: on for keys, _, _ in bar.hints() for _, key, on in keys
            if key in ("ctrl+z", "ctrl+y")}


def test_textual_binds_neither_ctrl_z_nor_ctrl_y_on_the_app() -> None:
    """ctrl+z reaches the screen's undo (Textual 8 does not bind it to suspending the
    process, and its driver turns the terminal's signal keys off)."""
    keys = {b.key for b in Binding.make_bindings(App.BINDINGS)}
    assert not keys & {"ctrl+z", "ctrl+y"}


@sync
async def test_ctrl_z_and_ctrl_y_undo_and_redo_an_obstacle_and_the_title_follows() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        assert undo_keys(app) == {}  # nothing edited: no undo hint
        await pilot.press("down", "down", "right", "o")  # (1,2): an obstacle
        assert app.session.grid.is_blocked((1, 2)) and "modified" in view.border_title
        await wait_until(pilot, lambda: undo_keys(app) == {"ctrl+z": True, "ctrl+y": False})
        # keys of two characters each, set apart (issue 42: they read "^z^y")
        assert "^z/^y Undo/Redo" in app.query_one(KeyBar).render_line(0).text
        await pilot.press("n", "n", "home", "ctrl+z")
        assert not app.session.grid.is_blocked((1, 2)) and not app.session.dirty
        assert app.session.run.k == 0 and not app.session.run.grid.is_blocked((1, 2))
        await wait_until(pilot, lambda: "modified" not in view.border_title)
        await wait_until(pilot, lambda: undo_keys(app) == {"ctrl+z": False, "ctrl+y": True})
        await pilot.press("ctrl+y")
        assert app.session.grid.is_blocked((1, 2)) and app.session.cursor == (1, 2)
        await wait_until(pilot, lambda: "modified" in view.border_title)
        await pilot.press("ctrl+z", "ctrl+z")  # the second has nothing to undo
        assert app.session.grid == load_map(TUTORIAL) and not app.session.dirty


@sync
async def test_undo_puts_back_a_moved_goal_and_the_cursor_on_it() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        app.session.cursor = (5, 1)
        await pilot.press("g", "left", "left", "ctrl+z")
        assert app.session.grid.goal == (5, 2) and app.session.cursor == (5, 2)
        assert app.query_one(GridView).cursor == (5, 2) and not app.session.dirty


@sync
async def test_a_mouse_stroke_is_one_edit() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()  # laid out: the cells have their size
        view = app.query_one(GridView)
        # Row 4 of the tutorial: (0,4) free, (1,4) free, (2,4) free ... painted as obstacles.
        assert not any(app.session.grid.is_blocked((x, 4)) for x in range(3))
        await pilot.mouse_down(GridView, offset=at(view, 0, 4))
        for x in (1, 2):
            await pilot.hover(GridView, offset=at(view, x, 4))
        await pilot.mouse_up(GridView, offset=at(view, 2, 4))
        await wait_until(pilot, lambda: all(app.session.grid.is_blocked((x, 4))
                                            for x in range(3)))
        await pilot.press("ctrl+z")
        assert app.session.grid == load_map(TUTORIAL) and not app.session.dirty
        await pilot.press("ctrl+y")
        assert all(app.session.grid.is_blocked((x, 4)) for x in range(3))


@sync
async def test_a_save_is_the_point_undo_compares_with(tmp_path: Path) -> None:
    path = tmp_path / "tutorial.txt"
    shutil.copy(TUTORIAL, path)
    app = SearchApp(load_map(path), path=path)
    async with app.run_test(size=SIZE) as pilot:
        app.session.cursor = (1, 2)
        await pilot.press("o", "ctrl+s")
        await wait_until(pilot, lambda: not app.session.dirty)
        await pilot.press("ctrl+z")
        assert app.session.dirty and "modified" in app.query_one(GridView).border_title
        await pilot.press("ctrl+y")
        assert not app.session.dirty

"""A Pacman layout in the app: the first of several dots is the goal and the status line says
so, the cell readout gives the course's (x, y) beside the app's, and the settings screen's
CS188 button sets the course's choices, each still changeable before Apply."""

from __future__ import annotations

from pathlib import Path

from tests.tui.test_app import click_shown, screen_shown, stats, sync, wait_until
from tests.tui.test_cells import readout
from tui_search.engine.course.presets import preset_semantics
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.registry import get_algorithm
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.settings import SettingsScreen

ROOT = Path(__file__).resolve().parents[2]
THREE = ROOT / "examples" / "cs188_style" / "layouts" / "threeDots.lay"
SIZE = (100, 32)


def layout_app() -> SearchApp:
    return SearchApp(load_map(THREE), path=THREE, algorithm="bfs")


@sync
async def test_the_app_says_which_dot_is_the_goal_and_the_courses_cells() -> None:
    app = layout_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        note = "3 dots: the goal is the first, (8,1) (the course's (8,3))"
        assert app.session.note == note
        await wait_until(pilot, lambda: note in " ".join(stats(app)))
        assert readout(app).startswith("Cursor (1,3) course (1,1): the start")
        await pilot.press("up", "up")
        assert readout(app) == "Cursor (1,1) course (1,3): never reached"  # the capsule


@sync
async def test_the_cs188_button_sets_the_courses_choices_and_each_can_change() -> None:
    app = layout_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        await click_shown(pilot, "#preset-cs188")
        await wait_until(pilot, lambda: screen.query_one("#order").value == "N,S,E,W")
        assert screen.chosen() == preset_semantics("cs188", get_algorithm("bfs"))
        screen.query_one("#goal_test-generate").value = True  # changed after the preset
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        sem = app.session.semantics
        assert sem.order == ("N", "S", "E", "W") and sem.visit == "expand"
        assert sem.goal_test_for(get_algorithm("bfs")) == "generate"

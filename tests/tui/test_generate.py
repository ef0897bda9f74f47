"""``ctrl+n`` (and the palette's "Generate a map"): a generated map replaces the current one,
untitled, after asking when there are unsaved edits; the prompt suggests the next seed and
keeps a bad recipe open with the reason."""

from __future__ import annotations

import threading
from pathlib import Path

import pytest
from textual.widgets import Input

from tests.tui.test_app import MAPS, SIZE, screen_shown, stats, sync, wait_until
from tests.tui.test_dialogs_fit import assert_fits
from tests.tui.test_files import answer, copy
from tui_search.engine.maps.generate import Recipe, generate, make_recipe
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.commands import SearchCommands
from tui_search.tui.dialogs.confirm_quit import ConfirmQuitScreen
from tui_search.tui.dialogs.generate_map import GenerateScreen
from tui_search.tui.screens.file_commands import GENERATE_AT_ONCE_CELLS

TUTORIAL = MAPS / "tutorial.txt"


async def generate_with(pilot, typed: str | None = None) -> tuple[GenerateScreen, str]:
    """Press ctrl+n, type ``typed`` (None: keep the suggestion) and enter; back once the prompt
    has answered (closed, or an error shown), with the prompt and what it suggested."""
    await pilot.press("ctrl+n")
    prompt = await screen_shown(pilot, GenerateScreen)
    suggested = prompt.query_one(Input).value
    if typed is not None:
        prompt.query_one(Input).value = typed
        await wait_until(pilot, lambda: prompt.query_one(Input).value == typed)
    await pilot.press("enter")
    await wait_until(pilot, lambda: pilot.app.screen is not prompt or bool(prompt.error))
    await pilot.pause()
    return prompt, suggested


@sync
async def test_m_generates_a_map_untitled_and_suggests_the_next_seed() -> None:
    app = SearchApp(load_map(TUTORIAL))
    async with app.run_test(size=SIZE) as pilot:
        _, suggested = await generate_with(pilot)
        assert suggested == "maze 21x15 1"
        session = app.session
        assert session.grid == generate(make_recipe("maze", "21x15", "1"))
        assert session.title == "maze 21x15 seed 1" and session.map_path is None
        assert session.run is not None and session.run.k == 0
        assert app.main.views[0].grid is session.grid
        _, suggested = await generate_with(pilot)
        assert suggested == "maze 21x15 2"
        assert session.title == "maze 21x15 seed 2"


@sync
async def test_a_bad_recipe_keeps_the_prompt_open_with_the_reason() -> None:
    app = SearchApp(load_map(TUTORIAL))
    async with app.run_test(size=SIZE) as pilot:
        prompt, _ = await generate_with(pilot, "maze 2x2 1")
        assert app.screen is prompt
        assert prompt.error == "size 2x2: maze needs at least 3x3"
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is not prompt)
        assert app.session.grid == load_map(TUTORIAL)


@sync
async def test_generating_over_unsaved_edits_asks_first(tmp_path: Path) -> None:
    path = copy(TUTORIAL, tmp_path)
    app = SearchApp(load_map(path), path=path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("down", "o")
        await wait_until(pilot, lambda: app.session.dirty)
        await generate_with(pilot, "random:30 12x8 alice")
        question = await screen_shown(pilot, ConfirmQuitScreen)
        assert "Generate random:30 12x8 seed alice anyway?" in str(
            question.query_one("Label").content)
        await answer(pilot, ConfirmQuitScreen, "n")  # cancel: the edit stays
        assert app.session.map_path == path and app.session.dirty
        await generate_with(pilot, "random:30 12x8 alice")
        await answer(pilot, ConfirmQuitScreen, "y")  # discard the edit
        await wait_until(pilot, lambda: app.session.map_path is None)
        assert app.session.grid == generate(make_recipe("random:30", "12x8", "alice"))
        assert not app.session.dirty and app.session.title == "random:30 12x8 seed alice"
    assert path.read_bytes() == TUTORIAL.read_bytes()


@sync
async def test_the_palette_offers_it_with_its_key() -> None:
    app = SearchApp(load_map(TUTORIAL))
    async with app.run_test(size=SIZE) as pilot:
        commands = {name: (run, help_text)
                    for name, run, help_text in SearchCommands(app.screen).commands()}
        name = next(n for n in commands if n.startswith("Generate a map"))
        assert "(key ^n)" in commands[name][1] and "DFS" in commands[name][1]
        await commands[name][0]()  # the main screen's run_action
        await screen_shown(pilot, GenerateScreen)


@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
@sync
async def test_the_prompt_fits_with_an_error_shown(size: tuple[int, int]) -> None:
    app = SearchApp(load_map(TUTORIAL))
    async with app.run_test(size=size) as pilot:
        prompt, _ = await generate_with(pilot, "blob 9x9 1")
        assert prompt.error.startswith("unknown kind 'blob'")
        await assert_fits(pilot, GenerateScreen)
        field = prompt.query_one(Input).region
        assert app.screen.region.intersection(field) == field and field.area


def gated(monkeypatch: pytest.MonkeyPatch) -> threading.Event:
    """The app's generator held until the returned event is set (a big map's thread).  The
    app imports it when a map is generated, so the engine's module is the one patched."""
    import tui_search.engine.maps.generate

    gate = threading.Event()

    def held(recipe: Recipe) -> Grid:
        assert gate.wait(10), "the test never let the generator go"
        return generate(recipe)

    monkeypatch.setattr(tui_search.engine.maps.generate, "generate", held)
    return gate


@sync
async def test_a_big_map_is_generated_in_a_thread_the_app_going_on(monkeypatch) -> None:
    """kruskal 999x999 takes ~5 s: above GENERATE_AT_ONCE_CELLS the status line says
    "Generating ...", keys still work, and the map is shown once made."""
    gate = gated(monkeypatch)
    side = int(GENERATE_AT_ONCE_CELLS ** 0.5) + 2  # just over: quick to make once let go
    app = SearchApp(load_map(TUTORIAL))
    async with app.run_test(size=SIZE) as pilot:
        await generate_with(pilot, f"kruskal {side}x{side} 4")
        note = f"Generating kruskal {side}x{side} seed 4…"
        await wait_until(pilot, lambda: note in stats(app)[1])
        assert app.session.grid == load_map(TUTORIAL)
        await pilot.press("n")  # the app answers meanwhile
        await wait_until(pilot, lambda: app.session.run is not None and app.session.run.k == 1)
        await wait_until(pilot, lambda: note in stats(app)[1])  # still said
        gate.set()
        await wait_until(pilot, lambda: app.session.title == f"kruskal {side}x{side} seed 4")
        assert app.session.grid == generate(make_recipe("kruskal", f"{side}x{side}", "4"))
        assert app.main.views[0].grid is app.session.grid and app.session.map_path is None
        assert "Generating" not in stats(app)[1]


@sync
async def test_an_edit_while_a_big_map_is_made_is_asked_about(monkeypatch) -> None:
    gate = gated(monkeypatch)
    app = SearchApp(load_map(TUTORIAL))
    async with app.run_test(size=SIZE) as pilot:
        await generate_with(pilot, "maze 401x401 1")
        await pilot.press("down", "o")
        await wait_until(pilot, lambda: app.session.dirty)
        gate.set()
        await answer(pilot, ConfirmQuitScreen, "n")  # keep the edit: no generated map
        assert app.session.grid != load_map(TUTORIAL) and app.session.dirty
        assert app.session.grid.width == load_map(TUTORIAL).width

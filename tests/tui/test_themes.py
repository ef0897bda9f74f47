"""Themes and the command palette, driven by Pilot: a theme chosen by key or in the palette
recolours every widget and is remembered in the config file (each test has its own config
directory: tests/conftest.py sets ``TUI_SEARCH_CONFIG_DIR``); a corrupt or unreachable config
file is said once and the defaults are used; the palette runs the app's commands."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest
from rich.color import Color
from textual.command import CommandList, CommandPalette

from tests.textual_internals import notifications, repainted
from tests.tui.test_app import SIZE, TUTORIAL, sync, tutorial_app, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.registry import ALGORITHMS, BIDIRECTIONAL
from tui_search.tui import config as config_module
from tui_search.tui.app import SearchApp
from tui_search.tui.config import CONFIG_DIR_ENV, Config, config_path
from tui_search.tui.view.themes import DEFAULT_THEME, THEMES
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.stats import Stats


def config_file() -> Path:
    return Path(os.environ[CONFIG_DIR_ENV]) / "config.json"


def start_colour(app: SearchApp) -> Color | None:
    return app.query_one(GridView).get_component_rich_style("grid-view--start").bgcolor


def config_notes(app: SearchApp) -> list[str]:
    return [n.message for n in notifications(app) if n.title == "Config file"]


async def hits(pilot) -> CommandList:
    """The palette's list once its search (in a worker) has answered."""
    found = pilot.app.screen.query_one(CommandList)
    await wait_until(pilot, lambda: bool(found.option_count) and found.highlighted is not None)
    await pilot.pause()
    return found


async def palette_run(pilot, query: str, best: bool = False) -> None:
    """Open the palette, type ``query`` (which names one command), take what it found
    (``best``: the query matches others too, fuzzily; the command it names comes first)."""
    await pilot.press("ctrl+p")
    await pilot.pause()
    palette = pilot.app.screen
    assert isinstance(palette, CommandPalette)
    await pilot.press(*query)
    found = await hits(pilot)
    prompts = [str(o.prompt) for o in found.options]
    if best:
        assert found.highlighted == 0 and prompts[0].lower().startswith(query.lower()), prompts
    else:
        assert found.option_count == 1, prompts
    await pilot.press("enter")
    await pilot.pause()


def test_the_config_dir_is_the_tests_own() -> None:
    assert config_path() == config_file()
    assert "pytest" in str(config_file()) or "tmp" in str(config_file())


def test_without_the_variable_the_file_is_in_the_users_config_dir(tmp_path: Path,
                                                                    monkeypatch) -> None:
    """What a user gets: platformdirs' user config directory for "tui-search", which on Linux
    is docs/01-keys.md's ``~/.config/tui-search/`` (or ``$XDG_CONFIG_HOME/tui-search/``); a theme
    chosen is saved there."""
    import platformdirs

    monkeypatch.delenv(CONFIG_DIR_ENV)
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "xdg"))
    expected = Path(platformdirs.user_config_dir("tui-search", appauthor=False)) / "config.json"
    assert config_path() == expected and expected.is_relative_to(tmp_path)
    if sys.platform.startswith("linux"):
        assert expected == tmp_path / "xdg" / "tui-search" / "config.json"
        monkeypatch.delenv("XDG_CONFIG_HOME")
        assert config_path() == tmp_path / ".config" / "tui-search" / "config.json"
    assert Config.load().save_theme("light") is None
    assert json.loads(config_path().read_text()) == {"theme": "light"}
    assert Config.load().theme == "light"


def test_only_the_apps_themes_are_offered() -> None:
    app = tutorial_app()
    assert set(app.available_themes) == set(THEMES)
    assert app.theme == DEFAULT_THEME


@sync
async def test_t_cycles_the_themes_and_recolours_the_map() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        seen = [(app.theme, start_colour(app))]
        for _ in THEMES:
            await pilot.press("t")
            await pilot.pause()
            seen.append((app.theme, start_colour(app)))
        assert [name for name, _ in seen] == [*THEMES, DEFAULT_THEME]
        assert len({colour for _, colour in seen}) == len(THEMES)  # each its own start colour
        assert seen[0] == seen[-1]


@sync
async def test_a_theme_command_in_the_palette_switches_and_is_remembered() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await palette_run(pilot, "theme light")
        assert app.theme == "light"
        assert not isinstance(app.screen, CommandPalette)
        assert app.query_one(Stats).rich_style.bgcolor != Color.parse("#000000")
    assert json.loads(config_file().read_text("utf-8")) == {"theme": "light"}


@sync
async def test_textuals_theme_picker_offers_the_apps_themes_and_remembers_too() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        app.action_change_theme()  # what the palette's own "Theme" command does
        await pilot.pause()
        await pilot.press(*"colour")
        found = await hits(pilot)
        assert [str(o.prompt) for o in found.options] == ["colour-blind"]
        await pilot.press("enter")
        await pilot.pause()
        assert app.theme == "colour-blind"
    assert json.loads(config_file().read_text("utf-8")) == {"theme": "colour-blind"}


@pytest.mark.parametrize("name", [n for n in THEMES if n != DEFAULT_THEME])
@sync
async def test_switching_draws_what_starting_in_the_theme_draws(name) -> None:
    """Nothing keeps the old theme's colours (the map and the panels cache their styles), and
    an app started in a theme is styled by it from the first frame."""
    drawn = []
    for app, switch in ((tutorial_app(), True),
                        (SearchApp(load_map(TUTORIAL), path=TUTORIAL, theme=name), False)):
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press("n", "n")
            if switch:
                app.theme = name
            await pilot.pause()
            assert app.theme == name
            drawn.append(await repainted(pilot))
    assert drawn[0] == drawn[1]


@sync
async def test_the_theme_persists_across_two_runs() -> None:
    first = tutorial_app()
    async with first.run_test(size=SIZE) as pilot:
        await pilot.press("t", "t")  # dark -> light -> colour-blind
        await pilot.pause()
    assert first.theme == "colour-blind"
    second = tutorial_app()
    assert second.theme == "colour-blind"
    async with second.run_test(size=SIZE):
        assert start_colour(second) == Color.parse(THEMES["colour-blind"].variables["map-start"])
        assert config_notes(second) == []


@sync
async def test_theme_flag_is_for_one_run_and_not_remembered() -> None:
    config_file().write_text('{"theme": "colour-blind", "other": [1, 2]}\n', "utf-8")
    app = SearchApp(load_map(TUTORIAL), theme="light")
    async with app.run_test(size=SIZE) as pilot:
        assert app.theme == "light"
        await pilot.pause()
    assert json.loads(config_file().read_text("utf-8"))["theme"] == "colour-blind"
    assert tutorial_app().theme == "colour-blind"


@sync
async def test_saving_the_theme_keeps_the_files_other_keys() -> None:
    config_file().write_text('{"other": {"kept": true}, "theme": "dark"}', "utf-8")
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("t")
        await pilot.pause()
    assert json.loads(config_file().read_text("utf-8")) == {"other": {"kept": True},
                                                             "theme": "light"}


@sync
async def test_a_corrupt_config_file_says_so_once_and_uses_the_defaults() -> None:
    broken = '{"theme": "light",\n  oops }\n'
    config_file().write_text(broken, "utf-8")
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert app.theme == DEFAULT_THEME
        notes = config_notes(app)
        assert len(notes) == 1
        assert notes[0].startswith(f"{config_file()}:2:3: not valid JSON")
        assert "using the defaults" in notes[0]
        await pilot.press("t")  # a choice still works, and is not said again
        await pilot.pause()
        assert app.theme == "light"
        assert len(config_notes(app)) == 1
    assert config_file().read_text("utf-8") == broken  # never written over


@pytest.mark.parametrize("content, why", [
    ('["theme", "light"]', "not a JSON object"),
    (b'{"theme": "\xff"}', "not UTF-8 text"),
    ('{"theme": "neon"}', "unknown theme 'neon' (use dark, light, colour-blind)"),
])
def test_config_problems_are_one_line_and_fall_back(content, why) -> None:
    path = config_file()
    path.write_bytes(content if isinstance(content, bytes) else content.encode())
    config = Config.load()
    assert config.theme is None
    assert config.problem is not None and "\n" not in config.problem
    assert config.problem.startswith(f"{path}: {why}")


def test_an_unknown_theme_is_replaced_by_the_next_choice() -> None:
    config_file().write_text('{"theme": "neon", "x": 1}', "utf-8")
    config = Config.load()
    assert config.save_theme("light") is None
    assert json.loads(config_file().read_text("utf-8")) == {"theme": "light", "x": 1}


@sync
async def test_a_config_dir_that_cannot_exist_never_stops_the_app(tmp_path, monkeypatch) -> None:
    """The config directory's path runs through a file: nothing can be read or written."""
    (tmp_path / "a-file").write_text("")
    monkeypatch.setenv(CONFIG_DIR_ENV, str(tmp_path / "a-file" / "tui-search"))
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert app.theme == DEFAULT_THEME
        await pilot.press("t", "t")
        await pilot.pause()
        assert app.theme == "colour-blind"
        assert len(config_notes(app)) == 1
        assert "not a directory" in config_notes(app)[0]


@sync
async def test_an_unwritable_config_dir_says_so_once(monkeypatch) -> None:
    def refuse(target: str, data: bytes) -> None:
        raise PermissionError(13, "Permission denied", target)

    monkeypatch.setattr(config_module, "write_atomically", refuse)
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("t", "t", "t")
        await pilot.pause()
        assert app.theme == DEFAULT_THEME and app.is_running
        assert config_notes(app) == [f"{config_file()}: cannot save the theme: permission denied"]


@sync
async def test_the_palette_picks_each_algorithm_of_the_registry() -> None:
    """Each search, the bidirectional ones (which have no key) too."""
    app = tutorial_app()
    everyone = [*ALGORITHMS.values(), *BIDIRECTIONAL.values()]
    async with app.run_test(size=SIZE) as pilot:
        for algorithm in reversed(everyone):
            # "Iterative deepening" is in "Iterative deepening A*" too, "Uniform-cost search"
            # in "Bidirectional uniform-cost search": it comes first
            longer = any(algorithm.name.lower() in other.name.lower() and other is not algorithm
                         for other in everyone)
            await palette_run(pilot, f"algorithm: {algorithm.name}", best=longer)
            assert app.session.algorithm == algorithm.key
            assert app.session.run is not None and app.session.run.algorithm == algorithm.key


@sync
async def test_the_palette_runs_the_apps_actions() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await palette_run(pilot, "overview")
        assert app.query_one(GridView).overview
        await palette_run(pilot, "search settings")
        assert type(app.screen).__name__ == "SettingsScreen"
        await pilot.press("escape")
        await palette_run(pilot, "help: keys, colours")
        assert type(app.screen).__name__ == "HelpScreen"


@sync
async def test_the_palette_lists_the_apps_commands_beside_textuals() -> None:
    from tui_search.tui.commands import SearchCommands

    app = tutorial_app()
    async with app.run_test(size=SIZE):
        names = [name for name, _, _ in SearchCommands(app.screen).commands()]
    assert [n for n in names if n.startswith("Algorithm: ")] == [
        f"Algorithm: {a.name}" for a in (*ALGORITHMS.values(), *BIDIRECTIONAL.values())]
    assert "Algorithm: Bidirectional A*" in names  # after the one-way searches
    assert [n for n in names if n.startswith("Theme: ")] == [
        f"Theme: {t.title}" for t in THEMES.values()]
    assert {"Search settings", "Save the map", "Save the map as…", "Open a map…",
            "Overview: the whole map"} <= set(names)
    assert any(p.__name__ == "SystemCommandsProvider"
               for p in (c() if not isinstance(c, type) else c for c in SearchApp.COMMANDS))


# -- colour-blind safety: the map's colours as protanopes and deuteranopes see them ----------
#: Viénot, Brettel and Mollon (1999): full protanopia and deuteranopia in linear RGB.
PROTAN = ((0.152286, 1.052583, -0.204868), (0.114503, 0.786281, 0.099216),
          (-0.003882, -0.048116, 1.051998))
DEUTAN = ((0.367322, 0.860646, -0.227968), (0.280085, 0.672501, 0.047413),
          (-0.011820, 0.042940, 0.968881))
NORMAL = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
#: The least CIE76 colour difference between two kinds of cell, in any of the three visions.
SAFE_DIFFERENCE = 30


def seen(colour: Color, vision) -> tuple[float, float, float]:
    """``colour`` in CIE L*a*b* as seen with ``vision`` (a matrix on linear RGB)."""
    def linear(c: int) -> float:
        c /= 255
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4

    rgb = [linear(c) for c in colour.get_truecolor()]
    r, g, b = (max(0.0, min(1.0, sum(m * c for m, c in zip(row, rgb, strict=True))))
               for row in vision)
    x, y, z = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.9505, \
        0.2126 * r + 0.7152 * g + 0.0722 * b, (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.089

    def f(t: float) -> float:
        return t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116

    return 116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))


async def least_difference(theme: str, of: str | None = None) -> tuple[float, str]:
    """The two kinds of cell whose fills (an obstacle's glyph colour) are closest, as drawn
    by the running app in ``theme``, in normal, protanopic or deuteranopic vision (``of``:
    only the pairs with that kind, e.g. ``"marked"`` against every kind and a free cell)."""
    import itertools
    import math

    app = SearchApp(load_map(TUTORIAL), theme=theme)
    async with app.run_test(size=SIZE):
        view = app.query_one(GridView)
        fills = {}
        for kind in ("wall", "start", "goal", "frontier", "expanded", "current", "path"):
            style = view.get_component_rich_style(f"grid-view--{kind}")
            fills[kind] = style.color if kind == "wall" else style.bgcolor
        if of is not None:
            fills["free"] = view.rich_style.bgcolor
            fills[of] = view.get_component_rich_style(f"grid-view--{of}").bgcolor
    return min((math.dist(seen(a, v), seen(b, v)), f"{ka}/{kb} {name}")
               for name, v in (("normal", NORMAL), ("protan", PROTAN), ("deutan", DEUTAN))
               for (ka, a), (kb, b) in itertools.combinations(fills.items(), 2)
               if of is None or of in (ka, kb))


@sync
async def test_the_colour_blind_theme_keeps_every_kind_of_cell_apart() -> None:
    difference, pair = await least_difference("colour-blind")
    assert difference >= SAFE_DIFFERENCE, pair


@sync
async def test_the_default_theme_is_what_the_colour_blind_check_catches() -> None:
    """The check can fail: in the default theme a deuteranope sees the red obstacles and the
    green path nearly alike."""
    difference, pair = await least_difference(DEFAULT_THEME)
    assert difference < SAFE_DIFFERENCE and pair == "wall/path deutan"


@pytest.mark.parametrize("name", list(THEMES))
@sync
async def test_a_replays_mark_stands_apart_from_every_kind_of_cell(name) -> None:
    """The first difference of a replay is filled with a colour of its own, far from every
    state's, the obstacles' and a free cell's in every theme and vision: it cannot hide on
    the light blue of the cell being expanded, nor pass for an obstacle."""
    difference, pair = await least_difference(name, of="marked")
    assert difference >= SAFE_DIFFERENCE, pair

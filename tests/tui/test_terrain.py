"""Terrain in the app, driven by Pilot: costs drawn on the map (the ramp, the digits) and in
the legend, the terrain brush (b picks, m or a mouse drag paints, undo takes a stroke back, a
save writes the digits and keeps every other line), the narration, the readout and the
comparison with costs, and the ramp in every theme and vision."""

from __future__ import annotations

import itertools
import math
import shutil
from pathlib import Path

import pytest

from tests.tui.test_app import MAPS, SIZE, at, sync, wait_until
from tests.tui.test_themes import DEUTAN, NORMAL, PROTAN, palette_run, seen
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import DEFAULT_SEMANTICS
from tui_search.tui.app import SearchApp
from tui_search.tui.model.map_edits import BRUSHES
from tui_search.tui.model.session import Session
from tui_search.tui.view.cell_codes import GOAL, START, WALL
from tui_search.tui.view.geometry import Geometry
from tui_search.tui.view.narration import narrate
from tui_search.tui.view.readout import describe
from tui_search.tui.view.themes import THEMES
from tui_search.tui.widgets.cell_style import RAMP_COMPONENTS, cost_level, cost_mark
from tui_search.tui.widgets.compare_table import CompareTable
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar
from tui_search.tui.widgets.legend import Legend
from tui_search.tui.widgets.map_lines import block_swatches

MUD = MAPS / "terrain-mud.txt"


def mud_app(path: Path = MUD, **kwargs) -> SearchApp:
    return SearchApp(load_map(path), path=path, **kwargs)


def brush_hint(app: SearchApp) -> str | None:
    """The key bar's hint for m (None: not shown)."""
    return next((d for keys, d, _ in app.query_one(KeyBar).hints()
                 for _, key, _ in keys if key == "m"), None)


# -- what costs look like ---------------------------------------------------------------------
def test_the_ramp_steps_and_the_digit_beside_a_glyph() -> None:
    assert [cost_level(c) for c in (0.5, 1, 1.5, 2, 3, 4, 5, 7, 8, 9, 99)] == [
        0, 0, 1, 1, 1, 2, 2, 3, 4, 4, 4]
    assert [cost_mark(c) for c in (1.0, 2.0, 9.0, 0.5, 12.0)] == [" ", "2", "9", " ", " "]


@sync
async def test_the_mud_is_shaded_and_carries_its_cost_and_the_legend_shows_the_ramp() -> None:
    app = mud_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        view = app.query_one(GridView)
        rows = [view.render_line(y) for y in range(view.geometry.size[1])]
        mud = view.get_component_rich_style("grid-view--cost-4").bgcolor
        # The mud (cost 9, the ramp's last step) is shaded, and its cells say 9.
        assert mud is not None and any(
            seg.style is not None and seg.style.bgcolor == mud for row in rows for seg in row)
        assert "9" in "".join(row.text for row in rows)
        legend = app.query_one(Legend).render().plain
        assert "2-3" in legend and "8+" in legend and "cost" in legend
    plain = SearchApp(load_map(MAPS / "tutorial.txt"))
    async with plain.run_test(size=SIZE):
        assert "8+" not in plain.query_one(Legend).render().plain  # no terrain: no ramp


@sync
async def test_the_ramp_reads_in_every_theme_and_vision() -> None:
    """Each step of the ramp stands further from the map's background in lightness (L*) than
    the one before, in normal, protanopic and deuteranopic vision: a lightness ramp, which
    colour-vision deficiencies keep."""
    for theme in THEMES:
        app = mud_app(theme=theme)
        async with app.run_test(size=SIZE):
            view = app.query_one(GridView)
            background = view.rich_style.bgcolor
            steps = [view.get_component_rich_style(f"grid-view--{c}").bgcolor
                     for c in RAMP_COMPONENTS]
        assert background is not None and all(steps)
        for vision in (NORMAL, PROTAN, DEUTAN):
            base = seen(background, vision)[0]
            distances = [abs(seen(s, vision)[0] - base) for s in steps if s is not None]
            assert all(b - a >= 7 for a, b in itertools.pairwise(distances)), (theme, distances)


@sync
async def test_the_overview_shades_a_free_block_by_its_dearest_cell() -> None:
    """z on a map with terrain: a free block takes the ramp's colour of the dearest cell in it
    (one 9 among 1s: the last step; a 3 among 2s: the first); an obstacle's block still draws
    the obstacle, the start's and the goal's theirs.  On the mud map, z shows the mud."""
    grid = Grid(25, 5, start=(0, 0), goal=(24, 4))
    grid.set_cost((7, 3), 9.0)
    for x in range(10, 15):
        grid.set_cost((x, 1), 2.0)
    grid.set_cost((12, 4), 3.0)
    grid.set_cost((16, 2), 9.0)
    grid.set_blocked((17, 2), True)
    app = SearchApp(grid)
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        await pilot.press("z")
        await wait_until(pilot, lambda: view.overview)
        view.geometry = Geometry(25, 5, 1, 5)  # the fit would choose 1; blocks of 5 here
        ramp = [view.get_component_rich_style(f"grid-view--{c}").bgcolor
                for c in RAMP_COMPONENTS]
        shown = block_swatches(view.grid, view.run, range(5), 0, 25, view.geometry.across)
        assert shown is not None and shown[0] == START and shown[3:] == [WALL, GOAL]
        assert [view.swatch(i).color for i in shown[1:3]] == [ramp[3], ramp[0]]
        line = view.render_line(0)  # the blocks' upper halves (the cursor's is the start's)
        colours = [seg.style.color for seg in line if seg.style
                   for _ in range(seg.cell_length)][view.pad_x:]
        assert colours[1:3] == [ramp[3], ramp[0]]
    app = mud_app()
    async with app.run_test(size=SIZE) as pilot:
        view = app.query_one(GridView)
        await pilot.press("z")
        await wait_until(pilot, lambda: view.overview)
        mud = view.get_component_rich_style("grid-view--cost-4").bgcolor
        segments = [seg for y in range(view.geometry.size[1]) for seg in view.render_line(y)]
        assert mud is not None and any(
            seg.style is not None and mud in (seg.style.color, seg.style.bgcolor)
            for seg in segments)


# -- the brush --------------------------------------------------------------------------------
@sync
async def test_b_picks_a_cost_the_key_bar_says_it_and_m_paints_it_and_undo_takes_it_back(
) -> None:
    app = mud_app()
    async with app.run_test(size=SIZE) as pilot:
        session = app.session
        assert brush_hint(app) is None  # no brush: no paint hint
        await pilot.press("b")
        assert session.edits.brush == BRUSHES[0]
        await wait_until(pilot, lambda: brush_hint(app) == "Paint cost 2")
        await pilot.press("b", "b")
        await wait_until(pilot, lambda: brush_hint(app) == "Paint cost 5")
        session.cursor = (0, 5)
        await pilot.press("m")
        assert session.grid.cost((0, 5)) == 5.0 and session.dirty and session.run.k == 0
        await pilot.press("ctrl+z")
        assert session.grid == load_map(MUD) and not session.dirty
        await pilot.press("ctrl+y")
        assert session.grid.cost((0, 5)) == 5.0
        for _ in range(len(BRUSHES) - 2):
            await pilot.press("b")
        assert session.edits.brush is None
        await wait_until(pilot, lambda: brush_hint(app) is None)


@sync
async def test_the_palette_picks_the_brush() -> None:
    app = mud_app()
    async with app.run_test(size=SIZE) as pilot:
        await palette_run(pilot, "Terrain brush: cost 9")
        assert app.session.edits.brush == 9.0
        await palette_run(pilot, "Terrain brush: off")
        assert app.session.edits.brush is None


@sync
async def test_a_drag_paints_a_stroke_that_undo_takes_back_as_one_edit() -> None:
    app = mud_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        view = app.query_one(GridView)
        await pilot.press("b", "b", "b")  # cost 5
        await pilot.mouse_down(GridView, offset=at(view, 0, 5))
        for x in (1, 2, 3):
            await pilot.hover(GridView, offset=at(view, x, 5))
        await pilot.mouse_up(GridView, offset=at(view, 3, 5))
        grid = app.session.grid
        await wait_until(pilot, lambda: all(grid.cost((x, 5)) == 5.0 for x in range(4)))
        assert not any(grid.is_blocked((x, 5)) for x in range(4))  # terrain, not obstacles
        await pilot.press("ctrl+z")  # the whole stroke
        assert app.session.grid == load_map(MUD) and not app.session.dirty


@sync
async def test_a_save_writes_the_painted_digits_and_keeps_every_other_line(tmp_path) -> None:
    path = tmp_path / "mud.txt"
    shutil.copy(MUD, path)
    before = path.read_text().split("\n")
    app = mud_app(path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("b", "b")  # cost 3
        app.session.cursor = (9, 0)
        await pilot.press("m")
        app.session.cursor = (4, 1)  # mud (9) painted 3
        await pilot.press("m", "ctrl+s")
        await wait_until(pilot, lambda: not app.session.dirty)
    after = path.read_text().split("\n")
    changed = [i for i, (a, b) in enumerate(zip(before, after, strict=True)) if a != b]
    assert len(after) == len(before) and changed == [4, 5]  # the two map rows, nothing else
    assert after[4] == ".........3" and after[5] == ".S.m3mm..."
    assert load_map(path).cost((4, 1)) == 3.0


def test_painting_a_cost_lapses_the_benchmarks_optimum_and_undo_brings_it_back() -> None:
    grid = Grid(4, 1, bytearray(4), start=(0, 0), goal=(3, 0))
    session = Session(grid, semantics=DEFAULT_SEMANTICS.replace(corners="never"),
                      optimal_cost=3.0)
    assert session.run.known_lowest == 3.0
    session.edits.brush, session.cursor = 5.0, (1, 0)
    assert session.edits.paint_cost(session.cursor) is None
    assert session.run.known_lowest is None  # the .scen's optimum no longer applies
    session.edits.undo()
    assert session.run.known_lowest == 3.0


def test_the_brush_refuses_an_obstacle_and_undo_of_an_obstacle_keeps_the_terrain() -> None:
    session = Session(load_map(MUD))
    session.edits.brush, session.cursor = 2.0, (3, 1)  # mud
    session.edits.brush = 9.0
    assert session.edits.paint_cost(session.cursor) == "(3,1) already costs 9"
    session.edits.toggle_wall(session.cursor)  # an obstacle on the mud
    assert (session.edits.paint_cost(session.cursor)
            == "Cannot paint terrain on an obstacle at (3,1)")
    session.edits.undo()
    assert session.grid == load_map(MUD)  # the mud is back under it


# -- what the search says of costs ------------------------------------------------------------
def test_the_narration_says_what_the_terrain_adds_to_g() -> None:
    run = Run(load_map(MUD), "ucs")
    said = []
    while run.forward():
        said.append(narrate(run))
    assert any("(3,1) costs 9: g 1.00 → 10.00" in line for line in said), said
    bfs = Run(load_map(MUD), "bfs")
    while bfs.forward():
        assert "costs" not in narrate(bfs)  # BFS ignores costs when choosing


@pytest.mark.parametrize(("algorithm", "expected"), [
    # A*: f's g is the costed g, and each successor's g adds the cost of the cell it enters
    ("astar", [("Expanded (2,2) f = 7.83 (g 1.41 + h 6.41): added SW, S, SE, E, NE; (3,3) "
                "costs 9: g 1.41 → 14.14, (3,2) costs 9: g 1.41 → 10.41, (3,1) costs 9: g 1.41 "
                "→ 14.14"),
               "(3,1) reached with a lower g; (3,1) costs 9: g 1.00 → 10.00"]),
    # greedy chooses by h alone but still says what g the terrain gives (diagonal: 9 x √2)
    ("greedy", [("Expanded (3,3) h = 5.00 (g 14.14): added SW, S, SE, E, NE; (3,4) costs 9: "
                 "g 14.14 → 23.14, (4,4) costs 9: g 14.14 → 26.87, (4,3) costs 9: g 14.14 → "
                 "23.14, 1 more on terrain")]),
])
def test_a_star_and_greedy_narrate_the_terrain_too(algorithm: str, expected: list[str]) -> None:
    run = Run(load_map(MUD), algorithm)
    said = []
    while run.forward():
        said.append(narrate(run))
    for text in expected:
        assert any(text in line for line in said), (text, said)


@pytest.mark.parametrize("algorithm", ["dfs", "iddfs"])
def test_the_uninformed_searches_do_not_narrate_costs(algorithm: str) -> None:
    run = Run(load_map(MUD), algorithm)  # they ignore costs when choosing, as BFS does
    while run.forward():
        assert "costs" not in narrate(run)


def test_the_readout_names_a_cells_cost() -> None:
    grid = load_map(MUD)
    assert describe(None, grid, (4, 2)) == "(4,2) costs 9: free"
    assert describe(None, grid, (0, 0)) == "(0,0): free"


@sync
async def test_the_comparison_says_each_paths_moves_and_cost() -> None:
    app = mud_app(compare="bfs,ucs")
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.press("end")
        table = app.query_one(CompareTable)
        await wait_until(pilot, lambda: any("cost" in line and "UCS" in line
                                            for line in table.text_lines[-1:]))
        assert table.text_lines[-1].endswith(
            "BFS's path has 7 moves, cost 32.11; UCS's 8 moves, cost 9.24")
    assert math.isclose(Run(load_map(MUD), "ucs").outcome().cost or 0, 9.2426, abs_tol=1e-3)


@sync
async def test_start_and_goal_put_on_costed_cells_with_the_keys_keep_their_costs() -> None:
    """The keys, and the cost the narration says; the rule (a move costs the cell it enters,
    the start's own cost is never paid, a start or goal on a digit keeps its cost) and the
    costs of the runs: tests/tui/test_session.py."""
    from tui_search.engine.maps.load import parse_map_text

    grid = parse_map_text("S9.4G\n")
    app = SearchApp(grid, algorithm="ucs")
    async with app.run_test(size=SIZE) as pilot:
        session = app.session
        await pilot.press("right", "s")  # the start on the 9
        await pilot.press("right", "right", "g")  # the goal on the 4
        await wait_until(pilot, lambda: (session.grid.start, session.grid.goal)
                         == ((1, 0), (3, 0)))
        assert (session.grid.cost((1, 0)), session.grid.cost((3, 0))) == (9.0, 4.0)
        await pilot.press("end")
        await wait_until(pilot, lambda: "cost 5.00" in app.main.stats.narration_text)

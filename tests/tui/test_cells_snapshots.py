"""Pictures of the classroom view (issue 12): big cells with their labels, the overview of a
big map, and the line that says what a cell is.  The docstring says what each must show."""

from __future__ import annotations

from tests.helpers import MOVINGAI
from tests.tui.test_app import tutorial_app, wait_until
from tests.tui.test_snapshots import patterned_grid
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp


def overview_after_steps(steps: int):
    """A ``run_before``: the run at step ``steps`` + 1 (panels and status in step), then z."""

    async def run_before(pilot) -> None:
        app = pilot.app
        await pilot.pause()  # the screen mounted
        app.session.run.goto(steps)
        app.main.action_first()  # a full redraw, done in slices: wait for its end ...
        await wait_until(pilot, lambda: app.session.seek is None)
        app.session.run.goto(steps)
        await pilot.press("n", "z")
        await wait_until(pilot, lambda: app.query_one("GridView").overview)

    return run_before


def test_the_tutorial_in_big_cells_with_arrows(snap_compare) -> None:
    """The tutorial's 6x6 map at 160x48, BFS after 6 steps: cells 12x6 characters filling the
    map area; each reached cell has its glyph top left, its depth top right and the arrow of
    the move that reached it in the middle (↓ under the start, ↗ and → further on); obstacles
    solid; the line under the map: 'Cursor (0,0): the start, expanded at step 1, depth 0'."""
    assert snap_compare(tutorial_app(), press=["n"] * 6, terminal_size=(160, 48))


def test_the_overview_of_a_512_map_shows_all_of_it(snap_compare) -> None:
    """A generated 512x512 patterned map at 140x45, BFS part-way (3000 steps), z: every row
    and column in view (no scrollbar), a half block a 7x7 block of cells: the walls' pattern
    red, the searched diamond around the start blue with its frontier edge, S in the middle."""

    grid = patterned_grid(512, 512, start=(256, 256), goal=(2, 2))
    assert snap_compare(SearchApp(grid), terminal_size=(140, 45),
                        run_before=overview_after_steps(3000))


def test_the_overview_of_maze512_shows_the_whole_maze(snap_compare) -> None:
    """The real MovingAI maze512-1-0 (512x512, corridors one cell wide) at 140x45, BFS from
    (251,250) near the middle part-way (20000 steps), z: all 512 columns and rows in 74x37
    characters inside the frame (no scrollbar), a half block a 7x7 block of cells.  Every
    block of the maze holds a wall and an obstacle outranks free, so the unsearched maze is
    solid obstacle colour but for a few all-free blocks on its right and bottom edges; the
    searched part around the start is blue (expanded outranks obstacle) with the cursor (on
    the start) white in it, the goal yellow top left; the panels and the status line agree: step
    20001."""

    grid = load_map(MOVINGAI / "maze512-1-0.map", start=(251, 250), goal=(1, 1))
    assert snap_compare(SearchApp(grid), terminal_size=(140, 45),
                        run_before=overview_after_steps(20000))


def test_the_readout_of_an_expanded_cell(snap_compare) -> None:
    """BFS after 5 steps, the cursor moved down two cells onto (0,2): the line under the map
    reads 'Cursor (0,2): expanded at step 3, depth 2, reached by S from (0,1)', the cursor
    cell drawn reversed."""
    assert snap_compare(tutorial_app(), press=["n"] * 5 + ["down", "down"],
                        terminal_size=(120, 36))

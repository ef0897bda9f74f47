"""The terminal's own cursor sits on the map's cursor cell (Textual issue #2348): a braille
display, and a screen reader's review cursor, follow the terminal's cursor, so the app moves
it there (Textual's public ``App.cursor_position``) whenever the map's cursor moves, the map
scrolls or the focus comes back to it."""

from __future__ import annotations

from textual.geometry import Offset

from tests.tui.test_app import open_grid, sync, tutorial_app, wait_until
from tui_search.tui.app import SearchApp
from tui_search.tui.widgets.grid_view import GridView


def cell_under_terminal_cursor(app: SearchApp) -> tuple[GridView, tuple[int, int] | None]:
    """The map under the terminal's cursor, and its cell there."""
    at = app.cursor_position
    widget, _region = app.screen.get_widget_at(at.x, at.y)
    assert isinstance(widget, GridView), widget
    view = widget.scrollable_content_region
    return widget, widget.cell_at(at.x - view.x, at.y - view.y)


@sync
async def test_the_terminal_cursor_is_on_the_cursor_s_cell_as_it_moves() -> None:
    app = tutorial_app()
    async with app.run_test(size=(100, 32)) as pilot:
        await wait_until(pilot, lambda: app.cursor_position != Offset(0, 0))
        assert cell_under_terminal_cursor(app)[1] == (0, 0)
        for key, cell in (("l", (1, 0)), ("j", (1, 1)), ("j", (1, 2)), ("h", (0, 2))):
            await pilot.press(key)
            await wait_until(pilot, lambda cell=cell: cell_under_terminal_cursor(app)[1] == cell)
        await pilot.press("n", "n")  # a step redraws the map: the cursor stays put
        await pilot.pause()
        assert cell_under_terminal_cursor(app)[1] == (0, 2) == app.session.cursor


@sync
async def test_it_follows_a_map_that_scrolls_and_the_map_with_the_focus() -> None:
    app = SearchApp(open_grid(120, 90), algorithm="bfs")
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press(*["l"] * 60, *["j"] * 50)  # past the view: the map scrolls
        await wait_until(pilot, lambda: cell_under_terminal_cursor(app)[1] == (60, 50))
    compare = SearchApp(open_grid(20, 10), compare="bfs,dfs")
    async with compare.run_test(size=(120, 40)) as pilot:
        await pilot.press("l", "l")
        await wait_until(pilot, lambda: cell_under_terminal_cursor(compare)[1] == (2, 0))
        view, _ = cell_under_terminal_cursor(compare)
        assert view.has_focus


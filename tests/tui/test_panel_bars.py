"""A list panel's scrollbar is drawn only while it has a thumb (``scrollbars.fit_bars``): a
list that overflows its panel shows its bar, one that fits shows none, and a list that grows
past its panel gets its bar."""

from __future__ import annotations

from tests.tui.test_app import wait_until
from tests.tui.test_panels import PanelApp, sync, walled_goal_grid
from tui_search.engine.run.recorded import Run
from tui_search.tui.widgets.frontier_panel import FrontierPanel


def bar_shown(panel: FrontierPanel) -> bool:
    """The panel's vertical bar is on the screen (a bar not drawn has no region)."""
    return bool(panel.vertical_scrollbar.region)


def queue_at(step: int) -> tuple[Run, FrontierPanel]:
    """BFS on an open 40x40 map at ``step`` (its queue is 1 long at step 0, ~20 at 100)."""
    run = Run(walled_goal_grid(40), "bfs")
    run.goto(step)
    return run, FrontierPanel()


@sync
async def test_a_list_that_overflows_shows_its_bar() -> None:
    run, panel = queue_at(100)
    async with PanelApp(panel, run).run_test(size=(50, 12)) as pilot:
        await wait_until(pilot, lambda: bool(panel.region))
        assert panel.virtual_size.height > panel.scrollable_content_region.height
        await wait_until(pilot, lambda: bar_shown(panel))
        assert panel.vertical_scrollbar.region.height == panel.scrollable_content_region.height


@sync
async def test_a_list_that_fits_shows_no_bar_until_it_grows_past_the_panel() -> None:
    run, panel = queue_at(0)
    async with PanelApp(panel, run).run_test(size=(50, 12)) as pilot:
        await wait_until(pilot, lambda: bool(panel.region) and panel.virtual_size.height == 2)
        await pilot.pause()
        assert panel.virtual_size.height <= panel.scrollable_content_region.height
        assert not bar_shown(panel)
        width = panel.scrollable_content_region.width
        run.goto(100)
        panel.show(run)
        await wait_until(pilot, lambda: bar_shown(panel))
        assert panel.virtual_size.height > panel.scrollable_content_region.height
        assert panel.scrollable_content_region.width == width  # its room was kept: no jump
        run.goto(0)
        panel.show(run)
        await wait_until(pilot, lambda: not bar_shown(panel))

"""Weighted A* in the app: the settings screen's weight, the status line's bound ("at most 2
× the optimum"), the answer's real ratio to the lowest cost, and compare mode beside UCS."""

from __future__ import annotations

from tests.helpers import grid_from_rows
from tests.tui.test_app import click_shown, screen_shown, stats, sync, wait_until
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.settings import SettingsScreen
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.run_pane import RunPane

SIZE = (100, 32)
#: A map where A* with weight 2 takes a path 1.27 times the cheapest (17.14 against 13.49).
DETOUR = [
    "S....#......",
    "#.##...#...#",
    "..####....##",
    "#....#.#....",
    "#...#...#...",
    "#...#.###...",
    ".......#.##G",
]


def detour_app(algorithm: str = "astar", compare: str | None = None) -> SearchApp:
    return SearchApp(grid_from_rows(DETOUR), algorithm=algorithm, compare=compare)


@sync
async def test_the_settings_pick_a_weight_and_the_status_line_states_the_bound() -> None:
    app = detour_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        box = screen.query_one("#weight")
        assert not box.disabled and box.value == "1"
        box.value = "0.5"  # no weight: said, and not applied
        explain = screen.query_one("#weight-explain")
        await wait_until(pilot, lambda: "a number 1 or more" in str(explain.render()))
        await click_shown(pilot, "#apply")
        await pilot.pause()
        assert app.screen is screen
        box.value = "2"
        await wait_until(pilot, lambda: "a number 1 or more" not in str(explain.render()))
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: app.session.run.semantics.weight == 2.0)
        await wait_until(pilot, lambda: "weight 2: at most 2 × the optimum" in stats(app)[0])
        assert app.session.semantics == Semantics(weight=2.0)
        panel = app.query_one(FrontierPanel)
        await wait_until(pilot, lambda: "f = g + 2·h" in str(panel.border_title))
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        # the real ratio, against the cheapest path a uniform-cost search finds
        await wait_until(pilot, lambda: "1.27 × the lowest, 13.49" in stats(app)[1])
        assert "cost 17.14" in stats(app)[1]
        await pilot.press("1")  # BFS: the weight is A*'s alone, and says nothing there
        await wait_until(pilot, lambda: app.session.run.algorithm == "bfs")
        await wait_until(pilot, lambda: "weight" not in stats(app)[0])
        assert app.session.run.semantics.weight == 1.0
        await pilot.press("6")  # A* again: weighted as chosen
        await wait_until(pilot, lambda: app.session.run.algorithm == "astar")
        await wait_until(pilot, lambda: "at most 2 × the optimum" in stats(app)[0])


@sync
async def test_the_weight_is_greyed_out_for_a_search_it_does_not_apply_to() -> None:
    app = detour_app("ucs")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        await wait_until(pilot, lambda: screen.query_one("#weight").disabled)
        assert "applies to A* only" in str(screen.query_one("#weight-explain").render())
        screen.query_one("#weight").value = "3"  # greyed out: nothing to weigh
        assert screen.chosen() == Semantics()


@sync
async def test_compare_mode_shows_weighted_astar_beside_ucs_with_its_ratio() -> None:
    app = detour_app(compare="ucs,astar:w=2")
    async with app.run_test(size=(120, 36)) as pilot:
        await wait_until(pilot, lambda: len(app.query(RunPane)) == 2)
        assert app.session.labels == ["UCS", "A* (w=2)"]
        await pilot.press("end")
        await wait_until(pilot, lambda: all(r.at_end for r in app.session.runs))
        weighted = app.main.panes[1].stats
        await wait_until(pilot, lambda: "at most 2 × the optimum" in weighted.status_text)
        await wait_until(pilot, lambda: "1.27 × the lowest" in weighted.narration_text)
        ucs, heavy = (r.path_cost() for r in app.session.runs)
        assert ucs is not None and heavy is not None and heavy / ucs < 2

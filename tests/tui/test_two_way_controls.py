"""The bidirectional searches from the app's own controls: the palette picks one, the settings
choose its stopping rule and turn (greyed out unless one is shown or ticked for compare mode)
and tick them for ``c``, and the help lists them and their kinds of cell."""

from __future__ import annotations

from tests.tui.test_app import click_shown, screen_shown, stats, sync, wait_until
from tests.tui.test_themes import palette_run
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.bidirectional import BiRun
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.help import KEYS, HelpScreen
from tui_search.tui.dialogs.settings import SettingsScreen
from tui_search.tui.model.searches import with_ticked
from tui_search.tui.widgets.legend import Legend
from tui_search.tui.widgets.run_pane import RunPane

TRAP = "maps/pathfinding-js-28.txt"  # bidirectional A*'s trap: 14.24 at the first meeting
SIZE = (100, 32)


def trap_app(algorithm: str = "bfs") -> SearchApp:
    return SearchApp(load_map(TRAP), algorithm=algorithm)


async def apply_settings(pilot, *picks: str) -> None:
    """Open the settings, click each of ``picks`` (ids) until it is on, and apply."""
    app = pilot.app
    await pilot.press("comma")
    screen = await screen_shown(pilot, SettingsScreen)
    for pick in picks:
        await click_shown(pilot, pick)
        await wait_until(pilot, lambda pick=pick: screen.query_one(pick).value)
    await click_shown(pilot, "#apply")
    await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))


def test_a_ticked_box_keeps_the_searches_as_compared() -> None:
    """A box stands for every search of its key (a heuristic, a rule kept); new ones come
    last; a box unticked takes its searches out."""
    both = "biastar:proven,biastar:first-meeting"
    assert with_ticked(both, ["biastar"]) == both
    assert with_ticked(both, ["bfs", "biastar"]) == f"{both},bfs"
    assert with_ticked(f"ucs,{both}", ["ucs"]) == "ucs"
    assert with_ticked("astar:manhattan,bfs", ["bfs", "astar", "bibfs"]) == (
        "astar:manhattan,bfs,bibfs")


@sync
async def test_the_palette_picks_bidirectional_a_star_and_the_pane_shows_both_halves() -> None:
    app = trap_app()
    async with app.run_test(size=SIZE) as pilot:
        await palette_run(pilot, "algorithm: bidirectional a*")
        await wait_until(pilot, lambda: isinstance(app.session.run, BiRun))
        assert app.session.run.algorithm == "biastar" and app.session.algorithm == "biastar"
        await wait_until(pilot, lambda: stats(app)[0].startswith("BiA*"))
        pane = app.query_one(RunPane)
        await wait_until(pilot, lambda: len(pane.query(".pane-frontier.-backward")) == 1)
        assert len(pane.query(".pane-frontier")) == 2


@sync
async def test_first_meeting_chosen_in_the_settings_falls_into_the_trap() -> None:
    """On PathFinding.js #28's map, bidirectional A* stopped at the first meeting answers
    14.24 (the proven meeting: 13.66)."""
    app = trap_app("biastar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.at_end() and "13.66" in stats(app)[0])
        await apply_settings(pilot, "#stop-first-meeting")
        await wait_until(pilot, lambda: app.session.semantics.stop == "first-meeting")
        await wait_until(pilot, lambda: app.session.run is not None and app.session.run.k == 0)
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.at_end() and "14.24" in stats(app)[0])
        assert "13.66" not in stats(app)[0]


@sync
async def test_the_stopping_rule_and_the_turn_are_kept_and_shown_again() -> None:
    """Chosen and applied, the stopping rule and the turn are the session's; the settings
    show them when opened again, and a one-way search between leaves them as they were."""
    app = trap_app("bibfs")
    async with app.run_test(size=SIZE) as pilot:
        await apply_settings(pilot, "#stop-first-meeting", "#turn-smaller")
        chosen = Semantics(stop="first-meeting", turn="smaller")
        await wait_until(pilot, lambda: app.session.semantics == chosen)
        assert app.session.run.semantics == chosen
        await pilot.press("4")  # uniform-cost search: the rules are a bidirectional's
        await wait_until(pilot, lambda: app.session.run.algorithm == "ucs")
        assert app.session.run.semantics == Semantics() and app.session.semantics == chosen
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        await wait_until(pilot, lambda: screen.query_one("#stop").disabled)
        assert screen.query_one("#stop-first-meeting").value
        assert screen.query_one("#turn-smaller").value
        assert screen.chosen() == chosen  # greyed out, kept
        await pilot.press("escape")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await palette_run(pilot, "algorithm: bidirectional bfs")
        await wait_until(pilot, lambda: app.session.run.algorithm == "bibfs")
        assert app.session.run.semantics == chosen


@sync
async def test_stop_and_turn_are_greyed_out_until_a_bidirectional_search_is_ticked() -> None:
    app = trap_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        explain = screen.query_one("#two-way-explain")
        await wait_until(pilot, lambda: screen.query_one("#stop").disabled)
        assert screen.query_one("#turn").disabled and "not BFS's" in str(explain.content)
        await click_shown(pilot, "#compare-biastar")
        await wait_until(pilot, lambda: not screen.query_one("#stop").disabled)
        assert not screen.query_one("#turn").disabled
        assert "first meeting" in str(explain.content)
        assert screen.picked() == "bfs,dfs,biastar"


@sync
async def test_the_settings_grey_out_what_a_bidirectional_search_does_not_use() -> None:
    """Shown alone, bidirectional A* uses the heuristic, the stopping rule and the turn; not
    the visit rule, the goal test, tree search, a priority queue's choices or the weight."""
    app = trap_app("biastar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        greyed = ("#visit", "#goal-test", "#tree_search", "#mark_start", "#ties", "#reopen",
                  "#exact_costs", "#weight", "#recursive")
        await wait_until(pilot, lambda: all(screen.query_one(g).disabled for g in greyed))
        assert not any(screen.query_one(c).disabled for c in ("#heuristic", "#stop", "#turn"))
        assert "it marks a cell reached" in str(screen.query_one("#visit-explain").content)
        assert "stops when its searches meet" in str(screen.query_one("#goal-explain").content)


@sync
async def test_the_settings_tick_bidirectional_searches_for_c() -> None:
    """BiA* ticked and DFS unticked: c compares BFS with bidirectional A*, a pane each."""
    app = trap_app()
    async with app.run_test(size=(120, 36)) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        await click_shown(pilot, "#compare-biastar")
        await wait_until(pilot, lambda: screen.query_one("#compare-biastar").value)
        await click_shown(pilot, "#compare-dfs")
        await wait_until(pilot, lambda: not screen.query_one("#compare-dfs").value)
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        assert app.session.comparison == "bfs,biastar"
        await pilot.press("c")
        await wait_until(pilot, lambda: len(app.query(RunPane)) == 2)
        assert app.session.labels == ["BFS", "BiA*"]
        assert isinstance(app.session.runs[1], BiRun)


@sync
async def test_the_palette_compares_the_two_stopping_rules() -> None:
    app = trap_app()
    async with app.run_test(size=(120, 36)) as pilot:
        await palette_run(pilot, "compare: bia* · bia* (first-meeting)")
        await wait_until(pilot, lambda: len(app.query(RunPane)) == 2)
        assert app.session.labels == ["BiA*", "BiA* (first-meeting)"]
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.at_end())
        costs = [round(run.path_cost() or 0, 2) for run in app.session.runs]
        assert costs == [13.66, 14.24]


@sync
async def test_the_help_lists_the_bidirectional_searches_and_their_cells() -> None:
    app = trap_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("question_mark")
        screen = await screen_shown(pilot, HelpScreen)
        legends = list(screen.query(Legend))
        await wait_until(pilot, lambda: all(legend.region.area for legend in legends))
        assert any("BiBFS / BiUCS / BiA*" in says and "palette" in says for _, says in KEYS)
        assert [legend.only_two_way for legend in legends] == [False, True]
        two_way = " ".join(entry.plain for entry in legends[1].entries())
        for kind in ("frontier ←", "expanded ←", "both", "meeting"):
            assert kind in two_way

"""Compare mode in the app: a pane a search, in lockstep on one map (issue 11)."""

from __future__ import annotations

import json

from tests.tui.test_app import (
    MAPS,
    TUTORIAL,
    open_grid,
    post_keys,
    screen_shown,
    slices_of_one_chunk,
    sync,
    tutorial_app,
    wait_until,
)
from tui_search.cli.main import main
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.settings import SettingsScreen
from tui_search.tui.widgets.run_pane import RunPane

SIZE = (160, 48)


def compare_app(spec: str = "bfs,dfs", path=TUTORIAL) -> SearchApp:
    return SearchApp(load_map(path), path=path, compare=spec)


def steps(app: SearchApp) -> list[int]:
    return [run.k for run in app.session.runs]


@sync
async def test_c_shows_two_panes_and_c_again_one_search() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        single = app.query_one(RunPane)  # one search: one pane
        assert app.session.spec == "bfs" and single.label == "BFS"
        await pilot.press("c")
        await pilot.pause()
        panes = app.query(RunPane)
        assert [p.label for p in panes] == ["BFS", "DFS"] and panes.first() is single
        assert all(p.display and p.view.display for p in panes)
        titles = [p.frontier.border_title for p in panes]
        assert titles == ["Queue (FIFO)", "Stack (LIFO)"]
        assert app.focused is panes[0].view
        await pilot.press("c")
        await pilot.pause()
        assert app.session.spec == "bfs" and list(app.query(RunPane)) == [single]
        assert len(app.session.runs) == 1 and app.focused is single.view


@sync
async def test_n_advances_every_run_and_end_then_p_leaves_the_finished_one() -> None:
    app = compare_app()
    async with app.run_test(size=SIZE) as pilot:
        for _ in range(3):
            await pilot.press("n")
        assert steps(app) == [3, 3]
        await pilot.press("end")
        await pilot.pause()
        assert steps(app) == [22, 7] and all(r.at_end for r in app.session.runs)
        dfs_pane = app.main.panes[1]
        assert "done at step 7" in dfs_pane.stats.status_text
        await pilot.press("p")
        assert steps(app) == [21, 7]  # DFS ended earlier: it stays on its last screen
        assert "done at step 7" in dfs_pane.stats.status_text
        # back to where the other ended, then both step back together
        for _ in range(14):
            await pilot.press("p")
        assert steps(app) == [7, 7]
        await pilot.press("p")
        assert steps(app) == [6, 6]
        await pilot.press("n")
        assert steps(app) == [7, 7]
        await pilot.press("n")
        assert steps(app) == [8, 7]  # DFS is done: n leaves it where it is
        await pilot.press("home")
        await pilot.pause()
        assert steps(app) == [0, 0]


@sync
async def test_the_table_equals_the_headless_comparison(capsys) -> None:
    assert main([str(TUTORIAL), "--headless", "--json", "--compare", "bfs,dfs,astar"]) == 0
    headless = json.loads(capsys.readouterr().out)["runs"]
    app = compare_app("bfs,dfs,astar")
    async with app.run_test(size=SIZE) as pilot:
        table = app.main.table
        assert table.text_lines[1].split()[:2] == ["BFS", "…"]  # going: no figures yet
        await pilot.press("end")
        await pilot.pause()
        rows = [line.replace(" *", "").split() for line in table.text_lines[1:4]]
        for row, run in zip(rows, headless, strict=True):
            _label, found, moves, cost, expanded, generated, peak = row
            assert found == "yes" and int(moves) == run["length"]
            assert float(cost) == round(run["cost"], 3)
            assert int(expanded) == run["expanded"] and int(generated) == run["generated"]
            assert int(peak) == run["max_frontier"]
        assert table.text_lines[-1].startswith("BFS expanded 22 nodes, DFS 7, A* ")


@sync
async def test_an_edit_restarts_every_run_on_the_one_map() -> None:
    app = compare_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        old = list(app.session.runs)
        await pilot.press("down", "down", "right", "o")  # an obstacle at (1,2)
        assert app.session.grid.is_blocked((1, 2)) and app.session.dirty
        assert steps(app) == [0, 0] and not set(app.session.runs) & set(old)
        assert all(p.view.grid is app.session.grid for p in app.main.panes)
        assert all(p.view.cursor == (1, 2) for p in app.main.panes)  # one cursor
        # a click on the second pane's map edits the same map
        view = app.main.panes[1].view
        x, y = view.screen_offset((3, 3))
        await pilot.click(view, offset=(x, y))
        assert app.session.grid.is_blocked((3, 3)) is False  # (3,3) was an obstacle: now free
        assert all(r.k == 0 for r in app.session.runs)


@sync
async def test_algorithm_keys_add_and_take_out_searches() -> None:
    app = compare_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("6")
        await pilot.pause()
        assert app.session.spec == "bfs,dfs,astar" and [p.label for p in app.main.panes] == [
            "BFS", "DFS", "A*"]
        await pilot.press("1")
        await pilot.pause()
        assert app.session.spec == "dfs,astar"
        await pilot.press("2")  # two stay at least
        await pilot.pause()
        assert app.session.spec == "dfs,astar"
        await pilot.press("1", "3")
        await pilot.pause()
        await pilot.press("4")  # four at most
        await pilot.pause()
        assert app.session.spec == "dfs,astar,bfs,iddfs"


@sync
async def test_the_settings_pick_what_c_compares() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        screen = app.screen
        assert isinstance(screen, SettingsScreen)
        screen.query_one("#compare-dfs").value = False
        await pilot.pause()
        screen.query_one("#apply").press()  # one ticked: refused, said why
        await pilot.pause()
        assert app.screen is screen and "tick two to four" in str(
            screen.query_one("#compare-explain").render())
        screen.query_one("#compare-ucs").value = True
        screen.query_one("#compare-astar").value = True
        await pilot.pause()
        screen.query_one("#apply").press()
        await pilot.pause()
        assert app.screen is not screen and app.session.spec.count(",") == 0
        await pilot.press("c")
        await pilot.pause()
        assert [p.label for p in app.main.panes] == ["BFS", "UCS", "A*"]


@sync
async def test_narrow_terminals_stack_the_panes_and_short_ones_fold_the_trees() -> None:
    app = compare_app()
    async with app.run_test(size=(70, 48)) as pilot:
        await pilot.pause()
        a, b = (p.region for p in app.main.panes)
        assert a.x == b.x and b.y > a.y  # one above the other
    app = compare_app()
    async with app.run_test(size=(100, 22)) as pilot:
        await pilot.pause()
        a, b = (p.region for p in app.main.panes)
        assert a.y == b.y and b.x > a.x  # side by side
        assert not app.main.panes[0].tree_panel.display  # too short for trees
    app = compare_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        a, b = (p.region for p in app.main.panes)
        assert a.y == b.y and b.x > a.x  # side by side
        assert app.main.panes[0].tree_panel.display
        await pilot.press("f")
        await pilot.pause()
        assert not app.main.panes[0].tree_panel.display
        await pilot.press("f")
        await pilot.pause()
        assert app.main.panes[0].tree_panel.display


@sync
async def test_f_folds_the_trees_of_one_pane_too() -> None:
    """One search is one pane: f folds its tree away as it folds those of several."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL)
    async with app.run_test(size=SIZE) as pilot:
        tree = app.main.panes[0].tree_panel
        await wait_until(pilot, lambda: tree.display and tree.region.area > 0)
        await pilot.press("f")
        await wait_until(pilot, lambda: not tree.display)
        await pilot.press("f")
        await wait_until(pilot, lambda: tree.display)


@sync
async def test_end_on_a_big_map_computes_each_run_in_slices_and_esc_stops(monkeypatch) -> None:
    recorded = slices_of_one_chunk(monkeypatch)
    app = SearchApp(open_grid(30, 30), compare="iddfs,bfs")  # iddfs: 67,105 steps, 17 chunks
    async with app.run_test(size=SIZE) as pilot:
        post_keys(app, "end", "escape")
        await wait_until(pilot, lambda: recorded and not app.session.seeking)
        await pilot.pause()  # a slice that esc failed to stop would be recorded by now
        assert len(recorded) == 1 and not app.session.runs[0].at_end
        assert "esc" not in app.session.note
        post_keys(app, "end")
        await wait_until(pilot,
                         lambda: app.session.seeking and "IDDFS: computing" in app.session.note)
        await wait_until(pilot, lambda: not app.session.seeking, seconds=60)
        assert all(r.at_end and r.found for r in app.session.runs) and app.session.note == ""
        assert len(set(recorded)) > 3  # in slices


@sync
async def test_play_runs_all_in_lockstep_to_the_end() -> None:
    app = compare_app()
    async with app.run_test(size=SIZE) as pilot:
        for _ in range(7):  # the fastest speed
            await pilot.press("plus")
        await pilot.press("space")
        await wait_until(pilot, lambda: not app.session.playing)
        assert steps(app) == [22, 7]


def test_the_command_line_opens_compare_mode_and_refuses_bad_searches(capsys,
                                                                       monkeypatch) -> None:
    seen = {}
    monkeypatch.setattr(SearchApp, "run",
                        lambda self: seen.setdefault("compare", self.session.spec))
    assert main([str(MAPS / "tutorial.txt"), "--compare", "bfs,dfs"]) == 0
    assert seen["compare"] == "bfs,dfs"
    assert main([str(TUTORIAL), "--compare", "bfs"]) == 2
    assert "compare two to four searches" in capsys.readouterr().err


@sync
async def test_a_setting_that_does_not_apply_to_one_pane_applies_to_the_others() -> None:
    app = compare_app("bfs,astar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        screen.query_one("#visit-expand").value = True
        screen.query_one("#apply").press()
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        assert [c.semantics.visit for c in app.session.contenders] == ["expand", "generate"]
        assert "does not apply to A*" in app.session.note
        assert "visit on expand" in app.main.panes[0].stats.status_text


@sync
async def test_an_exercise_above_the_panes_takes_its_room_from_them() -> None:
    app = compare_app()
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.pause()
        a, b = (p.region for p in app.main.panes)
        assert a.y == b.y  # side by side: 60 columns each
        await pilot.press("x")
        await pilot.pause()
        a2, b2 = (p.region for p in app.main.panes)
        assert a2.y == b2.y and a2.width == a.width  # still side by side, as wide
        challenge = app.query_one("#challenge").region
        assert challenge.width == 120 and challenge.bottom <= a2.y < a.y + challenge.height + 1


@sync
async def test_keys_pressed_at_once_act_on_the_new_comparison() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        post_keys(app, "c", "n", "n")
        await wait_until(pilot,
                         lambda: all(p.is_mounted for p in app.main.panes) and app.main.panes)
        await pilot.pause()
        assert app.session.spec == "bfs,dfs" and steps(app) == [2, 2]
        post_keys(app, "3", "4")
        await wait_until(pilot, lambda: app.session.spec == "bfs,dfs,iddfs,ucs")
        post_keys(app, "c", "c", "n")  # off and on again, then a step: every key was handled
        await wait_until(pilot, lambda: steps(app) == [1, 1, 1, 1])
        assert app.session.spec == "bfs,dfs,iddfs,ucs" and len(app.main.panes) == 4


@sync
async def test_a_spaced_or_trailing_comma_spec_and_unchanged_settings_keep_the_comparison(
) -> None:
    app = compare_app("dfs, bfs,")
    async with app.run_test(size=SIZE) as pilot:
        assert app.session.spec == "dfs,bfs"
        await pilot.press("n", "n")
        await pilot.press("2")  # takes DFS out? two stay at least: no
        assert app.session.spec == "dfs,bfs" and steps(app) == [2, 2]
        await pilot.press("comma")
        (await screen_shown(pilot, SettingsScreen)).query_one("#apply").press()
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        assert app.session.spec == "dfs,bfs" and steps(app) == [2, 2]  # nothing changed


@sync
async def test_the_settings_in_compare_mode_are_for_every_search_compared() -> None:
    app = compare_app("bfs,astar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        screen = app.screen
        assert screen.query_one("#heuristic").disabled is False  # for A*
        assert screen.query_one("#visit").disabled is False  # for BFS
        screen.query_one("#heuristic-manhattan").value = True
        screen.query_one("#apply").press()
        await pilot.pause()
        assert [c.semantics.heuristic for c in app.session.contenders] == ["manhattan", "manhattan"]
        assert "inadmissible" in app.main.panes[1].stats.status_text


@sync
async def test_short_terminals_put_the_panes_beside_each_other_and_four_in_two_rows() -> None:
    app = compare_app()
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        a, b = (p.region for p in app.main.panes)
        assert a.y == b.y  # too short to stack: beside each other, 40 columns each
    app = compare_app("bfs,dfs,ucs,astar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        regions = [p.region for p in app.main.panes]
        assert len({r.y for r in regions}) == 2 and len({r.x for r in regions}) == 2


@sync
async def test_zoom_and_labels_stay_when_a_search_is_added() -> None:
    app = compare_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("left_square_bracket", "a")
        await pilot.pause()
        before = app.main.panes[0].view.view_state()
        await pilot.press("6")
        await wait_until(pilot, lambda: len(app.main.panes) == 3 and all(
            p.is_mounted for p in app.main.panes))
        assert all(p.view.view_state() == before for p in app.main.panes)


@sync
async def test_the_palette_offers_comparisons_and_a_bad_one_is_said_not_crashed() -> None:
    from tui_search.tui.commands import SearchCommands

    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        names = [name for name, _, _ in SearchCommands(app.screen).commands()]
        assert "Compare: A* · A* (manhattan)" in names and "Compare: BFS · DFS" in names
        await app.main.run_action("show_compare('astar,astar:manhattan')")
        await wait_until(pilot,
                         lambda: all(p.is_mounted for p in app.main.panes) and app.main.panes)
        assert [p.label for p in app.main.panes] == ["A*", "A* (manhattan)"]
        await app.main.run_action("show_compare('bfs,nope')")
        await pilot.pause()
        assert app.session.spec == "astar,astar:manhattan"  # unchanged, and said in a notification

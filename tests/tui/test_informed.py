"""Uniform-cost, greedy best-first and A* in the app: the keys, the priority queue panel, the
status line's g, h and f, the narration, the lowest cost beside the path's, the heuristic in
the settings and the inadmissible warning."""

from __future__ import annotations

from tests.helpers import grid_from_rows
from tests.tui.test_app import (
    ARENA,
    MAPS,
    click_shown,
    screen_shown,
    stats,
    sync,
    tutorial_app,
    wait_until,
)
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.scenarios import load_scenario
from tui_search.engine.run.position import CellState
from tui_search.engine.run.queries import EventTree
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.heuristics import INADMISSIBLE
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.settings import SettingsScreen
from tui_search.tui.view.narration import narrate
from tui_search.tui.view.readout import describe
from tui_search.tui.widgets.frontier_panel import FrontierPanel

SIZE = (120, 36)


def panel_lines(app: SearchApp) -> list[str]:
    panel = app.query_one(FrontierPanel)
    return [panel.line_text(y) for y in range(12)]


@sync
async def test_the_keys_pick_the_informed_searches_from_the_registry() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        for key, algorithm, title in (("4", "ucs", "Priority queue (UCS: g)"),
                                      ("5", "greedy", "Priority queue (Greedy: h)"),
                                      ("6", "astar", "Priority queue (A*: f = g + h)")):
            await pilot.press(key)
            assert app.session.run.algorithm == algorithm and app.session.run.k == 0
            assert app.query_one(FrontierPanel).border_title == title


@sync
async def test_a_star_shows_its_queue_in_order_with_g_h_f_and_stale_entries() -> None:
    """The tutorial under A* after five steps (docs/01-keys.md's example): (0,3) was pushed at
    g 3.83, then reached at g 3.00 -- its first entry is struck out as stale."""
    app = tutorial_app("astar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press(*"nnnnn")
        lines = panel_lines(app)
        assert lines[0] == "5 in the priority queue"
        assert lines[1] == "▶  (2,1) NE  f 7.24 g 3.83 h 3.41"
        assert lines[4] == " + (0,3) S   f 8.41 g 3.00 h 5.41"
        assert lines[5].startswith("   (0,3) SW  f 9.24 g 3.83 h 5.41") and "stale" in lines[5]
        status, narration = stats(app)
        assert "f 7.00 (g 2.00 + h 5.00)" in status
        assert narration == ("Expanded (0,2) f = 7.00 (g 2.00 + h 5.00): added S; (0,3) reached "
                             "with a lower g")
        # back one step: the second (0,3) is not pushed yet, so the first is not stale
        await pilot.press("p")
        assert not any("stale" in line for line in panel_lines(app))
        await pilot.press("n")
        assert lines == panel_lines(app)


@sync
async def test_uniform_cost_shows_g_only_and_ends_on_the_lowest_cost() -> None:
    app = tutorial_app("ucs")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        assert panel_lines(app)[1].endswith("g 2.00") or " g " in panel_lines(app)[1]
        assert " h " not in panel_lines(app)[1]
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        assert "cost 8.66 (the lowest)" in stats(app)[1]
        assert stats(app)[1].startswith("Took the goal (5,2) off the priority queue: found")


@sync
async def test_bfs_on_exercise_one_is_shown_the_cheaper_path() -> None:
    """The fewest moves is not the cheapest: BFS's path costs 2.83 where 2.00 exists."""
    grid = load_map(MAPS / "exercise1-bfs-wins.txt")
    app = SearchApp(grid)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        assert "cost 2.83 (lowest 2.00)" in stats(app)[1]


@sync
async def test_a_stale_step_is_discarded_and_says_why() -> None:
    rows = ["S..#.", "...#G"]
    grid = Grid(5, 2, bytearray(1 if c == "#" else 0 for row in rows for c in row),
                start=(0, 0), goal=(4, 1))
    app = SearchApp(grid, algorithm="astar")
    async with app.run_test(size=SIZE) as pilot:
        run = app.session.run
        run.advance()
        k = recording_of(run).discarded_steps()[0]
        for _ in range(k):
            await pilot.press("n")
        assert run.steps.is_discarded(run.k)
        narration = stats(app)[1]
        assert "stale (its cell was reached with a lower g since), discarded" in narration
        lines = panel_lines(app)
        assert lines[1].startswith("✗ ") and " h " in lines[1]  # a figure stays with its name
        assert "stale, discarded" in " ".join(lines[1:3])  # wrapped in a narrow panel


def test_a_cell_expanded_then_reached_with_a_lower_g_is_narrated_re_opened() -> None:
    """A* with the inadmissible manhattan heuristic beside diagonal moves: (2,2) is expanded
    at step 6 with g 4.83 (reached round by the south), then (3,1) reaches it diagonally at
    g 2.83 + 1.41 = 4.24 -- the issue's "(4,4) re-opened with a lower g"; it is expanded
    again next step."""
    grid = grid_from_rows([".#....",
                           "....#S",
                           ".#.##.",
                           "G#...#"])
    run = Run(grid, "astar", Semantics(heuristic="manhattan"))
    run.goto(6)
    assert narrate(run) == "Expanded (2,2) f = 7.83 (g 4.83 + h 3.00): added N, NW, NE"
    run.goto(8)
    assert narrate(run) == ("Expanded (3,1) f = 7.83 (g 2.83 + h 5.00): added NW, W, SW; "
                            "(2,1) reached with a lower g, (2,2) re-opened with a lower g")
    run.goto(9)
    assert run.now.current_node() == (2, 2) and not run.steps.is_discarded(9)
    assert narrate(run).startswith("Expanded (2,2) f = 7.24 (g 4.24 + h 3.00)")


def test_a_cell_only_taken_off_stale_is_not_narrated_re_opened() -> None:
    """Greedy takes equal h in push order, so (4,1)'s costlier entry (g 5.24) comes off first,
    stale, and is discarded at step 17; when (3,2) reaches it cheaper still at step 19 it has
    never been expanded: "reached with a lower g", not "re-opened"."""
    grid = grid_from_rows(["G.##..",
                           "###..#",
                           "......",
                           "...##.",
                           "..S#.."])
    run = Run(grid, "greedy", Semantics(heuristic="manhattan"))
    run.goto(17)
    assert run.now.current_node() == (4, 1) and run.steps.is_discarded(17)
    assert run.now.times_reached((4, 1)) == (2, 0)  # taken off once, stale: not expanded
    run.goto(18)  # the map and the readout: still waiting on the frontier, not expanded
    assert run.now.row_states(1)[4] == CellState.FRONTIER
    assert describe(run, grid, (4, 1)).startswith("(4,1): on the frontier since step 12,")
    run.goto(19)
    assert narrate(run) == ("Expanded (3,2) h = 5.00 (g 2.41): added E, NE; "
                            "(4,2) reached with a lower g, (4,1) reached with a lower g")


@sync
async def test_the_heuristic_is_a_setting_and_an_inadmissible_one_is_named() -> None:
    app = tutorial_app("astar")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        await click_shown(pilot, "#heuristic-manhattan")
        await wait_until(pilot, lambda: "inadmissible" in str(
            screen.query_one("#heuristic-explain").render()))
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: app.session.run.semantics.heuristic == "manhattan")
        await pilot.pause()
        status = stats(app)[0]
        assert "heuristic manhattan" in status and INADMISSIBLE in status
        # the heuristic does not apply to BFS: its settings grey it out, its status says nothing
        await pilot.press("1")
        await wait_until(pilot, lambda: app.session.run.algorithm == "bfs")
        await pilot.pause()
        assert "manhattan" not in stats(app)[0]
        await pilot.press("comma")
        assert (await screen_shown(pilot, SettingsScreen)).query_one("#heuristic").disabled


@sync
async def test_switching_to_a_star_keeps_its_own_goal_test() -> None:
    """The settings keep "the algorithm's own" goal test: BFS tests on generation, A* on
    expansion, and neither is shown as a difference."""
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await pilot.press("6")
        await wait_until(pilot, lambda: app.session.run.algo.key == "astar")
        run = app.session.run
        assert run.goal_test == "expand" and "goal test" not in stats(app)[0]
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        assert app.screen.query_one("#goal_test-expand").value


@sync
async def test_the_benchmark_optimum_is_shown_while_the_map_is_unchanged() -> None:
    """On screen; that an edit drops it: tests/tui/test_session.py."""
    scen = load_scenario(ARENA.with_suffix(".map.scen"), 5)
    grid = load_map(ARENA, start=scen.start, goal=scen.goal)
    app = SearchApp(grid, path=ARENA, algorithm="ucs", semantics=Semantics(corners="never"),
                    optimal_cost=scen.optimal_length)
    async with app.run_test(size=SIZE) as pilot:
        assert app.session.run.known_lowest == scen.optimal_length
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        assert "cost 2.00 (the lowest)" in stats(app)[1]


@sync
async def test_a_priority_queue_of_100000_entries_is_drawn_line_by_line() -> None:
    """Uniform-cost tree search keeps every successor: ~100,000 entries after 20,000 steps.
    The panel is one line-API widget (no widget per entry): its height is the queue's, its
    last line is the queue's last entry, and a step either way keeps it in priority order.
    Focused and scrolled (page down, end, page up, home, a jump to line 50,000), the rows on
    screen are the entries at the scroll offset, with no widget added; the next step scrolls
    back to the front."""
    grid = Grid(400, 400, start=(200, 200), goal=(0, 0))
    app = SearchApp(grid, algorithm="ucs", semantics=Semantics(tree_search=True),
                    max_steps=30_000)
    async with app.run_test(size=SIZE) as pilot:
        run = app.session.run
        run.goto(20_000)
        app.main.present()  # the app's own refresh, after moving its run directly
        await pilot.pause()
        panel = app.query_one(FrontierPanel)
        n = run.now.frontier_len()
        assert n > 100_000
        assert panel.line_text(0) == f"{n:,} in the priority queue"
        assert panel.virtual_size.height == n + 1 and not panel.children
        (last,) = run.now.frontier(n - 1, n)
        x, y = run.nodes.cell(last)
        assert panel.line_text(n)[3:].startswith(f"({x},{y})")
        await pilot.press("n", "p")
        tree = EventTree(recording_of(run))
        keys = [tree.priority_key(g) for g in run.now.frontier(0, 200)]
        assert keys == sorted(keys) and run.k == 20_000
        widgets = len(list(app.screen.walk_children()))

        # scrolled (Tab focuses the queue; its keys scroll it), the lines on screen are the
        # queue's entries at the scroll offset, drawn from the run, still with no widget each
        await pilot.press("tab")
        assert app.focused is panel
        seen = []
        for key in ("pagedown", "pagedown", "end", "pageup", "home"):
            await pilot.press(key)
            await wait_until(pilot, lambda: shown_entries(panel) == queue_at(panel, run))
            seen.append(panel.scroll_offset.y)
        page = panel.scrollable_content_region.height
        assert seen[:2] == [page, 2 * page] and seen[3] == seen[2] - page and seen[4] == 0
        assert seen[2] == n + 1 - page  # the end: the queue's last entry on the last row
        assert shown_entries(panel)[0] is None  # home: the count line again
        panel.scroll_to(y=50_000, animate=False, immediate=True)
        await pilot.pause()
        (g,) = run.now.frontier(49_999, 50_000)  # line 50,000: the queue's entry 49,999
        x, y = run.nodes.cell(g)
        assert shown_entries(panel) == queue_at(panel, run)
        assert shown_entries(panel)[0] == (f"({x},{y})", f"{run.nodes.cost(g):.2f}")
        assert not panel.children and len(list(app.screen.walk_children())) == widgets
        # the next step scrolls the queue back to its front
        await pilot.press("n")
        await wait_until(pilot, lambda: panel.scroll_offset.y == 0)
        assert shown_entries(panel) == queue_at(panel, run) and run.k == 20_001


def shown_entries(panel: FrontierPanel) -> list[tuple[str, str] | None]:
    """The (cell, g) each row of the panel draws on screen, None for a row that is no entry
    (the count line)."""
    out: list[tuple[str, str] | None] = []
    for y in range(panel.scrollable_content_region.height):
        words = panel.render_line(y).text.split()
        cell = next((w for w in words if w.startswith("(")), None)
        out.append(None if cell is None else (cell, words[words.index("g") + 1]))
    return out


def queue_at(panel: FrontierPanel, run: Run) -> list[tuple[str, str] | None]:
    """What those rows must show: the queue's entries from the scroll offset on."""
    top = panel.scroll_offset.y
    rows = panel.scrollable_content_region.height
    out: list[tuple[str, str] | None] = [None] * max(0, 1 - top)
    for g in run.now.frontier(max(0, top - 1), top - 1 + rows):
        x, y = run.nodes.cell(g)
        out.append((f"({x},{y})", f"{run.nodes.cost(g):.2f}"))
    return out

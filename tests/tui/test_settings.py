"""The search settings screen (``,``) and what the app shows of the choices in force."""

from __future__ import annotations

from tests.tui.test_app import (
    TUTORIAL,
    click_shown,
    screen_shown,
    stats,
    sync,
    tutorial_app,
    wait_until,
)
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import recording_of
from tui_search.engine.search.choices import Semantics
from tui_search.tui.app import SearchApp
from tui_search.tui.dialogs.settings import SettingsScreen
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.search_tree import SearchTreePanel

SIZE = (100, 32)


@sync
async def test_settings_apply_starts_a_new_run_at_step_0() -> None:
    """Pick corners 'never' with the keyboard, apply: a new run on the same map under the new
    rule, at step 0, and the status line says what differs from the defaults."""
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        first = app.session.run
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        await pilot.press("right", "right", "enter")  # corners has the focus: never
        await wait_until(pilot, lambda: app.screen.query_one("#corners-never").value)
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await pilot.pause()
        run = app.session.run
        assert run is not first and run.k == 0
        assert run.semantics == Semantics(corners="never") == app.session.semantics
        assert "corners: never" in stats(app)[0]


@sync
async def test_cancel_and_escape_change_nothing() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n")
        first = app.session.run
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        await pilot.press("right", "enter", "escape")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await pilot.pause()
        assert app.session.run is first and first.k == 1 and app.session.semantics == Semantics()
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        await click_shown(pilot, "#cancel")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await pilot.pause()
        assert app.session.run is first


@sync
async def test_a_bad_move_order_is_shown_and_not_applied() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        order = screen.query_one("#order")
        order.value = "N,UP"
        error = screen.query_one("#order-error")
        await wait_until(pilot, lambda: "unknown direction 'UP'" in str(error.render()))
        await click_shown(pilot, "#apply")
        await pilot.pause()
        assert app.screen is screen  # still open
        assert "unknown direction 'UP'" in str(error.render())
        order.value = "N,W,S,E"
        order.focus()
        await wait_until(pilot, lambda: "UP" not in str(error.render()) and order.has_focus)
        await pilot.press("enter")  # enter in the order applies, as the Apply button does
        await wait_until(pilot, lambda: app.session.semantics.order == ("N", "W", "S", "E"))


@sync
async def test_tree_search_greys_out_the_visit_rule_and_defaults_restore_all() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        screen = await screen_shown(pilot, SettingsScreen)
        await click_shown(pilot, "#visit-expand")
        await wait_until(pilot, lambda: screen.query_one("#visit-expand").value)
        await click_shown(pilot, "#tree_search")
        await wait_until(pilot, lambda: screen.query_one("#visit").disabled)
        assert screen.chosen() == Semantics(tree_search=True)  # visit does not apply
        await click_shown(pilot, "#defaults")
        await wait_until(pilot, lambda: not screen.query_one("#visit").disabled)
        assert screen.chosen() == Semantics()


@sync
async def test_visit_on_expand_lists_duplicates_and_says_when_a_step_is_discarded() -> None:
    """Under visit on expand the queue lists a cell as often as it is on it; a discarded
    step's narration says it threw the copy away."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, semantics=Semantics(visit="expand"))
    async with app.run_test(size=SIZE) as pilot:
        run = app.session.run
        run.advance()
        k = recording_of(run).discarded_steps()[0]
        for _ in range(k - 1):
            await pilot.press("n")
        cells = [run.nodes.cell(g) for g in run.now.frontier()]
        assert len(cells) > len(set(cells))  # a cell twice on the queue
        panel = app.query_one(FrontierPanel)
        shown = [panel.line_text(y) for y in range(len(cells))]
        dup = next(c for c in cells if cells.count(c) > 1)
        assert sum(f"({dup[0]},{dup[1]})" in line for line in shown) == cells.count(dup)
        await pilot.press("n")
        status, narration = stats(app)
        assert "already expanded, discarded" in narration
        assert "discarded 1" in status and "visit on expand" in status


@sync
async def test_no_path_under_a_corner_rule_says_which_rule_blocked_it() -> None:
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, semantics=Semantics(corners="one"))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.run.at_end)
        await pilot.pause()
        assert not app.session.run.found
        assert "the corner rule 'one' blocks it" in stats(app)[1]


@sync
async def test_switching_to_iddfs_drops_visit_on_expand_and_says_so() -> None:
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, semantics=Semantics(visit="expand"))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("3")
        await wait_until(pilot, lambda: app.session.run.algorithm == "iddfs")
        assert app.session.run.semantics.visit == "generate"
        assert "does not apply to IDDFS" in stats(app)[1]


@sync
async def test_a_discarded_step_shows_the_entry_it_threw_away() -> None:
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, semantics=Semantics(visit="expand"))
    async with app.run_test(size=SIZE) as pilot:
        run = app.session.run
        run.advance()
        k = recording_of(run).discarded_steps()[0]
        for _ in range(k):
            await pilot.press("n")
        x, y = run.nodes.cell(run.steps.expanded_event(k))
        first = app.query_one(FrontierPanel).line_text(1)  # under the count
        assert first.startswith(f"✗  ({x},{y})") and "discarded" in first
        assert any("◀ discarded" in line for line in app.query_one(SearchTreePanel).lines())
        await pilot.press("n")  # the next step expands: the mark goes
        if not run.steps.is_discarded(k + 1):
            assert "✗" not in " ".join(app.query_one(FrontierPanel).lines())


@sync
async def test_a_box_ticked_holds_a_tick_and_one_not_is_empty() -> None:
    """Textual's checkbox draws an ``X`` in every box, dim when off: here a ticked box holds
    ✓ and a picked radio button ●, the others nothing, and a click changes the mark."""
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        screen = app.screen

        def mark(selector: str) -> str:
            return screen.query_one(selector).render().plain[1]  # inside ▐ ▌

        assert (mark("#compare-bfs"), mark("#compare-ucs"), mark("#tree_search")) == (
            "✓", " ", " ")
        assert (mark("#corners-always"), mark("#corners-never")) == ("●", " ")
        await click_shown(pilot, "#tree_search")
        await wait_until(pilot, lambda: mark("#tree_search") == "✓")
        await click_shown(pilot, "#corners-never")
        await wait_until(pilot, lambda: mark("#corners-never") == "●")
        assert mark("#corners-always") == " "
        assert "X" not in "".join(mark(f"#compare-{k}") for k in ("bfs", "dfs", "ucs"))


@sync
async def test_a_recursion_and_a_closed_set_are_picked_and_applied() -> None:
    """DFS: pick "a line lists calls", apply: the run is the recursion and the Code panel's
    code says so.  A*: ties on the smallest cell, no re-opening, exact costs: applied."""
    from tui_search.tui.view.code_trace import code_of

    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("2", "comma")
        await screen_shown(pilot, SettingsScreen)
        await click_shown(pilot, "#recursive-calls")
        await wait_until(pilot, lambda: app.screen.query_one("#recursive-calls").value)
        assert app.screen.query_one("#visit").disabled  # a recursion visits on entry
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await wait_until(pilot, lambda: app.session.run.semantics.recursive == "calls")
        assert "function visit(node):" in "\n".join(code_of(app.session.run).numbered())
        await pilot.press("6", "comma")
        await screen_shown(pilot, SettingsScreen)
        assert not app.screen.query_one("#ties").disabled
        for target in ("#ties-node", "#reopen", "#exact_costs"):
            await click_shown(pilot, target)
        await wait_until(pilot, lambda: app.screen.query_one("#ties-node").value
                         and not app.screen.query_one("#reopen").value)
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await wait_until(pilot, lambda: app.session.run.algorithm == "astar"
                         and app.session.run.semantics.ties == "node")
        sem = app.session.run.semantics
        assert not sem.reopen and sem.cost_tolerance == 0 and not sem.recursive


@sync
async def test_a_choice_the_screen_does_not_show_is_kept_when_settings_apply() -> None:
    """--flip-even is the command line's only: applying the settings keeps it."""
    flipped = Semantics(order=("E", "W", "N", "S"), flip_even=True)
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, algorithm="astar", semantics=flipped)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("comma")
        await screen_shown(pilot, SettingsScreen)
        await pilot.press("right", "right", "enter")  # corners: never
        await wait_until(pilot, lambda: app.screen.query_one("#corners-never").value)
        await click_shown(pilot, "#apply")
        await wait_until(pilot, lambda: not isinstance(app.screen, SettingsScreen))
        await wait_until(pilot, lambda: app.session.semantics.corners == "never")
        assert app.session.semantics == flipped.replace(corners="never")
        assert "reversed where x + y is even" in stats(app)[0]

"""Predict the next node: the quiz mode (i, enter)."""

from __future__ import annotations

from tests.tui.test_app import TUTORIAL, stats, sync, tutorial_app, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.key_bar import KeyBar

SIZE = (120, 36)


def panel_text(app) -> list[str]:
    panel = app.query_one(FrontierPanel)
    return [panel.line_text(y) for y in range(8)]


@sync
async def test_the_quiz_hides_the_order_asks_and_keeps_a_score() -> None:
    """BFS on the tutorial: after two steps the queue holds (0,2) and (1,2), front first.
    The quiz lists them by cell with no next-out mark; the cursor on the front and enter is
    right, on another cell wrong; the score counts both."""
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        assert "Quiz" in [desc for _, desc, _ in app.query_one(KeyBar).hints()]
        await pilot.press("n", "n")
        front = app.session.run.now.frontier(0, 1)[0]
        answer = app.session.run.nodes.cell(front)
        await pilot.press("i")
        assert app.session.quiz.on and stats(app)[1].startswith(
            "Quiz (0 of 0): which node comes off the queue next?")
        lines = panel_text(app)
        assert not any("▶" in line or "front" in line for line in lines)
        assert app.query_one(FrontierPanel).border_title.endswith("· order hidden")
        app.session.cursor = answer
        await pilot.press("enter")
        assert app.session.run.k == 3 and app.session.run.now.current_node() == answer
        assert stats(app)[1].startswith(f"Right: ({answer[0]},{answer[1]}) was the queue's "
                                        "front · 1 of 1")
        app.session.cursor = (5, 5)  # not on the frontier at all
        await pilot.press("enter")
        node = app.session.run.now.current_node()
        assert stats(app)[1].startswith(f"Not quite: ({node[0]},{node[1]}) came off the "
                                        "queue's front, not (5,5) · 1 of 2")
        await pilot.press("i")  # off: the order and the marks come back
        assert not app.session.quiz.on and any("▶" in line for line in panel_text(app))


@sync
async def test_enter_does_nothing_outside_the_quiz() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("enter")
        assert app.session.run.k == 0


# -- picking the answer in the frontier panel (click, tab and up/down) ------------------------
def entry_offset(panel: FrontierPanel, cell) -> tuple[int, int]:
    """Where to click on ``panel`` (its region, border included) for the entry of ``cell``."""
    y = next(y for y in range(panel.virtual_size.height) if panel.entry_cell(y) == cell)
    return (4, 1 + y - round(panel.scroll_y))  # the border's line, then the list's lines


async def click_entry(pilot, cell, times: int = 1, panel: FrontierPanel | None = None) -> None:
    """Click the line of ``cell``'s entry in ``panel`` (the app's single one by default)."""
    panel = panel or pilot.app.main.panes[0].frontier
    await pilot.click(panel, offset=entry_offset(panel, cell), times=times)
    await pilot.pause()


async def quiz_after_two_steps(pilot):
    """BFS on the tutorial, two steps, quiz on: the queue holds two entries; the answer (the
    front) and the entry that is not it."""
    await pilot.press("n", "n", "i")
    run = pilot.app.session.run
    cells = [run.nodes.cell(g) for g in run.now.frontier(0, 10)]
    return cells[0], cells[1]


@sync
async def test_a_click_on_the_front_entry_picks_it_and_enter_answers_right() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        answer, _ = await quiz_after_two_steps(pilot)
        assert "Cursor on it or click its entry, then enter" in stats(app)[1]
        panel = app.query_one(FrontierPanel)
        assert panel.border_subtitle == "+ just added · click picks"
        await click_entry(pilot, answer)
        # the pick is the cursor
        assert app.session.cursor == answer and app.main.views[0].cursor == answer
        assert app.session.run.k == 2  # a click picks; it does not answer
        assert panel.entry_cell(panel.pick_line()) == answer
        assert panel.line_band(panel.pick_line()) is not None  # the picked line is marked
        await pilot.press("enter")
        assert app.session.run.k == 3 and app.session.run.now.current_node() == answer
        assert (app.session.quiz.right, app.session.quiz.asked) == (1, 1)
        assert stats(app)[1].startswith(f"Right: ({answer[0]},{answer[1]}) was the queue's "
                                        "front · 1 of 1 · next: cursor or pick, enter")


@sync
async def test_a_click_on_another_entry_and_enter_is_not_quite() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        answer, other = await quiz_after_two_steps(pilot)
        await click_entry(pilot, other)
        assert app.session.cursor == other
        await pilot.press("enter")
        assert app.session.run.now.current_node() == answer
        assert (app.session.quiz.right, app.session.quiz.asked) == (0, 1)
        assert stats(app)[1].startswith(
            f"Not quite: ({answer[0]},{answer[1]}) came off the queue's front, "
            f"not ({other[0]},{other[1]}) · 0 of 1")


@sync
async def test_a_double_click_on_an_entry_picks_and_answers() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        answer, _ = await quiz_after_two_steps(pilot)
        await click_entry(pilot, answer, times=2)
        assert app.session.run.k == 3 and (app.session.quiz.right, app.session.quiz.asked) == (1, 1)


@sync
async def test_clicks_on_the_count_line_or_outside_the_quiz_pick_nothing() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("n", "n")
        panel = app.query_one(FrontierPanel)
        await pilot.click(FrontierPanel, offset=(4, 2))  # no quiz: the front entry's line
        await pilot.pause()
        assert app.session.cursor == (0, 0) and panel.pick_line() is None
        await pilot.press("i")
        await pilot.click(FrontierPanel, offset=(4, 1))  # the count line
        await pilot.pause()
        assert app.session.cursor == (0, 0) and app.session.run.k == 2


@sync
async def test_tab_to_the_frontier_then_up_down_pick_and_enter_answers() -> None:
    """From the keyboard: tab moves the focus to the frontier panel; in the quiz its key hint
    is "Pick" and up / down move the pick (the cursor) entry by entry; enter answers."""
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        answer, _ = await quiz_after_two_steps(pilot)
        panel = app.query_one(FrontierPanel)
        for _ in range(4):
            if app.focused is panel:
                break
            await pilot.press("tab")
        assert app.focused is panel
        assert "Pick" in [desc for _, desc, _ in app.query_one(KeyBar).hints()]
        order = [panel.entry_cell(y) for y in (1, 2)]  # by cell: the listed order
        assert None not in order and panel.entry_cell(3) is None
        await pilot.press("down")  # nothing picked yet (the cursor is on the start): the first
        assert app.session.cursor == order[0] and panel.pick_line() == 1
        await pilot.press("down", "down")  # stops at the last
        assert app.session.cursor == order[1] and panel.pick_line() == 2
        await pilot.press("up")
        assert app.session.cursor == order[0]
        while app.session.cursor != answer:
            await pilot.press("up")
        await pilot.press("enter")
        assert (app.session.quiz.right, app.session.quiz.asked) == (1, 1) and app.session.run.k == 3
        await pilot.press("i")  # quiz off: up / down scroll the panel again, the pick is gone
        assert "Pick" not in [desc for _, desc, _ in app.query_one(KeyBar).hints()]
        cursor = app.session.cursor
        await pilot.press("down")
        assert app.session.cursor == cursor and panel.pick_line() is None


@sync
async def test_in_compare_mode_the_left_panes_frontier_picks() -> None:
    app = tutorial_app()
    async with app.run_test(size=(160, 44)) as pilot:
        await pilot.press("c")
        await pilot.pause()
        left, right = (pane.frontier for pane in app.main.panes)
        await pilot.press("n", "n", "i")
        answer = app.session.run.nodes.cell(app.session.run.now.frontier(0, 1)[0])
        await pilot.click(right, offset=(4, 2))  # the right pane's front: not the quiz's
        await pilot.pause()
        assert app.session.cursor == (0, 0)
        await click_entry(pilot, answer, panel=left)
        assert app.session.cursor == answer
        await pilot.press("enter")
        assert (app.session.quiz.right, app.session.quiz.asked) == (1, 1)
        assert app.main.stats.narration_text.startswith(f"Right: ({answer[0]},{answer[1]}) was")


@sync
async def test_the_quiz_key_stays_in_a_narrow_key_bar_while_the_quiz_is_on() -> None:
    """At 100 columns the bar leaves the quiz's hint out (it matters less than most), but
    while the quiz is on its key is the way out, so it is kept; off again, it goes."""
    app = tutorial_app()
    async with app.run_test(size=(100, 30)) as pilot:
        def shown() -> list[str]:
            return [desc for _, desc, _ in app.query_one(KeyBar).shown_hints()]

        assert "Quiz" not in shown() and "Help" in shown()
        await pilot.press("i")
        assert "Quiz" in shown() and "Help" in shown() and "Quit" in shown()
        await pilot.press("i")
        assert "Quiz" not in shown()


@sync
async def test_in_a_narrow_pane_an_entry_of_several_rows_is_picked_by_any_of_them() -> None:
    """Three searches at 120x40: A*'s entries take rows of their own for their figures; a
    click on a figures row picks its entry, and down moves the pick a whole entry on."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="astar,bfs,dfs")
    async with app.run_test(size=(120, 40)) as pilot:
        panel = app.main.panes[0].frontier
        await pilot.press("n", "n", "i")
        await wait_until(pilot, lambda: any(panel.entry_cell(y) for y in range(9)))
        first = next(y for y in range(panel.virtual_size.height) if panel.entry_cell(y))
        rows = next(y for y in range(first, first + 9)
                    if panel.entry_cell(y) != panel.entry_cell(first)) - first
        assert rows > 1 and "f" in panel.line_text(first + 1)  # the figures under the cell
        cell = panel.entry_cell(first + rows)
        await pilot.click(panel, offset=(4, 1 + first + rows + 1 - round(panel.scroll_y)))
        await wait_until(pilot, lambda: app.session.cursor == cell)
        assert panel.pick_line() == first + rows
        panel.focus()
        await pilot.press("up")
        await wait_until(pilot, lambda: panel.pick_line() == first)

"""Predict the next node: the quiz mode (i, enter)."""

from __future__ import annotations

from tests.tui.test_app import stats, sync, tutorial_app
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
        front = app.search_run.frontier(0, 1)[0]
        answer = app.search_run.gen_cell(front)
        await pilot.press("i")
        assert app.quiz and stats(app)[1].startswith("Quiz: which node comes off the queue next?")
        lines = panel_text(app)
        assert not any("▶" in line or "front" in line for line in lines)
        assert app.query_one(FrontierPanel).border_title.endswith("· order hidden")
        app.cursor_cell = answer
        await pilot.press("enter")
        assert app.search_run.k == 3 and app.search_run.current_node() == answer
        assert stats(app)[1].startswith(f"Right: ({answer[0]},{answer[1]}) was the queue's "
                                        "front · 1 of 1")
        app.cursor_cell = (5, 5)  # not on the frontier at all
        await pilot.press("enter")
        node = app.search_run.current_node()
        assert stats(app)[1].startswith(f"Not quite: ({node[0]},{node[1]}) came off the "
                                        "queue's front, not (5,5) · 1 of 2")
        await pilot.press("i")  # off: the order and the marks come back
        assert not app.quiz and any("▶" in line for line in panel_text(app))


@sync
async def test_under_dfs_the_answer_is_the_stacks_top() -> None:
    app = tutorial_app("dfs")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("i")
        assert "(it is the stack's top)" in stats(app)[1]
        for _ in range(3):
            top = app.search_run.gen_cell(app.search_run.frontier(0, 1)[0])
            app.cursor_cell = top
            await pilot.press("enter")
        assert "3 of 3" in stats(app)[1]


@sync
async def test_enter_does_nothing_outside_the_quiz() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("enter")
        assert app.search_run.k == 0

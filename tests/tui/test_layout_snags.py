"""Issue 42's layout snags, each at the size where a new teacher saw it: the comparison table
after a resize, the tutorial's step at 80x24, the trees' fragments, the replay's room, the
Code panel's room, the panes' cells level, the toasts and the key bar."""

from __future__ import annotations

from tests.helpers import TUTORIAL
from tests.textual_internals import composited, settle
from tests.tui.test_app import sync, tutorial_app, wait_until
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.model.replay_jumps import LOCKSTEP_SHORT
from tui_search.tui.widgets.key_bar import KeyBar


def toasts(app) -> list[str]:
    """The text of each notification on screen now."""
    return [str(toast.render()) for toast in app.screen.query("Toast")]


# -- toasts -----------------------------------------------------------------------------------
@sync
async def test_b_pressed_four_times_shows_one_toast_the_last() -> None:
    """Four presses of b: one toast, saying the brush the last press picked (a note of the
    same kind replaces the one before; they piled up over the map)."""
    app = tutorial_app()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await pilot.press("b", "b", "b", "b")
        brush = app.session.edits.brush
        last = "Terrain brush off" if brush is None else f"cost {brush:g}"
        await wait_until(pilot, lambda: len(toasts(app)) == 1 and last in toasts(app)[0])
        await pilot.press("a", "a")  # another kind: its own toast, replaced in turn
        await wait_until(pilot, lambda: [t for t in toasts(app) if "Cell labels" in t]
                         == ["Cell labels: none"])


# -- the key bar ------------------------------------------------------------------------------
@sync
async def test_the_key_bar_sets_word_keys_apart_and_the_lockstep_line_has_a_verb() -> None:
    """A lesson's section keys read ``pgdn/pgup Lesson`` (they read ``pgdnpgup``); keys of a
    character each still read as a row (``np Step``); the lockstep's short line at 80x24
    says what c does (``c back to one``, not ``c one``) on one row."""
    from tests.tui.test_lesson import lesson_app

    app = lesson_app("choices")
    async with app.run_test(size=(80, 24)) as pilot:
        bar = app.main.query_one(KeyBar)
        await wait_until(pilot, lambda: "pgdn/pgup Lesson" in bar.render_line(0).text)
        assert "np Step" in bar.render_line(0).text
    assert LOCKSTEP_SHORT.endswith("· c back to one") and len(LOCKSTEP_SHORT) <= 78
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    async with app.run_test(size=(80, 24)) as pilot:
        stats = app.main.stats
        await wait_until(pilot, lambda: any("c back to one" in row
                                            for row in stats.shown_lines()))
        assert not any(row.rstrip().endswith("c one") for row in stats.shown_lines())


# -- the comparison table after a resize ------------------------------------------------------
def screen_text(app: SearchApp) -> list[str]:
    """The terminal as painted, a line of text a row."""
    return ["".join(text for text, _ in line) for line in composited(app)]


@sync
async def test_compare_at_the_end_then_a_resize_to_120_by_40_shows_the_table_filled() -> None:
    """``--compare bfs,dfs`` at 80x24 (no room for the table), ``end``, then the window
    dragged to 120x40: the table has its rows at once, and the screen is the one a start at
    120x40 shows (the table was an empty box over a 5-row gap until the next step)."""
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    fresh = SearchApp(load_map(TUTORIAL), path=TUTORIAL, compare="bfs,dfs")
    async with fresh.run_test(size=(120, 40)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: fresh.session.at_end())
        await settle(pilot)
        expected = screen_text(fresh)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.at_end())
        assert app.main._table.made is None or not app.main.table.display
        await pilot.resize_terminal(120, 40)
        await wait_until(pilot, lambda: app.main._table.made is not None
                         and app.main.table.display and app.main.table.region.height > 0)
        table = app.main.table
        assert [line.split()[0] for line in table.text_lines[1:3]] == ["BFS", "DFS"]
        await settle(pilot)
        await wait_until(pilot, lambda: screen_text(app) == expected)

"""Issue 42's layout snags, each at the size where a new teacher saw it: the comparison table
after a resize, the tutorial's step at 80x24, the trees' fragments, the replay's room, the
Code panel's room, the panes' cells level, the toasts and the key bar."""

from __future__ import annotations

from tests.helpers import TUTORIAL
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

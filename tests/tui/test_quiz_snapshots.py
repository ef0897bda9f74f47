"""Picture of the quiz (look at it as a PNG before accepting a change)."""

from __future__ import annotations

from tests.tui.test_app import tutorial_app


def test_the_quiz_after_a_wrong_answer(snap_compare) -> None:
    """BFS on the tutorial, quiz on after two steps, enter with the cursor on the start: the
    status says 'Not quite: (0,2) came off the queue's front, not (0,0) · 0 of 1'; the queue's
    panel is titled '· order hidden' and lists its entries by cell, with no ▶."""
    assert snap_compare(tutorial_app(), press=["n", "n", "i", "enter"], terminal_size=(100, 30))


def test_the_quiz_with_an_entry_picked(snap_compare) -> None:
    """BFS on the tutorial, quiz on after two steps, a click on the second entry listed,
    (1,2) SE: its line is marked across the panel (the pick) and the map's cursor is on that
    cell; no step is taken yet (still step 2, the question in the status line)."""

    async def pick(pilot) -> None:
        await pilot.press("n", "n", "i")
        # past the border and the count: the first entry
        await pilot.click(pilot.app.main.panes[0].frontier, offset=(4, 3))
        await pilot.pause()

    assert snap_compare(tutorial_app(), run_before=pick, terminal_size=(100, 30))

"""Picture of the quiz (look at it as a PNG before accepting a change)."""

from __future__ import annotations

from tests.tui.test_app import tutorial_app


def test_the_quiz_after_a_wrong_answer(snap_compare) -> None:
    """BFS on the tutorial, quiz on after two steps, enter with the cursor on the start: the
    status says 'Not quite: (0,2) came off the queue's front, not (0,0) · 0 of 1'; the queue's
    panel is titled '· order hidden' and lists its entries by cell, with no ▶."""
    assert snap_compare(tutorial_app(), press=["n", "n", "i", "enter"], terminal_size=(100, 30))

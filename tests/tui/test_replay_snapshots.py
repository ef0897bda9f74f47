"""A picture of ``--replay`` (look at it as a PNG before accepting a change)."""

from __future__ import annotations

from tests.tui.test_replay import replay_app


def test_replay_at_its_first_difference(snap_compare) -> None:
    """The student's BFS (order N,W,S,E, the newest entry taken at step 9) left, the app's BFS
    right, both at step 9 after d: the trace's line names its file ('your trace · trace.jsonl'),
    BFS's its moves ('BFS · moves N,W,S,E'); the trace's (2,1) and BFS's (0,5) marked on each map,
    filled violet with white glyphs (the expanding ◉ kept); the status line says 'step 9: your trace
    expands (2,1); BFS expands (0,5) · d: to it and back'; the left frontier is titled 'Frontier, as
    added', its entries oldest first with no ▶, its legend that the trace gives no discipline; the
    right is BFS's queue."""
    assert snap_compare(replay_app(), press=["d"], terminal_size=(120, 40))



def test_replay_at_its_first_difference_in_the_light_theme(snap_compare) -> None:
    """The same in the light (projector) theme: the two marked cells violet, apart from the
    dark blue of the cell being expanded, the pale blue expanded cells and the dark obstacles."""
    assert snap_compare(replay_app(theme="light"), press=["d"], terminal_size=(120, 40))

"""What the status lines say, from the session alone (no Textual): one search's counts and
narration, several searches' names and the lockstep's sentence, the note and the playback,
"done at step k", the inadmissible warning, and what goes first at narrow widths."""

from __future__ import annotations

from tests.helpers import TUTORIAL
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.heuristics import INADMISSIBLE
from tui_search.tui.model.session import LOCKSTEP, LOCKSTEP_SHORT, Session
from tui_search.tui.view.pieces import lay_out, line_text, text_of
from tui_search.tui.view.status_lines import (
    MAX_ROWS,
    PANE_ROWS,
    Status,
    screen_status,
    search_status,
)

BOUND = "at most 7⁸ = 5,764,801"


def tutorial(**options: object) -> Session:
    return Session(load_map(TUTORIAL), TUTORIAL, **options)  # type: ignore[arg-type]


def to_end(run: Run) -> Run:
    run.advance()
    assert run.total is not None
    run.goto(run.total)
    return run


def texts(status: Status) -> list[str]:
    """The counts, then the narration, each unwrapped."""
    return [line_text(line.pieces) for line in status.lines]


def rows(status: Status, width: int) -> list[str]:
    """The rows the lines take at ``width`` cells."""
    return [text_of(row) for row in lay_out(status.lines, width, status.max_rows)]


def test_one_search_the_screen_shows_its_run_s_counts_and_narration() -> None:
    status = screen_status(tutorial(), 100)
    assert texts(status) == [
        "BFS │ step 0/22 │ expanded 0 │ generated 1 │ queue 1 (peak 1) │ speed 5/s",
        "START (0,0) is on the queue. Press n to expand it."]
    assert status.max_rows == MAX_ROWS
    assert rows(status, 100) == texts(status)


def test_several_searches_the_screen_names_them_and_says_how_the_lockstep_goes() -> None:
    session = tutorial(compare="bfs,dfs")
    wide, narrow = screen_status(session, len(LOCKSTEP) + 2), screen_status(session, 80)
    assert texts(wide) == ["compare BFS · DFS │ speed 5/s", LOCKSTEP]
    assert texts(narrow) == ["compare BFS · DFS │ speed 5/s", LOCKSTEP_SHORT]
    assert wide.max_rows == MAX_ROWS
    assert len(rows(narrow, 78)) == 2  # the short sentence takes one row


def test_the_note_replaces_the_narration_or_the_sentence_and_playing_says_so() -> None:
    for session in (tutorial(), tutorial(compare="bfs,dfs")):
        session.note = "Computing the end…"
        session.playing = True
        status = screen_status(session, 100)
        assert texts(status)[1] == "Computing the end…"
        assert status.lines[1].pieces[0].parts == [("Computing the end…", "stats--note")]
        assert texts(status)[0].endswith("│ ▶ playing 5/s")


def test_no_start_or_goal_the_screen_names_the_search_and_says_what_is_missing() -> None:
    grid = load_map(TUTORIAL)
    grid.goal = None
    session = Session(grid, TUTORIAL, algorithm="dfs")
    assert session.run is None
    assert texts(screen_status(session, 100)) == [
        "DFS │ speed 5/s", "Place a start (s) and a goal (g) to search"]


def test_a_pane_among_several_says_done_at_step_k_and_its_map_comes_first() -> None:
    run = to_end(tutorial().runs[0])
    pane = search_status(run, "BFS", in_pane=True, done=True)
    alone = search_status(run, "BFS", in_pane=False)
    assert pane.max_rows == PANE_ROWS and alone.max_rows == MAX_ROWS
    assert texts(pane)[0].startswith("BFS │ done at step 22 │ step 22/22")
    assert "done at step" not in texts(alone)[0]
    assert texts(pane)[1] == texts(alone)[1] and texts(alone)[1].endswith(BOUND)
    # narrow: a pane's bound gives way to the counts; alone, it never goes; the path's moves
    # and cost never go (issue 20), nor the step and the nodes expanded: they take more rows
    # than PANE_ROWS (the queue's size goes, short form and all, where that saves a row)
    assert rows(pane, 30) == ["BFS │ step 22/22 │ expanded 22", "Goal (5,2) found from (5,1) ·",
                              "path: 7 moves, cost 8.66 (the", "lowest)"]
    assert rows(pane, 21) == ["BFS │ step 22/22", "expanded 22 │ queue 2",
                              "Goal (5,2) found from", "(5,1) · path: 7",
                              "moves, cost 8.66 (the", "lowest)"]
    assert rows(alone, 30)[1:] == ["Goal (5,2) found from (5,1) ·",
                                   "path: 7 moves, cost 8.66 (the",
                                   "lowest) · generated 24 of at", "most 7⁸ = 5,764,801"]


def test_an_inadmissible_heuristic_is_always_said() -> None:
    session = tutorial(algorithm="astar", semantics=Semantics(heuristic="manhattan"))
    for status in (screen_status(session, 100),
                   search_status(session.run, "A*", in_pane=True)):
        assert f"A* · heuristic manhattan · {INADMISSIBLE} │ step 0/13" in texts(status)[0]
        for width in (20, 40, 60):  # rank 0: never dropped, wrapped word by word
            assert INADMISSIBLE.split()[-1] in " ".join(rows(status, width))


def test_at_narrow_widths_the_figures_a_student_can_do_without_go_first() -> None:
    session = tutorial(algorithm="astar")
    for _ in range(5):
        session.step(forward=True)
    session.playing = True
    status = screen_status(session, 40)
    assert texts(status)[0].endswith("│ priority queue 5 (peak 5) │ ▶ playing 5/s")
    for width in (30, 40, 50):
        shown = rows(status, width)
        assert len(shown) <= MAX_ROWS
        assert "playing" not in " ".join(shown)  # the playback goes first
        assert "step 5/16" in shown[0] and "expanded 5" in " ".join(shown)  # never go
        assert " ".join(shown).endswith(texts(status)[1].split()[-1])  # the narration whole
    # the frontier's size stays while the peak, the discarded nodes ... make room
    assert "priority queue 5 │" not in rows(status, 50)[1]
    assert rows(status, 50)[1].endswith("generated 10 │ priority queue 5")
    assert rows(status, 30)[0] == "A* │ step 5/16 │ expanded 5"  # then it goes too

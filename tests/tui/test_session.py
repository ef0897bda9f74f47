"""The session model without Textual: every search a pane, the lockstep, edits, the quiz, the
seek and the exercise, as plain unit tests (the screen only shows what these decide)."""

from __future__ import annotations

from tests.helpers import TUTORIAL
from tui_search.engine.course.exercise_file import built_in_exercise
from tui_search.engine.course.grading import grade
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.choices import DEFAULT_SEMANTICS
from tui_search.tui.model import playback
from tui_search.tui.model.seek import Seek
from tui_search.tui.model.session import DEFAULT_COMPARE, NEEDS_ENDPOINTS, Session


def tutorial(**options: object) -> Session:
    return Session(load_map(TUTORIAL), TUTORIAL, **options)  # type: ignore[arg-type]


def steps(session: Session) -> list[int]:
    return [run.k for run in session.runs]


def test_one_search_is_one_pane_and_c_compares_the_pick() -> None:
    session = tutorial()
    assert session.spec == "bfs" and session.labels == ["BFS"] and len(session.runs) == 1
    assert session.toggle_compare() is None
    assert session.spec == DEFAULT_COMPARE and session.labels == ["BFS", "DFS"]
    assert session.toggle_compare() is None
    assert session.labels == ["BFS"] and session.comparison == DEFAULT_COMPARE


def test_an_algorithm_key_replaces_one_search_and_adds_or_takes_out_one_of_several() -> None:
    session = tutorial()
    assert session.choose_algorithm("dfs") is None and session.labels == ["DFS"]
    session.show_searches("bfs,dfs")
    assert session.choose_algorithm("astar") is None and session.labels == ["BFS", "DFS", "A*"]
    assert session.choose_algorithm("bfs") is None and session.labels == ["DFS", "A*"]
    warning = session.choose_algorithm("dfs")
    assert warning is not None and "two searches at least" in warning
    assert session.labels == ["DFS", "A*"]
    session.show_searches("dfs,astar,bfs,ucs")
    warning = session.choose_algorithm("greedy")
    assert warning is not None and "four searches at most" in warning and len(session.runs) == 4


def test_a_refused_spec_changes_nothing() -> None:
    session = tutorial()
    error = session.show_searches("bfs,nosuch")
    assert error is not None and error.startswith("Cannot compare bfs,nosuch")
    assert session.spec == "bfs" and session.comparison == DEFAULT_COMPARE


def test_the_visit_rule_falls_back_where_it_does_not_apply() -> None:
    session = tutorial(semantics=DEFAULT_SEMANTICS.replace(visit="expand"))
    session.choose_algorithm("iddfs")  # the setting stays for the next search it applies to
    assert session.semantics.visit == "expand" and "does not apply to ID" in session.note
    assert session.contenders[0].semantics.visit == "generate"
    session.new_runs()  # said once: an edit or r shows the narration again
    assert session.note == "" and session.contenders[0].semantics.visit == "generate"
    session.choose_algorithm("bfs")
    assert session.contenders[0].semantics.visit == "expand" and session.note == ""
    session = tutorial(semantics=DEFAULT_SEMANTICS.replace(visit="expand"), compare="bfs,iddfs")
    assert "Visit on expand does not apply to ID" in session.note
    assert [c.semantics.visit for c in session.contenders] == ["expand", "generate"]


def test_a_choice_a_search_names_itself_is_not_a_setting_that_did_not_apply() -> None:
    """``biastar:first-meeting`` and ``astar:w=2`` choose their own rule and weight: no note
    says the settings did not apply to them; a stopping rule set for all still does not apply
    to BFS, and the note says so."""
    from tui_search.tui.model.searches import searches_of

    for spec in ("biastar:first-meeting,biastar", "astar:w=2,astar", "bibfs:smaller,bfs"):
        assert searches_of(spec, DEFAULT_SEMANTICS)[1] == ""
    note = searches_of("biastar,bfs", DEFAULT_SEMANTICS.replace(stop="first-meeting"))[1]
    assert note == "Some settings do not apply to BFS: their defaults there"


def test_lockstep_steps_every_run_forward_and_the_latest_back() -> None:
    session = tutorial(compare="bfs,dfs")
    for k in range(3):
        assert session.step(forward=True) == [(k, False), (k, False)]
    assert steps(session) == [3, 3]
    session.start_seek(to_end=True)
    while (seek := session.seek) is not None and seek.work() is not None:
        pass
    session.seek_done()
    assert steps(session) == [22, 7] and session.at_end()
    before = session.step(forward=False)
    assert before == [(22, True), (7, True)] and steps(session) == [21, 7]
    assert session.step(forward=True) == [(21, False), (7, True)] and steps(session) == [22, 7]
    assert session.step(forward=True) is None  # all at their ends: nothing moves


def test_an_edit_marks_the_map_and_restarts_every_run() -> None:
    session = tutorial(compare="bfs,dfs")
    session.step(forward=True)
    old = list(session.runs)
    session.move_cursor((1, 2))
    assert session.edits.toggle_wall(session.cursor) is None
    assert session.grid.is_blocked((1, 2)) and session.dirty
    assert steps(session) == [0, 0] and not set(session.runs) & set(old)
    assert session.title == "tutorial.txt · modified"
    refusal = session.edits.place("start", session.cursor)  # on the obstacle just made
    assert refusal == "Cannot put the start on an obstacle at (1,2)"
    assert not session.edits.paint((1, 2), wall=True)  # already an obstacle: no edit
    assert session.edits.paint((1, 2), wall=False) and not session.grid.is_blocked((1, 2))
    assert not session.move_cursor((99, 0)) and session.cursor == (1, 2)


def test_no_start_means_no_runs_and_a_note() -> None:
    grid = load_map(TUTORIAL)
    grid.start = None
    session = Session(grid)
    assert session.runs == [] and session.run is None and session.note == NEEDS_ENDPOINTS
    assert session.step(forward=True) is None


def test_the_quiz_scores_the_cursor_against_the_node_taken_off() -> None:
    session = tutorial()
    session.toggle_quiz()
    assert session.quiz.on and session.note.startswith("Quiz (0 of 0): which node comes off")
    session.move_cursor((0, 0))  # BFS takes the start off first
    assert session.answer() == [(0, False)]
    assert session.quiz.right == 1 and session.note.startswith("Right: (0,0)")
    session.move_cursor((5, 5))
    session.answer()
    assert (session.quiz.right, session.quiz.asked) == (1, 2)
    assert session.note.startswith("Not quite: (0,1) came off the queue's front, not (5,5)")
    session.toggle_quiz()
    assert not session.quiz.on and session.note == ""


def test_play_ticks_until_the_end_then_again_from_step_0() -> None:
    session = tutorial()
    assert session.play() is False and session.playing
    while session.playing:
        session.tick()
    assert session.at_end()
    assert session.play() is True  # at the end: back to step 0 first
    assert isinstance(session.seek, Seek)
    while (seek := session.seek) is not None and seek.work() is not None:
        pass
    session.seek_done()
    assert steps(session) == [0] and session.playing


def test_a_seek_says_how_far_it_is_and_stop_abandons_it() -> None:
    session = Session(Grid(30, 30, start=(0, 0), goal=(29, 29)), compare="iddfs,bfs")
    session.start_seek(to_end=True)
    assert session.seek is not None
    progress = session.seek.work(seconds=0.0)
    assert progress is not None and progress.startswith("IDDFS: computing the search…")
    assert progress.endswith("esc to stop")
    session.note = progress
    session.stop()
    assert session.seek is None and session.note == "" and not session.at_end()


def test_the_exercise_verdict_is_the_headless_one() -> None:
    session = tutorial(exercise=1)
    assert session.verdict() == grade(built_in_exercise(1), session.grid, session.max_steps)
    session.cycle_exercise()
    assert session.exercise is built_in_exercise(2)
    session.cycle_exercise()
    assert session.exercise is None


def test_the_settings_pick_what_c_compares_and_apply_their_rules() -> None:
    session = tutorial(compare="bfs,dfs")
    corners = DEFAULT_SEMANTICS.replace(corners="never")
    session.choose_settings(corners, "bfs,ucs")
    assert session.labels == ["BFS", "UCS"] and session.comparison == "bfs,ucs"
    assert all(c.semantics.corners == "never" for c in session.contenders)
    session.toggle_compare()
    session.choose_settings(corners, "dfs,astar")  # one pane: only what c compares changes
    assert session.labels == ["BFS"] and session.comparison == "dfs,astar"


def test_x_cycles_through_an_exercise_file_given_at_start() -> None:
    from tests.helpers import ROOT
    from tui_search.engine.course.exercise_file import load_exercise

    mine = load_exercise(ROOT / "tests" / "data" / "exercises" / "greedy-not-optimal.toml")
    session = tutorial(exercise=mine)
    assert session.verdict().exercise is mine and not session.verdict().solved
    seen = []
    for _ in range(4):
        session.cycle_exercise()
        seen.append(session.exercise)
    assert seen == [built_in_exercise(1), built_in_exercise(2), None, mine]


# -- checks that drove the app with Pilot, though they need no screen ------------------------
def to_the_end(session: Session) -> None:
    """What ``end`` does: every run to its end, the seek's slices one after another."""
    session.start_seek(to_end=True)
    while (seek := session.seek) is not None and seek.work() is not None:
        pass
    session.seek_done()


def test_an_obstacle_on_the_path_restarts_the_run_and_the_new_run_goes_round_it() -> None:
    session = tutorial()
    to_the_end(session)
    assert (1, 2) in session.run.path()
    session.cursor = (1, 2)
    assert session.edits.toggle_wall(session.cursor) is None  # o
    assert session.grid.is_blocked((1, 2)) and session.dirty
    assert session.run.k == 0 and session.run.grid.is_blocked((1, 2))
    to_the_end(session)
    assert (1, 2) not in (session.run.path() or [])
    assert session.edits.toggle_wall(session.cursor) is None
    assert not session.grid.is_blocked((1, 2))


def test_start_and_goal_moved_restart_the_search_between_them() -> None:
    session = tutorial()
    session.step(forward=True)
    session.step(forward=True)
    assert session.edits.place("start", (0, 2)) is None  # s
    assert session.grid.start == (0, 2) and session.dirty
    assert session.run.k == 0 and session.run.grid.start == (0, 2)
    assert session.edits.place("goal", (1, 2)) is None  # g
    assert session.grid.goal == (1, 2)
    to_the_end(session)
    assert session.run.path() == [(0, 2), (1, 2)]


def test_start_and_goal_put_on_costed_cells_keep_their_costs() -> None:
    """The issue's rule: a move costs the cell it enters, the start's own cost is never paid,
    and a start or goal placed on a digit keeps that cell's cost while the app runs."""
    from tui_search.engine.maps.load import parse_map_text

    session = Session(parse_map_text("S9.4G\n"), algorithm="ucs")
    assert session.edits.place("start", (1, 0)) is None  # the start on the 9
    assert session.edits.place("goal", (3, 0)) is None  # the goal on the 4
    assert (session.grid.start, session.grid.goal) == ((1, 0), (3, 0))
    assert (session.grid.cost((1, 0)), session.grid.cost((3, 0))) == (9.0, 4.0)
    to_the_end(session)
    out = session.run.outcome()
    assert out.found and out.path == [(1, 0), (2, 0), (3, 0)]
    assert out.cost == 5.0  # 1 into (2,0), 4 into the goal; the start's 9 not paid
    assert session.edits.place("start", (0, 0)) is None  # the start back: the 9 is still there
    to_the_end(session)
    assert session.run.outcome().cost == 14.0  # 9 + 1 + 4
    assert session.grid.cost((1, 0)) == 9.0


def test_the_benchmark_optimum_holds_until_the_map_is_edited() -> None:
    from tests.helpers import MOVINGAI
    from tui_search.engine.maps.scenarios import load_scenario
    from tui_search.engine.search.choices import Semantics

    arena = MOVINGAI / "arena.map"
    scen = load_scenario(arena.with_suffix(".map.scen"), 5)
    grid = load_map(arena, start=scen.start, goal=scen.goal)
    session = Session(grid, arena, algorithm="ucs", semantics=Semantics(corners="never"),
                      optimal_cost=scen.optimal_length)
    assert session.run.known_lowest == scen.optimal_length
    to_the_end(session)
    assert session.run.outcome().cost == scen.optimal_length
    assert session.edits.toggle_wall((0, 0)) is None  # an edit: the figure no longer applies
    assert session.run.known_lowest is None


def test_play_at_a_high_speed_runs_every_pane_in_lockstep_to_the_end() -> None:
    session = tutorial(compare="bfs,dfs")
    for _ in range(7):  # + seven times: many steps a tick
        session.set_speed(session.speed_index + 1)
    assert playback.steps_per_tick(session.speed) > 1
    assert session.play() is False
    while session.playing:  # what the playback timer calls
        session.tick()
    assert steps(session) == [22, 7]


def test_under_dfs_the_quiz_s_answer_is_the_stack_s_top() -> None:
    session = tutorial(algorithm="dfs")
    session.toggle_quiz()
    assert "(it is the stack's top)" in session.note
    for _ in range(3):
        session.cursor = session.run.nodes.cell(session.run.now.frontier(0, 1)[0])
        session.answer()
    assert "3 of 3" in session.note


def test_the_quiz_in_compare_mode_asks_of_the_left_pane_and_steps_all() -> None:
    session = tutorial(compare="dfs,bfs")
    session.toggle_quiz()
    assert session.answer() is not None  # the cursor is on the start: it comes off first
    assert session.quiz.asked == 1 and session.quiz.right == 1 and steps(session) == [1, 1]
    assert "stack's top" in session.note

"""The tutorial's exercises as live challenges in the app (--exercise N, x, the palette)."""

from __future__ import annotations

import threading

import pytest

from tests.tui.test_app import MAPS, TUTORIAL, sync, tutorial_app, wait_until
from tui_search.cli.main import main
from tui_search.engine.course.exercise_file import built_in_exercise
from tui_search.engine.course.grading import LIVE_CELLS, grade
from tui_search.engine.maps.grid import Grid
from tui_search.engine.maps.load import load_map
from tui_search.tui.app import SearchApp
from tui_search.tui.screens import exercise_check
from tui_search.tui.widgets.challenge import ChallengePanel

SIZE = (120, 36)


def number(app: SearchApp) -> int | None:
    """The tutorial's exercise shown (None: none, or a file's)."""
    return app.session.exercise.number if app.session.exercise is not None else None


def challenge(app: SearchApp) -> ChallengePanel:
    return app.main.challenge


def shown(panel: ChallengePanel) -> bool:
    """Shown: mounted (it is, from the first time it shows) and displayed."""
    return panel.is_mounted and panel.display


@sync
async def test_moving_the_goal_solves_exercise_one_the_moment_it_does() -> None:
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL, exercise=1)
    async with app.run_test(size=SIZE) as pilot:
        panel = challenge(app)
        assert panel.display and panel.border_title == "Exercise 1"
        assert "Not solved yet: BFS expanded 22 nodes, DFS 7" in panel.text
        app.main.views[0].set_cursor((0, 4))
        app.session.cursor = (0, 4)
        await pilot.press("g")
        assert panel.verdict.solved and "Solved ✓ BFS expanded 5 nodes, DFS 18" in panel.text
        assert "Hint" not in panel.text  # only the goal moved
        # an edit that unsolves it says so
        app.session.cursor = (2, 0)
        app.main.views[0].set_cursor((2, 0))
        await pilot.press("g")
        assert not panel.verdict.solved and "Not solved any more" in panel.text


@sync
async def test_exercise_one_hints_when_more_than_the_goal_changed() -> None:
    app = SearchApp(load_map(MAPS / "exercise1-bfs-wins.txt"), exercise=1)
    async with app.run_test(size=SIZE):
        assert challenge(app).verdict.solved
        assert "Hint: the exercise changes only the goal" in challenge(app).text


@sync
async def test_x_cycles_the_exercises_and_hides_the_panel() -> None:
    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        assert not shown(challenge(app))
        await pilot.press("x")
        assert number(app) == 1 and shown(challenge(app))
        await pilot.press("x")
        assert number(app) == 2 and "Exercise 2" == challenge(app).border_title
        assert "Not solved yet: both paths have 7 moves" in challenge(app).text
        await pilot.press("x")
        assert app.session.exercise is None and not shown(challenge(app))


@sync
async def test_exercise_two_on_its_shipped_solution_and_a_big_map() -> None:
    app = SearchApp(load_map(MAPS / "exercise2-dfs-longer.txt"), exercise=2)
    async with app.run_test(size=SIZE):
        assert challenge(app).verdict.solved
        assert "BFS's path has 5 moves, DFS's 8" in challenge(app).text


@sync
async def test_a_big_map_is_checked_in_the_background_once_the_edits_pause(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Over LIVE_CELLS cells the check runs in a thread: "Checking" at once, the verdict the
    headless grading gives once it is done; an edit meanwhile makes the old verdict stale (not
    shown) and a new check gives the edited map's.  The pause before a check ends when the
    test opens a gate (on a busy machine the app can take longer to start than the pause)."""
    gate = threading.Event()
    monkeypatch.setattr(exercise_check, "sleep", lambda seconds: gate.wait(60))
    grid = Grid(150, 150, start=(0, 0), goal=(149, 149))
    assert grid.width * grid.height > LIVE_CELLS
    big = SearchApp(grid, exercise=1)
    async with big.run_test(size=SIZE) as pilot:
        assert challenge(big).verdict is None and "Checking" in challenge(big).text
        gate.set()
        await wait_until(pilot, lambda: challenge(big).verdict is not None)
        want = grade(built_in_exercise(1), grid.copy())
        assert challenge(big).verdict == want
        assert f"{want.outcomes[0][2].expanded:,}" in challenge(big).text
        # two edits in a row (the goal moved next to the start, then one further): the first
        # one's check is cancelled or its verdict stale; the verdict is the last map's
        gate.clear()
        await pilot.press("right", "g")
        assert challenge(big).verdict is None and "Checking" in challenge(big).text
        await pilot.press("right", "g")
        assert big.session.grid.goal == (2, 0)
        gate.set()
        await wait_until(pilot, lambda: challenge(big).verdict is not None)
        edited = grade(built_in_exercise(1), big.session.grid.copy())
        assert challenge(big).verdict == edited and edited != want


def test_exercise_without_headless_opens_the_app(monkeypatch) -> None:
    seen = {}

    def fake_run(self, *args, **kwargs):
        seen["exercise"] = self.session.exercise.number
        seen["title"] = self.session.map_name

    monkeypatch.setattr(SearchApp, "run", fake_run)
    assert main(["--exercise", "2"]) == 0
    assert seen == {"exercise": 2, "title": "tutorial (built-in)"}
    teacher = MAPS.parent / "tests" / "data" / "exercises" / "greedy-not-optimal.toml"
    monkeypatch.setattr(SearchApp, "run", lambda self, *a, **k: seen.update(
        title=self.session.exercise.title))
    assert main(["--exercise", str(teacher)]) == 0
    assert seen["title"] == "Greedy is not optimal"


@sync
async def test_the_palette_turns_the_exercises_on_and_off() -> None:
    """As a user would: ctrl+p, type the command's name, enter."""
    from tests.tui.test_themes import palette_run

    app = tutorial_app()
    async with app.run_test(size=SIZE) as pilot:
        assert app.session.exercise is None and not shown(challenge(app))
        await palette_run(pilot, "Exercise 1")
        assert number(app) == 1 and shown(challenge(app))
        assert challenge(app).border_title == "Exercise 1"
        assert "Not solved yet: BFS expanded 22 nodes, DFS 7" in challenge(app).text
        await palette_run(pilot, "Exercise 2")
        assert number(app) == 2 and challenge(app).border_title == "Exercise 2"
        await palette_run(pilot, "Exercise: off", best=True)  # exercise 1's quote matches too
        assert app.session.exercise is None and not shown(challenge(app))


@sync
async def test_a_teachers_exercise_fails_an_edit_it_does_not_allow() -> None:
    from tui_search.engine.course.exercise_file import load_exercise

    teacher = load_exercise(MAPS.parent / "tests" / "data" / "exercises" /
                            "greedy-not-optimal.toml")  # edits = ["obstacles"]
    app = SearchApp(teacher.grid.copy(), exercise=teacher)
    async with app.run_test(size=SIZE) as pilot:
        panel = challenge(app)
        assert panel.display and "Greedy is not optimal" in str(panel.border_title)
        app.main.views[0].set_cursor((0, 1))
        app.session.cursor = (0, 1)
        await pilot.press("s")  # the start moved: not an edit this exercise allows
        await wait_until(pilot, lambda: "changed the start" in panel.text)
        assert not panel.verdict.solved
        assert "changed the start, which the exercise does not allow" in panel.text


@sync
async def test_a_map_the_searches_gave_up_on_is_not_graded(tmp_path) -> None:
    """Under --max-steps the searches give up: "Not graded", never "not solved" or "no path"."""
    long = tmp_path / "long.txt"
    long.write_text("S\n" + ".\n" * 50 + "G\n")
    app = SearchApp(load_map(long), path=long, exercise=1, max_steps=10)
    async with app.run_test(size=SIZE) as pilot:
        panel = challenge(app)
        await wait_until(pilot, lambda: "gave up" in panel.text)
        assert "Not graded: BFS and DFS gave up at 10 steps" in panel.text
        assert "not solved" not in panel.text.lower() and "no path" not in panel.text


MAZE = MAPS.parent / "tests" / "data" / "exercises" / "maze-4-connected.toml"


@sync
async def test_an_exercise_s_rules_are_the_panes_and_the_panel_names_them() -> None:
    """``--exercise maze-4-connected.toml``: the panes run under its rules (N, E, S, W; no
    corner cut), the panel says them; ``x`` to exercise 1 puts the tutorial's back, saying
    so, and back round to the file its rules again."""
    from tui_search.cli.main import build_app
    from tui_search.cli.parse import parse_options

    app = build_app(parse_options(["--exercise", str(MAZE)]))
    async with app.run_test(size=SIZE) as pilot:
        panel = challenge(app)
        assert panel.border_title == "The long way round"
        assert "Rules: moves N,E,S,W · corners: never" in panel.text
        assert "Not solved yet: BFS's path has 24 moves, DFS's 28" in panel.text
        assert [r.semantics.order for r in app.session.runs] == [("N", "E", "S", "W")]
        await pilot.press("end")
        await wait_until(pilot, lambda: app.session.runs[0].at_end)
        assert app.session.runs[0].outcome().length == 24  # as the challenge counts it
        await pilot.press("x")
        assert number(app) == 1 and "Rules" not in panel.text
        assert app.session.semantics.is_default and app.session.runs[0].k == 0
        assert app.session.note == "The searches run under Exercise 1's rules: the tutorial's"
        await pilot.press("x", "x", "x")
        assert app.session.exercise is not None and app.session.exercise.path == str(MAZE)
        assert app.session.semantics.corners == "never"


@sync
async def test_a_lesson_shows_an_exercise_file_beside_it(tmp_path) -> None:
    from tui_search.engine.course.lesson import read_lesson

    (tmp_path / "maze.toml").write_text(MAZE.read_text())
    (tmp_path / "lesson.md").write_text("# Mazes\n\n## Four moves\n\n```lesson\n"
                                        "exercise: maze.toml\n```\n\nMove the goal.\n")
    app = SearchApp(load_map(TUTORIAL), path=TUTORIAL,
                    lesson=read_lesson(tmp_path / "lesson.md"))
    async with app.run_test(size=SIZE) as pilot:
        panel = challenge(app)
        await wait_until(pilot, lambda: shown(panel))
        assert panel.border_title == "The long way round"
        assert "Rules: moves N,E,S,W · corners: never" in panel.text
        assert "Not solved yet: BFS's path has 24 moves, DFS's 28" in panel.text  # its map
        assert app.session.map_name == "maze.toml's map"
        assert app.session.runs[0].semantics.order == ("N", "E", "S", "W")

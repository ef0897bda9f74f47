"""The command line's comparisons (``--compare``) and exercise grading (``--exercise``)."""

from __future__ import annotations

import json

import pytest

from tests.helpers import MAPS, ROOT
from tests.test_cli import TUTORIAL, run_cli
from tui_search.engine.maps.load import load_map
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.compare import comparison, parse_compare, summary_sentence

SOLUTIONS = {1: ["exercise1-bfs-wins.txt", "exercise1-goal-moved.txt"],
             2: ["exercise2-dfs-longer.txt"]}

GREEDY_FILE = ROOT / "tests" / "data" / "exercises" / "greedy-not-optimal.toml"


def test_the_compare_json_is_the_single_runs_in_order(capsys) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", "--json", "--compare",
                             "dfs,bfs,astar:manhattan")
    assert code == 0 and err == ""
    runs = json.loads(out)["runs"]
    singles = []
    for argv in (["-a", "dfs"], ["-a", "bfs"], ["-a", "astar", "--heuristic", "manhattan"]):
        _, single, _ = run_cli(capsys, TUTORIAL, "--headless", "--json", *argv)
        singles.append(json.loads(single))
    assert runs == singles


def test_the_compare_table_marks_the_fewest_expanded_and_the_cheapest(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--compare", "bfs,dfs")
    lines = out.splitlines()
    assert code == 0 and lines[0] == "Comparison on " + TUTORIAL + ":"
    bfs = next(line for line in lines if line.strip().startswith("BFS "))
    dfs = next(line for line in lines if line.strip().startswith("DFS "))
    assert "22 " in bfs and "7 *" in dfs and "22 *" not in bfs
    assert lines[-1] == "  BFS expanded 22 nodes, DFS 7; both paths have 7 moves"


@pytest.mark.parametrize(("name", "code"), [("no-path.txt", 1), ("tutorial.txt", 0)])
def test_compare_exits_1_when_any_run_finds_no_path(capsys, name, code) -> None:
    got, _, _ = run_cli(capsys, str(MAPS / name), "--headless", "--compare", "bfs,dfs")
    assert got == code


def test_compare_exits_3_when_any_run_gives_up(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--compare", "bfs,iddfs",
                           "--max-steps", "5")
    assert code == 3 and "gave up" in out


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["--compare", "bfs"], "compare two to four searches, not 1"),
        (["--compare", "bfs,dfs,ucs,astar,greedy"], "compare two to four searches, not 5"),
        (["--compare", "bfs:octile,dfs"], "'bfs:octile': bfs uses no heuristic"),
        (["--compare", "astar:taxi,dfs"], "unknown heuristic"),
        (["--compare", "bfs,dijkstra"], "unknown algorithm 'dijkstra'"),
        (["--compare", "bfs,astar", "--visit", "expand"], "the visit rule does not apply to A*"),
        (["--compare", "bfs,dfs", "-a", "dfs"], "--compare chooses the searches: leave out -a"),
        (["--compare", "bfs,dfs", "--trace", "-"], "--trace is for one search"),
        (["--compare", "bfs,dfs", "--exercise", "1"],
         "--compare and --exercise: choose one (the exercise compares BFS and DFS itself)"),
        (["--compare", "bfs,dfs", "--exercise", str(GREEDY_FILE)],
         "--compare and --exercise: choose one (the exercise compares Greedy and A* itself)"),
        (["--exercise", ""], "--exercise: the name is empty (give 1, 2 or an exercise file)"),
        (["--exercise", " "], "--exercise: the name is empty"),
        (["--exercise", "1", "--corners", "never"], "leave out --corners"),
        (["--exercise", "2", "--order", "N,W,S,E"],
         ("--exercise grades under the exercise's own rules: leave out --order (an exercise "
         "file sets its rules: docs/04-exercises.md)")),
        (["--exercise", "3"], "--exercise 3: the tutorial has exercises 1 and 2"),
    ],
)
def test_refused_combinations(capsys, argv, expected) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", *argv)
    assert code == 2 and out == ""
    assert expected in err and err.count("\n") == 1


def test_compare_without_headless_refuses_bad_searches_before_the_app_starts(capsys) -> None:
    code, _, err = run_cli(capsys, TUTORIAL, "--compare", "bfs,nope")
    assert code == 2 and "--compare 'bfs,nope'" in err and err.count("\n") == 1


@pytest.mark.parametrize("exercise", [1, 2])
def test_the_shipped_solutions_solve_their_exercise_and_the_tutorial_neither(
        capsys, exercise) -> None:
    for name in SOLUTIONS[exercise]:
        code, out, _ = run_cli(capsys, str(MAPS / name), "--headless", "--exercise",
                               str(exercise))
        assert code == 0 and f"exercise {exercise} solved" in out, name
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--exercise", str(exercise))
    assert code == 1 and f"exercise {exercise} not solved" in out


def test_exercise_one_hints_when_more_than_the_goal_moved(capsys) -> None:
    _, out, _ = run_cli(capsys, str(MAPS / "exercise1-goal-moved.txt"), "--headless",
                        "--exercise", "1")
    assert "hint" not in out
    _, out, _ = run_cli(capsys, str(MAPS / "exercise1-bfs-wins.txt"), "--headless",
                        "--exercise", "1")
    assert "  hint: the exercise changes only the goal: here the map's size changed" in (
        out.splitlines())


def test_grading_a_map_with_no_path_and_a_bad_map(capsys, tmp_path) -> None:
    code, out, _ = run_cli(capsys, str(MAPS / "no-path.txt"), "--headless", "--exercise", "1")
    assert code == 1 and "not solved — no path to the goal" in out
    bad = tmp_path / "student.txt"
    bad.write_text("S..\n.x.\n..G\n")
    code, out, err = run_cli(capsys, str(bad), "--headless", "--exercise", "1")
    assert code == 2 and out == "" and f"{bad}:2:2" in err


def test_grading_a_search_that_gives_up_is_not_called_no_path(capsys, tmp_path) -> None:
    long = tmp_path / "long.txt"
    long.write_text("S\n" + ".\n" * 50 + "G\n")
    code, out, _ = run_cli(capsys, str(long), "--headless", "--exercise", "1",
                           "--max-steps", "10")
    assert code == 3 and "no path" not in out
    assert "exercise 1 not graded — BFS and DFS gave up at 10 steps" in out
    code, out, _ = run_cli(capsys, str(long), "--headless", "--exercise", "1", "--json",
                           "--max-steps", "10")
    assert code == 3 and json.loads(out)[0]["bfs"]["gave_up"] is True


def test_grading_json_gives_the_figures(capsys) -> None:
    code, out, _ = run_cli(capsys, str(MAPS / "exercise2-dfs-longer.txt"), "--headless",
                           "--json", "--exercise", "2")
    [result] = json.loads(out)  # a list, as for a folder of maps
    assert code == 0 and result["solved"] and result["exercise"] == 2
    assert result["bfs"]["moves"] == 5 and result["dfs"]["moves"] == 8


def test_the_sentence_in_the_tutorials_terms() -> None:
    grid = load_map(MAPS / "tutorial.txt")
    contenders = parse_compare("dfs,bfs")
    outcomes = [Run(grid, c.algorithm, c.semantics).outcome() for c in contenders]
    rows = comparison([c.label for c in contenders], outcomes)
    assert summary_sentence(rows) == "DFS expanded 7 nodes, BFS 22; both paths have 7 moves"
    assert [r.fewest_expanded for r in rows] == [True, False]
    assert [r.cheapest for r in rows] == [True, True]
    assert parse_compare("astar:manhattan,ucs", Semantics())[0].label == "A* (manhattan)"


def test_searches_that_gave_up_are_named_in_the_sentence(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--compare", "bfs,dfs",
                           "--max-steps", "3")
    assert code == 3
    assert "no path found, BFS, DFS stopped at the step limit" in out

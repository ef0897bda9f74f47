"""The command line's informed searches: -a ucs|greedy|astar, --heuristic, the benchmark's
optimal length beside the path's cost, and the combinations refused."""

from __future__ import annotations

import json

import pytest

from tests.helpers import MAPS, MOVINGAI
from tests.test_cli import TUTORIAL, run_cli

ARENA = [str(MOVINGAI / "arena.map"), "--scen", str(MOVINGAI / "arena.map.scen")]


def headless_json(capsys, *argv: str) -> dict:
    code, out, err = run_cli(capsys, *argv, "--headless", "--json")
    assert err == "" and code in (0, 1)
    return json.loads(out)


@pytest.mark.parametrize("key", ["ucs", "greedy", "astar"])
def test_each_informed_search_runs_headless(capsys, key: str) -> None:
    result = headless_json(capsys, TUTORIAL, "-a", key)
    assert result["algorithm"] == key and result["found"]
    assert result["semantics"]["goal_test"] == "expand"  # their default
    assert result["semantics"]["visit"] is None
    assert result["semantics"]["heuristic"] == (None if key == "ucs" else "octile")


def test_the_cheapest_path_beats_the_fewest_moves_on_exercise_one(capsys) -> None:
    exercise = str(MAPS / "exercise1-bfs-wins.txt")
    bfs = headless_json(capsys, exercise)
    astar = headless_json(capsys, exercise, "-a", "astar")
    assert round(bfs["cost"], 2) == 2.83 and round(astar["cost"], 2) == 2.0


def test_scen_gives_the_optimal_length_and_whether_it_was_met(capsys) -> None:
    """arena row 5: BFS (corner cutting allowed) takes SE, NE for 2.83; the benchmark's lowest
    under no corner cutting is 2.00, and UCS with --corners never meets it."""
    bfs = headless_json(capsys, *ARENA, "--scen-row", "5", "--corners", "never")
    assert bfs["optimal_length"] == 2.0 and bfs["optimal"] is False  # 2 moves, one diagonal
    cutting = headless_json(capsys, *ARENA, "--scen-row", "5")
    assert cutting["optimal_length"] == 2.0 and cutting["optimal"] is None  # not its rules
    four = headless_json(capsys, *ARENA, "--scen-row", "5", "--corners", "never",
                         "--order", "N,W,S,E")
    assert four["optimal"] is None
    ucs = headless_json(capsys, *ARENA, "--scen-row", "5", "-a", "ucs", "--corners", "never")
    assert ucs["optimal"] is True and abs(ucs["cost"] - ucs["optimal_length"]) < 1e-4
    plain = headless_json(capsys, TUTORIAL)
    assert "optimal" not in plain and "optimal_length" not in plain


def test_a_moved_start_or_goal_drops_the_rows_optimum(capsys) -> None:
    """The row's optimum is for its own start and goal: --goal moves one, and the output says
    nothing of the benchmark."""
    moved = headless_json(capsys, *ARENA, "--scen-row", "100", "--goal", "30,30",
                          "--corners", "never")
    assert "optimal" not in moved and "optimal_length" not in moved


def test_the_text_output_names_the_benchmark_and_an_inadmissible_heuristic(capsys) -> None:
    code, out, _ = run_cli(capsys, *ARENA, "--scen-row", "5", "--headless", "-a", "astar",
                           "--corners", "never")
    assert code == 0
    assert "  benchmark:    lowest cost 2.000: this path is optimal" in out.splitlines()
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "astar",
                           "--heuristic", "manhattan")
    lines = out.splitlines()
    assert "  semantics:    heuristic manhattan" in lines
    assert "  warning:      inadmissible heuristic: the path may not be optimal" in lines
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "astar",
                           "--heuristic", "manhattan", "--order", "N,W,S,E")
    assert "warning" not in out  # no diagonals: manhattan is admissible


def test_goal_test_on_generate_is_available_and_named(capsys) -> None:
    result = headless_json(capsys, TUTORIAL, "-a", "ucs", "--goal-test", "generate")
    assert result["semantics"]["goal_test"] == "generate" and result["found"]
    _code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "ucs", "--goal-test",
                           "generate")
    assert "  semantics:    goal test on generate" in out.splitlines()


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["-a", "bfs", "--heuristic", "octile"],
         "--heuristic applies to -a greedy, astar, idastar only"),
        (["-a", "ucs", "--heuristic", "manhattan"], "--heuristic applies to -a greedy, astar"),
        (["-a", "astar", "--visit", "expand"], "--visit does not apply to -a astar"),
        (["-a", "astar", "--heuristic", "taxicab"], "argument --heuristic: invalid choice"),
    ],
)
def test_refused_combinations_are_one_line(capsys, argv, expected) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", *argv)
    assert code == 2 and out == ""
    assert expected in err and err.count("\n") == 1


def test_tree_search_a_star_streams_and_finds_the_cheapest(capsys) -> None:
    result = headless_json(capsys, TUTORIAL, "-a", "astar", "--tree-search")
    assert result["found"] and round(result["cost"], 2) == 8.66
    assert result["semantics"]["tree_search"] is True

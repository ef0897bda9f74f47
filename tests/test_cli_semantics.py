"""The command line's search choices, the JSON's words, and headless memory."""

from __future__ import annotations

import json
import tracemalloc

import pytest

from tests.helpers import MAPS
from tests.test_cli import TUTORIAL, run_cli
from tui_search.cli.headless import moves_text, run_headless
from tui_search.cli.parse import parse_options


def headless_json(capsys, *argv: str) -> tuple[int, dict]:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", "--json", *argv)
    assert err == ""
    return code, json.loads(out)


def test_the_json_names_every_choice_in_force(capsys) -> None:
    _code, result = headless_json(capsys, "--corners", "one", "--goal-test", "expand",
                                 "--order", "N,E,S,W,NE,SE,SW,NW", "-a", "dfs")
    assert result["semantics"] == {
        "order": ["N", "E", "S", "W", "NE", "SE", "SW", "NW"], "corners": "one",
        "visit": "generate", "goal_test": "expand", "tree_search": False, "heuristic": None,
        "ties": None, "cost_tolerance": None, "reopen": None, "recursive": None,
        "path_check": None, "mark_start": True, "weight": None, "flip_even": False,
    }
    _, default = headless_json(capsys)
    assert default["semantics"]["corners"] == "always" and default["discarded"] == 0


def test_length_is_the_moves_and_steps_is_not_a_json_key(capsys) -> None:
    """One word, one meaning: a step is an expansion; the path's number of moves is its
    length."""
    _, result = headless_json(capsys)
    assert "steps" not in result and result["length"] == len(result["moves"]) == 7


def test_visit_on_expand_counts_discarded_steps_and_the_trace_marks_them(capsys) -> None:
    code, result = headless_json(capsys, "--visit", "expand")
    assert code == 0 and result["discarded"] > 0 and result["semantics"]["visit"] == "expand"
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--visit", "expand", "--trace", "-")
    lines = [json.loads(line) for line in out.splitlines()]
    marked = [line for line in lines if line.get("discarded")]
    assert len(marked) == result["discarded"]
    assert all(line["successors"] == [] for line in marked)
    assert len(lines) == result["expanded"] + result["discarded"]  # a line per step


def test_tree_search_json_and_the_corner_synonym(capsys) -> None:
    _, tree = headless_json(capsys, "--tree-search", "-a", "dfs")
    assert tree["semantics"]["tree_search"] and tree["semantics"]["visit"] is None
    _, iddfs = headless_json(capsys, "-a", "iddfs")
    assert iddfs["semantics"]["visit"] is None  # does not apply to iterative deepening
    _, never = headless_json(capsys, "--no-corner-cutting")
    _, never2 = headless_json(capsys, "--corners", "never")
    assert never == never2 and not never["found"]


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["--tree-search", "--visit", "expand"], "--visit does not apply to --tree-search"),
        (["--tree-search", "--visit", "generate"], "--visit does not apply to --tree-search"),
        (["-a", "iddfs", "--visit", "expand"], "--visit does not apply to -a iddfs"),
        (["-a", "iddfs", "--visit", "generate"], "--visit does not apply to -a iddfs"),
        (["--no-corner-cutting", "--corners", "one"], "--no-corner-cutting means --corners never"),
        (["--corners", "sometimes"], "argument --corners: invalid choice"),
        (["--goal-test", "never"], "argument --goal-test: invalid choice"),
        (["--order", ""], "--order '': name at least one direction"),
        (["--order", "N,N"], "--order 'N,N': direction N is given twice"),
    ],
)
def test_a_combination_that_makes_no_sense_is_one_line_exit_2(capsys, argv, expected) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", *argv)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and expected in err, err


def test_a_bad_choice_is_refused_before_the_app_starts(capsys) -> None:
    code, _, err = run_cli(capsys, TUTORIAL, "--tree-search", "--visit", "expand")
    assert code == 2 and "--visit does not apply" in err


def test_no_path_names_the_rule_that_blocked_it(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--corners", "never")
    assert code == 1
    assert "no path — the corner rule 'never' blocks it" in out.splitlines()[0]
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--order", "N,W,S,E")
    assert "no path — the moves N,W,S,E block it" in out.splitlines()[0]
    code, out, _ = run_cli(capsys, str(MAPS / "no-path.txt"), "--headless", "--corners", "one")
    assert out.splitlines()[0].endswith(": no path")  # walled in: no rule to blame


def test_a_long_path_prints_its_ends_and_a_count() -> None:
    moves = ["N"] * 10 + ["E"] * 3000 + ["S"] * 10
    text = moves_text(moves)
    assert text.startswith("N, N, N, N, N, N, N, N, … 3,004 more …, S, S")
    assert text.count(",") < 30
    assert moves_text(["N", "E"]) == "N, E"


def test_the_json_keeps_every_move_of_a_long_path(capsys, tmp_path) -> None:
    rows = ["S" + "." * 59, "#" * 59 + ".", "G" + "." * 59]
    path = tmp_path / "long.txt"
    path.write_text("\n".join(rows) + "\n")
    code, out, _ = run_cli(capsys, str(path), "--headless", "--json")
    result = json.loads(out)
    assert code == 0 and len(result["moves"]) == result["length"] > 100
    code, out, _ = run_cli(capsys, str(path), "--headless")
    assert "more …" in out and len(max(out.splitlines(), key=len)) < 200


def _peak_bytes(capsys, path, max_steps: int) -> int:
    """Peak memory of a headless tree-search iterative deepening (depth-limited search with
    path checking: its steps grow exponentially) that gives up after ``max_steps``, from the
    map loaded to the result printed."""
    options = parse_options([str(path), "--headless", "--json", "-a", "iddfs",
                             "--tree-search", "--max-steps", str(max_steps)])
    tracemalloc.start()
    try:
        code = run_headless(options)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert code == 3 and json.loads(capsys.readouterr().out)["expanded"] == max_steps
    return peak


def test_headless_memory_does_not_grow_with_the_steps(capsys, tmp_path) -> None:
    """Ten times the steps, the same memory: the streamed search keeps the map's cells, the
    frontier and the parents it points to, never the steps (about 8 KB here at either count,
    where a recorded run holds 53 KB at 2,000 steps and 500 KB at 20,000)."""
    path = tmp_path / "walled.txt"
    path.write_text("S.....\n......\n......\n......\n....##\n....#G\n")
    small, big = _peak_bytes(capsys, path, 2_000), _peak_bytes(capsys, path, 20_000)
    assert big < 1.5 * small


@pytest.mark.parametrize("argv", [["-a", "iddfs"], ["--tree-search", "-a", "dfs"],
                                  ["--tree-search", "--goal-test", "expand"]])
def test_a_streamed_trace_is_the_recorded_runs_trace(capsys, argv) -> None:
    """Iterative deepening and tree search stream the reference loop; their trace lines are
    the ones the recorded run (what the app steps through) gives."""
    from io import StringIO

    from tui_search.cli.flags import semantics_from
    from tui_search.cli.headless import trace_line
    from tui_search.engine.maps.load import load_map
    from tui_search.engine.run.recorded import Run

    options = parse_options([TUTORIAL, "--headless", *argv, "--max-steps", "400"])
    _code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--trace", "-", *argv,
                           "--max-steps", "400")
    semantics = semantics_from(options)
    run = Run(load_map(TUTORIAL), options.algorithm, semantics, 400)
    recorded = StringIO()
    for step in run.steps.all():
        recorded.write(trace_line(step))
    assert out == recorded.getvalue() and out.count("\n") == run.recorded

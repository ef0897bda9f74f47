"""``--check-trace FILE``: the command line's verdicts, exit codes and errors, and the complete
example of docs/03-traces.md (a student's BFS in plain Python, examples/student_bfs.py) run for
real."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers import MAPS, ROOT
from tui_search.cli.main import main

MAP = str(MAPS / "exercise2-dfs-longer.txt")
TUTORIAL = str(MAPS / "tutorial.txt")
EXAMPLE = ROOT / "examples" / "student_bfs.py"


def run_cli(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def student_trace(tmp_path: Path) -> Path:
    """The example's trace of the map, written by running it as a student would."""
    done = subprocess.run([sys.executable, str(EXAMPLE), MAP], capture_output=True, text=True,
                          check=True, timeout=60)
    trace = tmp_path / "trace.jsonl"
    trace.write_text(done.stdout)
    return trace


def test_the_example_does_not_import_the_app() -> None:
    assert "tui_search" not in EXAMPLE.read_text().split('"""', 2)[2]


def test_the_students_bfs_matches_bfs_with_its_order(capsys, student_trace: Path) -> None:
    code, out, err = run_cli(capsys, MAP, "--headless", "-a", "bfs", "--order", "N,W,S,E",
                             "--check-trace", str(student_trace))
    assert (code, err) == (0, "")
    assert out == ("matches BFS (order N,W,S,E; visit on generate; goal test on generate) "
                   "for all 35 steps\n")


def test_with_another_order_it_names_the_first_difference(capsys, student_trace: Path) -> None:
    code, out, _ = run_cli(capsys, MAP, "--headless", "-a", "bfs", "--order", "N,E,S,W",
                           "--check-trace", str(student_trace))
    assert code == 1
    first, second = out.splitlines()
    assert first.startswith("step ") and "your trace added" in first
    assert second.startswith("  (") and "BFS (order N,E,S,W;" in second


def test_json_verdict(capsys, student_trace: Path) -> None:
    code, out, _ = run_cli(capsys, MAP, "--headless", "--json", "-a", "dfs", "--order",
                           "N,W,S,E", "--check-trace", str(student_trace))
    obj = json.loads(out)
    assert code == 1 and obj["verdict"] == "difference" and obj["algorithm"] == "dfs"
    assert obj["choices"]["order"] == ["N", "W", "S", "E"]
    assert obj["first_difference"]["step"] == obj["matched_steps"] + 1
    assert obj["first_difference"]["message"].startswith(f"step {obj['matched_steps'] + 1}:")


def test_the_apps_own_trace_of_the_tutorial(capsys, tmp_path: Path) -> None:
    trace = tmp_path / "t.jsonl"
    assert main([TUTORIAL, "--headless", "-a", "dfs", "--visit", "expand", "--trace",
                 str(trace)]) == 0
    capsys.readouterr()
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "dfs", "--visit", "expand",
                           "--check-trace", str(trace))
    assert code == 0 and out.startswith("matches DFS (order N,NW,W,SW,S,SE,E,NE; visit on "
                                        "expand; goal test on generate) for all")


@pytest.mark.parametrize("argv, expected", [
    (["--check-trace", "T"], "tui-search: error: --json, --csv, --trace and --check-trace go"),
    (["--headless", "--check-trace", "T", "--visit", "expand"],
     ("tui-search: error: without -a, --check-trace tries every search and choice: give -a "
      "to check --visit")),
    (["--headless", "-a", "bfs", "--check-trace", "T", "--trace", "U"],
     "tui-search: error: --check-trace checks one search: leave out --trace"),
    (["--headless", "-a", "bfs", "--check-trace", "T"],
     "tui-search: T:2:10: not JSON: Expecting value"),
    (["--headless", "-a", "bfs", "--check-trace", "missing.jsonl"],
     "tui-search: missing.jsonl: no such file"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path: Path, monkeypatch, argv,
                                          expected) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "T").write_text('{"node": [0, 0], "successors": []}\n{"node": \n')
    code, out, err = run_cli(capsys, TUTORIAL, *argv)
    assert code == 2 and out == ""
    assert err.startswith(expected), err
    assert err.count("\n") == 1


def test_the_traces_page_shows_the_example_and_its_trace_is_current(student_trace: Path) -> None:
    """docs/03-traces.md shows examples/student_bfs.py whole, and the trace it writes."""
    page = (ROOT / "docs" / "03-traces.md").read_text()
    assert f"```python\n{EXAMPLE.read_text()}```" in page
    assert (ROOT / "examples" / "student_bfs.jsonl").read_text() == student_trace.read_text()


def test_without_a_it_says_which_search_the_trace_is(capsys, student_trace: Path) -> None:
    code, out, _ = run_cli(capsys, MAP, "--headless", "--check-trace", str(student_trace))
    assert code == 0
    assert out.splitlines()[0] == ("your trace is BFS (order N,W,S,E; visit on generate; goal "
                                   "test on generate), for all 35 steps")
    code, out, _ = run_cli(capsys, MAP, "--headless", "--json", "--check-trace",
                           str(student_trace))
    obj = json.loads(out)
    # Every full match is listed: on a 4-connected map of cells costing 1, uniform-cost search
    # (and greedy and A* with no estimate), its ties the oldest first, is BFS.
    assert code == 0 and obj["verdict"] == "match"
    assert [c["algorithm"] for c in obj["candidates"]] == ["bfs", "ucs", "greedy", "astar"]
    assert all(c["verdict"] == "match" for c in obj["candidates"])
    assert obj["candidates"][0]["matched_steps"] == 35


def test_a_trace_cut_at_max_steps_matches_with_the_same_limit(capsys, tmp_path: Path) -> None:
    trace = tmp_path / "t.jsonl"
    argv = [TUTORIAL, "--headless", "-a", "bfs", "--tree-search", "--max-steps", "40"]
    assert main([*argv, "--trace", str(trace)]) == 3  # gave up
    capsys.readouterr()
    code, out, _ = run_cli(capsys, *argv, "--check-trace", str(trace))
    assert code == 0 and out.endswith("for all 40 steps\n")
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "--max-steps", "40", "--check-trace",
                           str(trace))
    assert code == 0 and out.startswith("your trace is BFS (")
    code, out, _ = run_cli(capsys, *argv[:-2], "--check-trace", str(trace))
    assert code == 1 and out.startswith("step 41: your trace ends after step 40; BFS goes on")


@pytest.mark.parametrize("flag", [["--exercise", "1"], ["--compare", "bfs,dfs"]])
def test_check_trace_with_an_exercise_or_a_comparison_is_refused(capsys, tmp_path, flag) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text('{"node": [0, 0], "successors": []}\n')
    code, out, err = run_cli(capsys, str(MAPS / "tutorial.txt"), "--headless", "--check-trace",
                             str(trace), *flag)
    assert code == 2 and out == "" and "--check-trace checks one trace" in err

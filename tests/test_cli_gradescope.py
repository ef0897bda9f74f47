"""``--gradescope OUT.json``: the class report and ``--check-search-py`` as Gradescope's
``results.json``, held to a JSON Schema written from Gradescope's published autograder
specification (tests/data/gradescope_results.schema.json); never written over an existing
file without ``--force``."""

from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest

from tests.test_cli import run_cli
from tui_search.cli.flags import EXIT_BAD_INPUT

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = json.loads((ROOT / "tests" / "data" / "gradescope_results.schema.json").read_text())
STUDENT = str(ROOT / "examples" / "cs188_style" / "search.py")
TWISTY = str(ROOT / "examples" / "cs188_style" / "layouts" / "twistyMaze.lay")
MAPS = ROOT / "maps"


def valid(path: Path) -> dict:
    data = json.loads(path.read_text())
    jsonschema.validate(data, SCHEMA)
    return data


def test_the_schema_refuses_what_gradescope_would() -> None:
    jsonschema.Draft202012Validator.check_schema(SCHEMA)
    for bad in ({"tests": [{"name": "x"}]},  # no score anywhere
                {"score": 1, "visibility": "sometimes"},
                {"score": 1, "tests": [{"score": 1, "status": "ok"}]},
                {"score": "1"}):
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate(bad, SCHEMA)


def test_the_class_report_as_results(capsys, tmp_path: Path) -> None:
    out = tmp_path / "results.json"
    maps = [str(MAPS / "exercise1-bfs-wins.txt"), str(MAPS / "exercise1-goal-moved.txt"),
            str(MAPS / "broken.txt")]
    code, text, _ = run_cli(capsys, "--exercise", "1", "--headless", *maps, "--gradescope",
                            str(out))
    data = valid(out)
    assert code == 1 and text  # the report printed as ever
    assert [t["name"] for t in data["tests"]] == maps
    assert [t["score"] for t in data["tests"]] == [1.0, 1.0, 0.0]
    assert data["score"] == 2.0 and data["output"].endswith("2 of 3 solved, 1 unreadable")
    assert all(t["max_score"] == 1.0 and t["visibility"] == "visible" for t in data["tests"])
    assert data["tests"][2]["output"].startswith("unreadable — ")


def test_a_students_search_py_as_results(capsys, tmp_path: Path) -> None:
    out = tmp_path / "results.json"
    code, _, _ = run_cli(capsys, "--check-search-py", STUDENT, TWISTY, "-a", "astar",
                         "--headless", "--gradescope", str(out))
    data = valid(out)
    assert code == 0 and data["score"] == 2.0
    assert data["output"] == ("your aStarSearch is A* (manhattan; no re-opening; order "
                              "N,S,E,W; goal test on expand), for all 114 expansions")
    assert [t["name"] for t in data["tests"]] == [f"aStarSearch on {TWISTY}: the search",
                                                  f"aStarSearch on {TWISTY}: its path"]


def test_a_bug_and_a_crash_score_nothing_but_are_said(capsys, tmp_path: Path) -> None:
    out = tmp_path / "bug.json"
    code, _, _ = run_cli(capsys, "--check-search-py",
                         str(ROOT / "tests" / "data" / "cs188" / "bfs_with_a_stack.py"), TWISTY,
                         "-a", "bfs", "--headless", "--gradescope", str(out))
    data = valid(out)
    assert code == 1 and [t["score"] for t in data["tests"]] == [0.0, 1.0]
    assert data["tests"][0]["output"].startswith("your breadthFirstSearch: step 4: ")
    crash = tmp_path / "crash.py"
    crash.write_text("def breadthFirstSearch(problem):\n    return 1 / 0\n")
    out = tmp_path / "crash.json"
    code, _, err = run_cli(capsys, "--check-search-py", str(crash), TWISTY, "--headless",
                           "--gradescope", str(out))
    data = valid(out)
    assert code == EXIT_BAD_INPUT and data["score"] == 0.0
    assert data["output"] == (f"{crash}:2: breadthFirstSearch raised ZeroDivisionError: "
                              "division by zero")
    assert err == f"tui-search: {data['output']}\n"


def test_never_over_a_file_without_force(capsys, tmp_path: Path) -> None:
    out = tmp_path / "results.json"
    out.write_text("the teacher's")
    argv = ["--check-search-py", STUDENT, TWISTY, "--headless", "--gradescope", str(out)]
    code, _, err = run_cli(capsys, *argv)
    assert code == EXIT_BAD_INPUT and out.read_text() == "the teacher's"
    assert err == f"tui-search: error: {out} exists: --force replaces it\n"
    code, _, _ = run_cli(capsys, *argv, "--force")
    assert code == 0 and valid(out)["score"] == 2.0


def test_only_where_there_are_grades(capsys, tmp_path: Path) -> None:
    code, _, err = run_cli(capsys, TWISTY, "--headless", "--gradescope",
                           str(tmp_path / "r.json"))
    assert code == EXIT_BAD_INPUT
    assert err.startswith("tui-search: error: --gradescope goes with --exercise E --headless")


def test_a_students_records_as_results(capsys, tmp_path: Path) -> None:
    """--class-report DIR --gradescope: one student's records (Gradescope grades a
    submission): a test an exercise tried, the quiz and the runs by hand worth what was
    asked of them; a folder of several students is refused in one line, and an existing
    file is replaced only with --force."""
    from tui_search.engine.course.records import Writer

    folder = tmp_path / "ada"
    folder.mkdir()
    ada = Writer(folder, "Ada")
    ada.write("exercise", exercise="BFS expands less", solved=True, verdict="solved",
              reason="", map="S.G\n", map_size=[3, 1])
    ada.write("exercise", exercise="Greedy is not optimal", solved=False,
              verdict="not solved", reason="", map="S.G\n", map_size=[3, 1])
    for right in (True, True, False):
        ada.write("quiz", algorithm="bfs", right=right)
    ada.write("by_hand", algorithm="bfs", finished=True, steps=22, mistakes=1,
              by_cause={"newest": 1}, seconds=80.0)
    out = tmp_path / "results.json"
    code, _, err = run_cli(capsys, "--class-report", str(folder), "--gradescope", str(out))
    assert (code, err) == (0, "")
    data = valid(out)
    scores = {t["name"]: (t["score"], t["max_score"]) for t in data["tests"]}
    assert scores == {"exercise: BFS expands less": (1.0, 1.0),
                      "exercise: Greedy is not optimal": (0.0, 1.0),
                      "quiz: the next node": (2.0, 3.0), "runs by hand": (1.0, 1.0)}
    assert data["score"] == 4.0 and "Ada" in data["output"]
    code, _, err = run_cli(capsys, "--class-report", str(folder), "--gradescope", str(out))
    assert code == EXIT_BAD_INPUT and "exists: --force replaces it" in err
    assert run_cli(capsys, "--class-report", str(folder), "--gradescope", str(out),
                   "--force")[0] == 0
    Writer(folder, "Ben").write("quiz", algorithm="bfs", right=True)
    code, _, err = run_cli(capsys, "--class-report", str(folder), "--gradescope",
                           str(tmp_path / "two.json"))
    assert code == EXIT_BAD_INPUT and "holds 2 students' records (Ada, Ben)" in err
    assert err.count("\n") == 1 and not (tmp_path / "two.json").exists()

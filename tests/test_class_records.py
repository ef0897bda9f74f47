"""A class's records from the command line: ``--class-report DIR`` (text, ``--csv``,
``--json``, a torn line warned of), exercise files done by hand (``by_hand``, ``mistakes``,
``seed = "student"``), ``--by-hand`` with each student's own generated map, and the flags'
one-line refusals."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest

from tests.helpers import MAPS
from tui_search.cli.main import main
from tui_search.cli.parse import parse_options
from tui_search.engine.course.exercise_file import parse_exercise
from tui_search.engine.course.records import Writer
from tui_search.engine.maps.read import MapError

TUTORIAL = str(MAPS / "tutorial.txt")


def run_cli(capsys, *argv: str) -> tuple[int, str, str]:
    try:
        code = main(list(argv))
    except SystemExit as exc:
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    return code, out, err


def class_folder(folder: Path) -> Path:
    """Three students' records: Ada solved an exercise and took the newest entry in BFS by
    hand; Ben answered two quiz questions and took the newest entry too; Cy checked a
    trace whose DFS took the oldest entry; then a line torn by a kill in Cy's file."""
    ada = Writer(folder, "Ada")
    ada.write("start", map_name="tutorial", exercise=None)
    ada.write("exercise", exercise="BFS expands less", solved=True, verdict="solved",
              reason="", map="S.G\n", map_size=[3, 1])
    ada.write("by_hand", algorithm="bfs", finished=True, steps=22, mistakes=2,
              by_cause={"newest": 1, "reached": 1}, seconds=80.0)
    ben = Writer(folder, "Ben", "0a0b0c")
    ben.write("quiz", algorithm="bfs", right=True)
    ben.write("quiz", algorithm="bfs", right=False)
    ben.write("by_hand", algorithm="bfs", finished=False, steps=5, mistakes=1,
              by_cause={"newest": 1}, seconds=30.0)
    cy = Writer(folder, "Cy")
    cy.write("trace_check", algorithm="dfs", verdict="difference", cause="oldest")
    with open(cy.path, "ab") as file:
        file.write(b'{"v":1,"student":"Cy","event":"qu')
    return folder


def test_the_class_report_a_row_a_student_and_the_misconceptions(capsys, tmp_path) -> None:
    folder = class_folder(tmp_path)
    code, out, err = run_cli(capsys, "--class-report", str(folder))
    assert code == 0
    lines = out.splitlines()
    assert lines[0] == f"Class report of {folder}: 3 students, 7 events"
    assert lines[1].split() == ["student", "exercises", "solved", "quiz", "by", "hand",
                                "mistakes", "by", "kind", "traces", "matched"]
    assert lines[2].split() == ["Ada", "BFS", "expands", "less", "1", "of", "1", "finished",
                                "newest", "1,", "reached", "1"]
    assert lines[3].split() == ["Ben", "1", "of", "2", "0", "of", "1", "finished", "newest",
                                "1"]
    assert lines[4].split() == ["Cy", "0", "of", "1"]
    assert lines[5:] == [
        "Misconceptions:",
        "  2 of 3 students took the newest entry in BFS at least once",
        "  1 of 3 students added a cell reached already in BFS at least once",
        "  1 of 3 students took the oldest entry in DFS at least once"]
    assert err == (f"tui-search: warning: {folder / 'Cy.jsonl'}:2: a torn or malformed line, "
                   "skipped\n")


def test_the_class_report_as_csv_and_json(capsys, tmp_path) -> None:
    folder = class_folder(tmp_path)
    code, out, _ = run_cli(capsys, "--class-report", str(folder), "--csv")
    assert code == 0
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [r["student"] for r in rows] == ["Ada", "Ben", "Cy"]
    assert (rows[0]["mistakes:newest"], rows[0]["mistakes:reached"],
            rows[0]["exercises_solved"]) == ("1", "1", "1")
    assert (rows[1]["quiz_right"], rows[1]["quiz_asked"]) == ("1", "2")
    code, out, _ = run_cli(capsys, "--class-report", str(folder), "--json")
    data = json.loads(out)
    assert [s["student"] for s in data["students"]] == ["Ada", "Ben", "Cy"]
    assert data["misconceptions"][0] == {
        "cause": "newest", "algorithm": "bfs", "students": 2, "of": 3, "names": ["Ada", "Ben"],
        "text": "2 of 3 students took the newest entry in BFS at least once"}
    assert data["warnings"] == [f"{folder / 'Cy.jsonl'}:2: a torn or malformed line, skipped"]


@pytest.mark.parametrize(("argv", "says"), [
    (["--class-report", "{d}", "--csv", "--json"], "--csv or --json, not both"),
    (["--class-report", "{d}", TUTORIAL], "leave out MAP"),
    (["--class-report", "{d}/missing"], "no such file"),
    (["--records", "{d}", TUTORIAL], "--records DIR needs --student NAME"),
    (["--class", "{d}/list.txt", TUTORIAL], "--class FILE goes with --serve --records DIR"),
    (["--by-hand", "--headless", TUTORIAL], "--by-hand steps one search in the app: leave "
     "out --headless"),
    (["--records", "{d}/file", "--student", "Ada", TUTORIAL], "file: not a folder"),
])
def test_the_flags_refuse_in_one_line(capsys, tmp_path, argv: list[str], says: str) -> None:
    (tmp_path / "file").write_text("")
    code, out, err = run_cli(capsys, *(a.format(d=tmp_path) for a in argv))
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and says in err, err


EXERCISE = """
title = "BFS by hand"
text = "Take each entry off the queue yourself."
generate = "maze 9x7"
seed = "student"
searches = ["bfs"]
by_hand = true
mistakes = 2
"""


def test_a_by_hand_exercise_has_an_allowance_and_each_student_their_own_map() -> None:
    exercise = parse_exercise(EXERCISE, "hand.toml")
    assert exercise.by_hand and exercise.mistakes == 2 and exercise.student_seed
    ada, ben = exercise.for_student("Ada"), exercise.for_student("Ben")
    assert ada.student == "Ada" and ada.grid.blocked != ben.grid.blocked
    assert exercise.for_student("Ada").grid.blocked == ada.grid.blocked  # the same each time


@pytest.mark.parametrize(("extra", "says"), [
    ('solved = "bfs.found"\n', "hand.toml:8:10: solved: not for a by-hand exercise"),
    ("mistakes = -1\n", "expected a whole number of mistakes allowed"),
])
def test_a_by_hand_exercise_refuses_what_it_cannot_have(extra: str, says: str) -> None:
    text = EXERCISE.replace("mistakes = 2\n", "") + extra
    with pytest.raises(MapError, match=says):
        parse_exercise(text, "hand.toml")


def test_by_hand_on_each_students_own_generated_map() -> None:
    ada = parse_options(["--by-hand", "--generate", "maze", "--seed", "Ada"])
    ben = parse_options(["--by-hand", "--generate", "maze", "--seed", "Ben"])
    assert ada.by_hand and ben.by_hand
    assert ada.grid is not None and ben.grid is not None
    assert ada.grid.blocked != ben.grid.blocked


def test_an_exercise_of_each_students_map_needs_the_student(capsys, tmp_path) -> None:
    path = tmp_path / "hand.toml"
    path.write_text(EXERCISE)
    code, _, err = run_cli(capsys, "--exercise", str(path))
    assert code == 2 and "give --student NAME" in err
    options = parse_options(["--exercise", str(path), "--student", "Ada"])
    assert options.exercise_read is not None and options.exercise_read.student == "Ada"

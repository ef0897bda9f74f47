"""Pacman layouts and ``--preset cs188`` on the command line: the preset in ``--help``, the
course's choices in one flag with each flag still changing one, the layout's note and the
course's count in the output, and a bad layout one line, exit 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.test_cli import run_cli
from tui_search.cli.flags import EXIT_BAD_INPUT

ROOT = Path(__file__).resolve().parents[1]
LAYOUTS = ROOT / "examples" / "cs188_style" / "layouts"
TWISTY = str(LAYOUTS / "twistyMaze.lay")
THREE = str(LAYOUTS / "threeDots.lay")


def test_help_lists_the_preset_and_what_it_sets(capsys) -> None:
    with pytest.raises(SystemExit) as exit_:
        run_cli(capsys, "--help")
    out = capsys.readouterr().out
    assert exit_.value.code == 0
    flat = " ".join(out.split())
    assert "--preset {cs188}" in flat
    assert "successors N,S,E,W, visit on expand, goal test on expand, graph search" in flat


def test_the_preset_sets_the_courses_choices(capsys) -> None:
    code, out, err = run_cli(capsys, TWISTY, "--preset", "cs188", "-a", "bfs", "--headless",
                             "--json")
    assert code == 0 and err == ""
    result = json.loads(out)
    sem = result["semantics"]
    assert sem["order"] == ["N", "S", "E", "W"] and sem["visit"] == "expand"
    assert sem["goal_test"] == "expand" and sem["tree_search"] is False
    assert (result["expanded"], result["length"], result["cost"]) == (201, 58, 58.0)


def test_a_flag_changes_one_of_the_presets_choices(capsys) -> None:
    code, out, _ = run_cli(capsys, TWISTY, "--preset", "cs188", "-a", "bfs", "--headless",
                           "--json", "--visit", "generate", "--order", "N,W,S,E")
    sem = json.loads(out)["semantics"]
    assert code == 0
    assert sem["order"] == ["N", "W", "S", "E"] and sem["visit"] == "generate"
    assert sem["goal_test"] == "expand"  # the preset's still


def test_the_preset_fits_each_search(capsys) -> None:
    code, out, _ = run_cli(capsys, TWISTY, "--preset", "cs188", "-a", "astar", "--headless",
                           "--json")
    sem = json.loads(out)["semantics"]
    assert code == 0
    assert sem["heuristic"] == "manhattan" and sem["reopen"] is False and sem["ties"] == "fifo"
    assert json.loads(out)["expanded"] == 115
    code, out, _ = run_cli(capsys, TWISTY, "--preset", "cs188", "--compare", "bfs,astar",
                           "--headless", "--json")
    runs = json.loads(out)["runs"]
    assert code == 0 and [r["expanded"] for r in runs] == [201, 115]


def test_the_text_says_the_first_dot_and_the_courses_count(capsys) -> None:
    code, out, _ = run_cli(capsys, THREE, "--preset", "cs188", "-a", "bfs", "--headless")
    assert code == 0
    assert "  note:         3 dots: the goal is the first, (8,1) (the course's (8,3))" in out
    assert ("  course count: 18 expanded (getSuccessors calls; the goal's step makes none)"
            in out.splitlines())


def test_a_bad_layout_is_one_line(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "bad.lay"
    bad.write_text("%%%%\n%P?.\n%%%%\n")
    code, out, err = run_cli(capsys, str(bad), "--headless")
    assert code == EXIT_BAD_INPUT and out == ""
    assert err.strip().endswith("bad.lay:2:3: unknown layout character '?' (use % walls, P "
                                "the start, . food, o G digits and spaces free)")
    assert len(err.strip().splitlines()) == 1

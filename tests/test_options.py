"""The command line is parsed once, into one frozen, typed value: :func:`parse_options` reads
the files the flags name into its fields, nothing changes it after, and nothing below the
command line sees argparse."""

from __future__ import annotations

import ast
from dataclasses import FrozenInstanceError

import pytest

from tests.helpers import MAPS, MOVINGAI, ROOT
from tui_search.cli.options import FLAGS, READ, Options
from tui_search.cli.parse import parse_options
from tui_search.cli.parser import build_parser

DATA = ROOT / "tests" / "data"


def test_the_options_have_a_field_for_every_flag_and_no_other() -> None:
    dests = {a.dest for a in build_parser()._actions} - {"help", "version"}
    assert dests == set(FLAGS) and not set(FLAGS) & set(READ)


def test_nothing_below_the_command_line_sees_argparse() -> None:
    found = []
    for path in sorted((ROOT / "tui_search").rglob("*.py")):
        if "cli" in path.relative_to(ROOT / "tui_search").parts:
            continue
        for node in ast.walk(ast.parse(path.read_text("utf-8"))):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            if "argparse" in names:
                found.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    assert found == []


def test_the_options_never_change_once_made() -> None:
    options = parse_options([str(MAPS / "tutorial.txt")])
    with pytest.raises(FrozenInstanceError):
        options.algorithm = "dfs"  # type: ignore[misc]
    changed = options.replace(algorithm="dfs")
    assert (options.algorithm, changed.algorithm) == ("bfs", "dfs")
    with pytest.raises(TypeError, match="missing"):
        Options(map=None)


def test_a_run_s_map_is_read_into_the_options_with_its_default_search() -> None:
    options = parse_options([str(MAPS / "tutorial.txt"), "--headless"])
    assert options.grid is not None and options.path == MAPS / "tutorial.txt"
    assert (options.algorithm, options.algorithm_given, options.maps) == (
        "bfs", False, (str(MAPS / "tutorial.txt"),))
    assert options.exercise_read is options.lesson_read is options.replay_read is None


def test_the_exercise_the_lesson_and_the_scenario_are_read_into_typed_fields() -> None:
    exercise = parse_options(["--exercise", str(DATA / "exercises" / "greedy-not-optimal.toml")])
    assert exercise.exercise_read is not None and exercise.exercise_read.number is None
    lesson = parse_options(["--lesson", str(DATA / "lessons" / "teacher.md")])
    assert lesson.lesson_read is not None and lesson.grid is not None
    arena = MOVINGAI / "arena.map"
    scenario = parse_options([str(arena), "--scen", f"{arena}.scen", "--scen-row", "5"])
    assert scenario.scenario is not None and scenario.grid is not None
    assert scenario.grid.start == scenario.scenario.start


def test_the_replay_is_read_beside_its_map(tmp_path) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text('{"node": [0, 0], "successors": [[0, 1]]}\n')
    options = parse_options([str(MAPS / "tutorial.txt"), "--replay", str(trace), "-a", "bfs"])
    assert options.replay_read is not None and options.replay_read.algorithm == "bfs"


def test_a_run_without_a_map_reads_none() -> None:
    for argv in (["--pseudocode"], ["--lesson"], ["--generate", "maze", "--output", "-"],
                 ["--exercise", "1", "--headless", "a.txt", "b.txt"]):
        assert parse_options(argv).grid is None, argv

"""Lessons read without the app (:mod:`tui_search.engine.course.lesson`): sections at ``## ``, a
``lesson`` block's keys carried on from section to section, every block kind, and a bad block
as one line naming the file, line and column (exit 2 from the command line)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.helpers import ROOT
from tests.test_cli import run_cli
from tui_search.engine.course.lesson import KEYS, built_in, find_lesson, parse_lesson, read_lesson
from tui_search.engine.maps.read import MapError

LESSONS = ROOT / "tests" / "data" / "lessons"
TEACHER = LESSONS / "teacher.md"


def test_the_teacher_s_lesson_uses_every_key_and_each_block_carries_the_rest_on() -> None:
    lesson = read_lesson(TEACHER)
    assert lesson.title == "A teacher's lesson"
    assert [s.title for s in lesson.sections] == [
        "The map and a search", "Heuristics and the goal test", "No block",
        "Moves, corners and tree search", "Side by side, with an exercise", "Back to one"]
    used = {line.partition(":")[0] for line in TEACHER.read_text().splitlines()
            if line.partition(":")[0] in KEYS}
    assert used == set(KEYS)
    first, informed, none, moves, side, back = (s.state for s in lesson.sections)
    assert none is None  # no block: the app stays as it is
    assert first is not None and first.map == LESSONS.resolve() / "discard.txt"
    assert (first.algorithm, first.visit, first.code, first.step) == ("dfs", "expand", True, 4)
    assert informed is not None and informed.map == first.map  # carried on
    assert (informed.heuristic, informed.goal_test, informed.step, informed.code) == (
        "manhattan", "generate", None, False)
    assert moves is not None and moves.order == ("N", "W", "S", "E")
    assert (moves.corners, moves.tree_search, moves.goal_test, moves.spec) == (
        "never", True, None, "bfs")
    # an exercise's rules are the section's: exercise 2's, the tutorial's (corners: always)
    assert side is not None and (side.spec, side.exercise, side.corners) == ("bfs,dfs", 2,
                                                                             "always")
    assert back is not None and (back.spec, back.exercise, back.step) == ("ucs", None, 1)


def test_a_section_shows_its_text_without_its_block_and_fences_hide_headings() -> None:
    side = read_lesson(TEACHER).sections[4]
    assert side.text.startswith("## Side by side, with an exercise\n")
    assert "```lesson" not in side.text and "## not a heading" in side.text
    assert side.line == 48
    assert read_lesson(TEACHER).sections[0].text.startswith("# A teacher's lesson")


def test_the_built_in_lessons_are_listed_and_found_by_name() -> None:
    assert set(built_in()) == {"tutorial", "choices", "bidirectional"}
    assert len(read_lesson(find_lesson("tutorial")).sections) == 10
    choices = read_lesson(find_lesson("choices"))
    assert len(choices.sections) == 5
    assert all(s.state is not None and s.state.code for s in choices.sections)


def test_the_bidirectional_lesson_walks_the_trap_on_its_own_copy_of_the_map() -> None:
    """Every section sets the app (its setting checked when read: a bad one would raise);
    the map is the package's copy of maps/pathfinding-js-28.txt, the same grid, so the lesson
    opens from anywhere; the stopping rules come in compare mode, two panes."""
    from tui_search.engine.maps.load import load_map

    lesson = read_lesson(find_lesson("bidirectional"), "bidirectional")
    assert lesson.title == "Bidirectional search and its trap"
    states = [s.state for s in lesson.sections]
    assert all(state is not None for state in states)
    trap_map = states[0].map if states[0] is not None else None
    assert trap_map is not None and trap_map.parent == find_lesson("bidirectional").parent
    assert load_map(trap_map) == load_map(ROOT / "maps" / "pathfinding-js-28.txt")
    assert [(s.spec, s.step) for s in states if s is not None] == [
        ("biastar:first-meeting,biastar", 0), ("biastar:first-meeting,biastar", 16),
        ("biastar:first-meeting,biastar", None), ("biastar,astar", None),
        ("bibfs:first-meeting,bibfs", None)]


BAD = [
    ("## A\n```lesson\nspeed: 3\n```\n", "lesson.md:3:1: unknown key 'speed'"),
    ("## A\n```lesson\n  step: soon\n```\n", "lesson.md:3:9: step 'soon': use a step number"),
    ("## A\n```lesson\nalgorithm bfs\n```\n", "lesson.md:3:1: expected 'key: value'"),
    ("## A\n```lesson\nstep: 1\nstep: 2\n```\n", "lesson.md:4:1: step is set twice"),
    ("## A\n```lesson\norder: N,UP\n```\n", "lesson.md:3:8: order 'N,UP': unknown direction"),
    ("## A\n```lesson\ncompare: bfs\n```\n", "lesson.md:3:10: compare 'bfs': compare two"),
    ("## A\n```lesson\ncode: yes\n```\n", "lesson.md:3:7: code 'yes': use on or off"),
    ("## A\n```lesson\nexercise: 3\n```\n", ("lesson.md:3:11: exercise '3': use 1, 2, an "
                                           "exercise file (FILE.toml, relative to the "
                                           "lesson file), off")),
    ("## A\n```lesson\nexercise: gone.toml\n```\n", "lesson.md:3:11: exercise 'gone.toml': "),
    ("## A\n```lesson\nmap: nowhere.txt\n```\n", "lesson.md:3:6: map 'nowhere.txt': "),
    # a combination: at the key the block set last that makes it (its line and column)
    ("## A\n```lesson\nalgorithm: iddfs\n  visit: expand\n```\n",
     "lesson.md:4:3: the visit rule does not apply to IDDFS"),
    ("## A\n```lesson\ntree-search: on\nvisit: expand\n```\n",
     "lesson.md:4:1: tree search has no visited set"),
    ("## A\n```lesson\nvisit: expand\n```\n## B\n```lesson\nstep: 2\nalgorithm: ucs\n```\n",
     "lesson.md:8:1: the visit rule does not apply to UCS"),
    ("## A\ntext\n```lesson\nstep: 1\n```\n",
     "lesson.md:3:1: a lesson block must come first in its section"),
    ("## A\n```lesson\nstep: 1\n", "lesson.md: a fenced block is not closed"),
    ("# Only a title\ntext\n", "lesson.md:1: no sections"),
]


@pytest.mark.parametrize(("text", "expected"), BAD)
def test_a_bad_block_is_one_line_naming_file_line_and_column(text: str, expected: str,
                                                            tmp_path: Path) -> None:
    with pytest.raises(MapError) as info:
        parse_lesson(text, tmp_path / "lesson.md", "lesson.md")
    message = str(info.value).replace(str(tmp_path / "lesson.md"), "lesson.md")
    assert message.startswith(expected) and "\n" not in message


MAZE = ROOT / "tests" / "data" / "exercises" / "maze-4-connected.toml"


def test_a_section_shows_an_exercise_file_beside_the_lesson_under_its_rules(
        tmp_path: Path) -> None:
    """``exercise: FILE.toml`` is read relative to the lesson; the section takes the
    exercise's rules (its searches and the panes run under them), and the next section keeps
    them as it keeps any choice; a choice the same block names otherwise is refused there."""
    (tmp_path / "maze.toml").write_text(MAZE.read_text())
    lesson = parse_lesson("## A\n```lesson\nexercise: maze.toml\nstep: 3\n```\n"
                          "## B\n```lesson\nexercise: off\n```\n",
                          tmp_path / "lesson.md")
    first, second = (s.state for s in lesson.sections)
    assert first is not None and second is not None
    assert not isinstance(first.exercise, int) and first.exercise is not None
    assert first.exercise.title == "The long way round"
    assert (first.order, first.corners, first.step) == (("N", "E", "S", "W"), "never", 3)
    assert first.semantics == first.exercise.semantics and first.map is None  # its own map
    assert second.exercise is None and second.order == ("N", "E", "S", "W")
    with pytest.raises(MapError) as info:
        parse_lesson("## A\n```lesson\ncorners: one\nexercise: maze.toml\n```\n",
                     tmp_path / "lesson.md")
    assert str(info.value) == (f"{tmp_path / 'lesson.md'}:3:1: corners: the exercise runs "
                               "under its own rules (moves N,E,S,W · corners: never): leave "
                               "out corners")
    (tmp_path / "bad.toml").write_text(MAZE.read_text().replace('order = "N,E,S,W"',
                                                                 'order = "N,E,UP"'))
    with pytest.raises(MapError) as info:
        parse_lesson("## A\n```lesson\nexercise: bad.toml\n```\n", tmp_path / "lesson.md")
    assert str(info.value).startswith(f"{tmp_path / 'lesson.md'}:3:11: exercise 'bad.toml': "
                                      f"{tmp_path / 'bad.toml'}:12:9: order: ")


def test_the_command_line_lists_the_lessons_and_refuses_a_bad_one(capsys,
                                                                   tmp_path: Path) -> None:
    code, out, err = run_cli(capsys, "--lesson")
    assert code == 0 and err == ""
    assert [line.split()[0] for line in out.splitlines()] == ["bidirectional", "choices",
                                                              "tutorial"]
    assert len({line.index(line.split()[1]) for line in out.splitlines()}) == 1  # a column
    bad = tmp_path / "bad.md"
    bad.write_text("## One\n\n```lesson\nalgorithm: quick\n```\n")
    code, out, err = run_cli(capsys, "--lesson", str(bad))
    assert (code, out) == (2, "")
    assert err == f"tui-search: {bad}:4:12: algorithm 'quick': use bfs, dfs, iddfs, ucs, " \
        "greedy, astar, idastar\n"
    code, _, err = run_cli(capsys, "--lesson", "no-such-lesson")
    assert code == 2 and "no such lesson (built in: bidirectional, choices, tutorial)" in err
    code, _, err = run_cli(capsys, "--lesson", "tutorial", "--headless")
    assert code == 2 and err.count("\n") == 1 and "--lesson is for the app" in err
    for flag, value in (("--compare", "bfs,dfs"), ("--exercise", "1")):  # never ignored
        code, out, err = run_cli(capsys, "--lesson", "tutorial", flag, value)
        assert (code, out) == (2, "") and err.count("\n") == 1 and f"leave out {flag}" in err


def test_a_number_key_a_built_in_lesson_names_is_that_search_s_key() -> None:
    import re

    from tui_search.engine.search.registry import ALGORITHMS

    by_key = {a.app_key: a for a in ALGORITHMS.values()}
    named = []
    for name in built_in():
        text = find_lesson(name).read_text("utf-8")
        for key, search in re.findall(r"`([1-9])` for (\w+)", text):
            named.append((name, key, search))
            assert key in by_key and search.upper() in (by_key[key].short.upper(),
                                                         by_key[key].key.upper()), (name, key)
    assert named  # the check has something to check

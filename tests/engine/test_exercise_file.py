"""Exercise files: the tutorial's two as shipped, a teacher's own, its errors, and edits the
exercise does not allow."""

from __future__ import annotations

import re
import sys
import types
from pathlib import Path

import pytest

from tests.helpers import MAPS, ROOT
from tui_search.engine.course import exercise_file
from tui_search.engine.course.exercise_file import built_in_exercise, find_exercise, load_exercise
from tui_search.engine.course.grading import grade
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MapError

#: Today's verdicts (before exercise files): map -> (exercise 1, exercise 2) solved, and the
#: reasons the tutorial's exercises gave then.
TODAY = {
    "tutorial.txt": (False, False, "BFS expanded 22 nodes, DFS 7; both paths have 7 moves"),
    "exercise1-bfs-wins.txt": (True, True, ("BFS expanded 5 nodes, DFS 20; BFS's path has 2 "
                               "moves, DFS's 17")),
    "exercise1-goal-moved.txt": (True, True, ("BFS expanded 5 nodes, DFS 18; BFS's path has 4 "
                                 "moves, DFS's 8")),
    "exercise2-dfs-longer.txt": (False, True, ("BFS expanded 32 nodes, DFS 9; BFS's path has 5 "
                                 "moves, DFS's 8")),
    "no-path.txt": (False, False, "no path to the goal (BFS expanded 30 nodes, DFS 30)"),
}

GREEDY = """\
title = "Greedy is not optimal"
text = "Move obstacles so that greedy best-first's path costs more than A*'s."
map = "tutorial.txt"
searches = ["greedy", "astar:manhattan"]
edits = ["obstacles"]
solved = "greedy.found and astar_manhattan.found and greedy.cost > astar_manhattan.cost"
hint = "Greedy looks only at h."
"""


@pytest.mark.parametrize("name", TODAY)
def test_the_shipped_files_give_today_s_verdicts(name: str) -> None:
    one, two, reason = TODAY[name]
    grid = load_map(MAPS / name)
    first, second = grade(built_in_exercise(1), grid), grade(built_in_exercise(2), grid)
    assert (first.solved, second.solved) == (one, two)
    assert first.reason == reason
    assert built_in_exercise(1).title == "Exercise 1" and find_exercise("2").number == 2


def test_exercise_one_hints_at_more_than_the_goal_and_two_allows_anything() -> None:
    moved = grade(built_in_exercise(1), load_map(MAPS / "exercise1-goal-moved.txt"))
    assert moved.solved and moved.hint == ""
    wins = grade(built_in_exercise(1), load_map(MAPS / "exercise1-bfs-wins.txt"))
    assert wins.solved and wins.hint == (
        "the exercise changes only the goal: here the map's size changed")
    assert grade(built_in_exercise(2), load_map(MAPS / "exercise1-bfs-wins.txt")).hint == ""


def write(tmp_path: Path, text: str, name: str = "greedy.toml") -> Path:
    (tmp_path / "tutorial.txt").write_text((MAPS / "tutorial.txt").read_text())
    path = tmp_path / name
    path.write_text(text)
    return path


def test_a_teacher_s_exercise(tmp_path: Path) -> None:
    ex = load_exercise(write(tmp_path, GREEDY))
    assert ex.title == "Greedy is not optimal" and ex.name == "exercise greedy"
    assert ex.fields == ("greedy.found", "astar_manhattan.found", "greedy.cost",
                         "astar_manhattan.cost")
    verdict = grade(ex, ex.grid.copy())
    assert not verdict.solved and verdict.hints == "Greedy looks only at h." == ex.hint
    assert verdict.hint == ""
    assert verdict.reason == "both found the goal; both paths cost 8.66"
    assert verdict.figures["greedy.cost"] == verdict.figures["astar_manhattan.cost"]


def test_an_edit_outside_edits_fails_the_exercise(tmp_path: Path) -> None:
    ex = load_exercise(write(tmp_path, GREEDY))
    grid = ex.grid.copy()
    grid.start = (0, 1)
    grid.set_blocked((3, 0), True)  # an obstacle: allowed
    verdict = grade(ex, grid)
    assert not verdict.solved and verdict.reason == (
        "changed the start, which the exercise does not allow")
    assert verdict.said == ("changed the start, which the exercise does not allow; "
                            "no path to the goal")  # what the searches did, as if allowed
    grid.goal = (0, 5)
    assert grade(ex, grid).reason == (
        "changed the start and the goal, which the exercise does not allow")
    hinted = load_exercise(write(tmp_path, GREEDY + 'other_edits = "hint"\n'))
    verdict = grade(hinted, grid)
    assert verdict.hint.startswith("the exercise changes only the obstacles: here the start "
                                   "and the goal changed")
    bigger = load_map(MAPS / "exercise1-bfs-wins.txt")
    assert grade(ex, bigger).reason == (
        "changed the map's size, which the exercise does not allow")


def test_a_generated_map(tmp_path: Path) -> None:
    text = GREEDY.replace('map = "tutorial.txt"', 'generate = "maze 15x11 7"')
    ex = load_exercise(write(tmp_path, text))
    assert (ex.grid.width, ex.grid.height) == (15, 11) and ex.grid.start is not None


@pytest.mark.parametrize(("change", "where", "message"), [
    (("solved = \"greedy.found and", "solved = \"greedy.fund and"), ":6:18",
     "solved: 'greedy.fund': unknown field 'fund'"),
    (("solved = \"greedy.found and", "solved = \"ucs.found and"), ":6:11",
     "solved: 'ucs' is not one of the exercise's searches (greedy, astar_manhattan)"),
    (("greedy.cost >", "greedy.cost >>"), ":6:67", "solved: expected a number"),
    (('solved = "', 'solved = "' + "(" * 200), ":6:61", "solved: nested too deeply"),
    (('solved = "', 'solved = "' + "not " * 2000), ":6:811", "solved: the condition is too long"),
    (("title = ", "title "), ":1:7", "not TOML: Expected '=' after a key"),
    (('searches = ["greedy", ', 'searches = ["nope", '), ":4:12",
     "searches: unknown algorithm 'nope'"),
    (('edits = ["obstacles"]', 'edits = ["walls"]'), ":5:9", "edits: unknown edit 'walls'"),
    (('map = "tutorial.txt"', 'map = "gone.txt"'), ":3:7", "map: "),
    (('map = "tutorial.txt"', 'generate = "maze 1x1 1"'), ":3:12", "generate: "),
    (('map = "tutorial.txt"', 'mop = "tutorial.txt"'), ":3:7", "mop: unknown key"),
    (('edits = ["obstacles"]', 'edits = 3'), ":5:9", "edits: expected a list of strings"),
    (('title = "Greedy is not optimal"', ''), "", "the exercise has no title"),
])
def test_a_bad_file_names_its_line_and_column(tmp_path: Path, change: tuple[str, str],
                                               where: str, message: str) -> None:
    path = write(tmp_path, GREEDY.replace(*change))
    with pytest.raises(MapError) as caught:
        load_exercise(path)
    assert str(caught.value).startswith(f"{path}{where}: {message}"), str(caught.value)


def test_a_multi_line_condition_names_the_line_it_is_on(tmp_path: Path) -> None:
    text = GREEDY.replace('solved = "greedy.found and astar_manhattan.found and',
                          'solved = """\ngreedy.found and\n  astar_manhattan.fund and')
    text = text.replace('astar_manhattan.cost"\n', 'astar_manhattan.cost"""\n')
    path = write(tmp_path, text)
    with pytest.raises(MapError) as caught:
        load_exercise(path)
    assert str(caught.value).startswith(f"{path}:8:19: solved: 'astar_manhattan.fund'")


@pytest.mark.parametrize(("solved", "points_at"), [
    (r'"greedy.found\tand\nastar_manhattan.fund > 1"', "fund"),
    (r'"greedy.found\u0020and \U00000020greedy.fund > 1"', "fund"),
    (r'"greedy.found and \\ greedy.cost"', "\\\\"),
    (r'"greedy.found and \"x\""', '\\"x'),
    ("'greedy.found and\\t greedy.fund > 1'", "\\t greedy"),  # literal: no escapes
    ('"""\\\n    greedy.found and\\t\\\n  greedy.fund > 1"""', "fund"),
    ('"""\ngreedy.found\\tand \\\\\n  greedy.cost"""', "\\\\"),
    ("'''\ngreedy.found and\n  greedy.fund > 1'''", "fund"),
])
def test_the_column_counts_the_toml_string_s_escapes(tmp_path: Path, solved: str,
                                                     points_at: str) -> None:
    """Each escape (``\\t``, ``\\"``, ``\\u0020``) is one character of the condition but more
    of the file: the error's line and column are the file's."""
    text = re.sub(r"(?m)^solved = .*$", lambda _: f"solved = {solved}", GREEDY)
    path = write(tmp_path, text)
    with pytest.raises(MapError) as caught:
        load_exercise(path)
    m = re.match(rf"{re.escape(str(path))}:(\d+):(\d+): solved: ", str(caught.value))
    assert m is not None, str(caught.value)
    line, col = int(m.group(1)), int(m.group(2))
    assert text.split("\n")[line - 1][col - 1:].startswith(points_at), str(caught.value)


def test_a_byte_order_mark_is_no_part_of_the_toml(tmp_path: Path) -> None:
    path = write(tmp_path, "", "bom.toml")
    path.write_bytes(b"\xef\xbb\xbf" + GREEDY.encode())
    assert load_exercise(path).title == "Greedy is not optimal"


def test_an_exercise_that_is_not_text_says_so(tmp_path: Path) -> None:
    path = tmp_path / "bad.toml"
    path.write_bytes(GREEDY.encode().replace(b"Greedy", b"Gr\xffedy"))
    with pytest.raises(MapError) as caught:
        load_exercise(path)
    assert str(caught.value) == (f"{path}:1:12: not UTF-8 (byte 0xff): an exercise file is "
                                 "UTF-8 text")


def test_python_3_10_reads_exercises_with_tomli(monkeypatch, tmp_path: Path) -> None:
    """Without ``tomllib`` (Python 3.10) the loader takes ``tomli``, which pyproject.toml
    requires there; a bad file is still one line at its line and column."""
    real = exercise_file.toml_parser()  # tomllib, or tomli when the tests run on 3.10
    calls: list[str] = []
    tomli = types.ModuleType("tomli")
    tomli.TOMLDecodeError = real.TOMLDecodeError  # type: ignore[attr-defined]
    tomli.loads = lambda text: calls.append(text) or real.loads(text)  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "tomllib", None)  # `import tomllib` raises ImportError
    monkeypatch.setitem(sys.modules, "tomli", tomli)
    chosen = exercise_file.toml_parser()
    assert chosen is tomli
    monkeypatch.setattr(exercise_file, "_toml", chosen)
    assert load_exercise(write(tmp_path, GREEDY)).title == "Greedy is not optimal"
    assert calls == [GREEDY]
    with pytest.raises(MapError) as bad:
        load_exercise(write(tmp_path, GREEDY.replace("title = ", "title "), "bad.toml"))
    assert (bad.value.line, bad.value.col) == (1, 7)
    pyproject = real.loads((Path(__file__).parents[2] / "pyproject.toml").read_text())
    assert 'tomli>=1.1; python_version < "3.11"' in pyproject["project"]["dependencies"]


# -- the rules an exercise sets ------------------------------------------------------------

SQUEEZE = """\
title = "Between the walls"
text = "Reach the goal."
map = "squeeze.txt"
searches = ["bfs", "astar"]
solved = "bfs.found"
"""


def test_the_rules_an_exercise_sets_are_every_search_s(tmp_path: Path) -> None:
    """With eight moves the robot slips diagonally between two walls; with ``order`` (N, E,
    S, W) it cannot, in every search the exercise runs, and the verdict says so."""
    (tmp_path / "squeeze.txt").write_text("S#\n#G\n")
    eight = load_exercise(write(tmp_path, SQUEEZE, "eight.toml"))
    assert eight.rules == "" and grade(eight, eight.grid).solved
    four = load_exercise(write(tmp_path, SQUEEZE + 'order = "N,E,S,W"\n', "four.toml"))
    assert four.rules == "moves N,E,S,W"
    assert [c.semantics.order for _, c in four.searches] == [("N", "E", "S", "W")] * 2
    verdict = grade(four, four.grid)
    assert not verdict.solved and verdict.reason == "no path to the goal"
    never = load_exercise(write(tmp_path, SQUEEZE + 'corners = "never"\n', "never.toml"))
    assert never.rules == "corners: never" and not grade(never, never.grid).solved
    every = load_exercise(write(tmp_path, SQUEEZE + (
        'order = "N,E,S,W,NE,SE,SW,NW"\ncorners = "one"\ngoal_test = "expand"\n'
        'heuristic = "manhattan"\ntree_search = true\n'), "every.toml"))
    (_, bfs), (_, astar) = every.searches
    assert (bfs.semantics.corners, bfs.semantics.goal_test, bfs.semantics.tree_search,
            astar.semantics.heuristic) == ("one", "expand", True, "manhattan")
    assert every.rules == ("moves N,E,S,W,NE,SE,SW,NW · corners: one · tree search · "
                           "goal test on expand · heuristic manhattan")
    visits = load_exercise(write(tmp_path, SQUEEZE.replace('"astar"', '"dfs"')
                                 + 'visit = "expand"\n', "visit.toml"))
    assert all(c.semantics.visit == "expand" for _, c in visits.searches)


def test_the_shipped_maze_exercise_is_four_connected() -> None:
    """tests/data/exercises/maze-4-connected.toml (docs/04-exercises.md's example): unsolved
    as it starts, solved with the goal moved, under its own rules."""
    ex = load_exercise(ROOT / "tests/data/exercises/maze-4-connected.toml")
    assert ex.rules == "moves N,E,S,W · corners: never"
    assert not grade(ex, ex.grid).solved
    grid = ex.grid.copy()
    grid.goal = (8, 0)
    assert grade(ex, grid).said == "BFS's path has 8 moves, DFS's 16; BFS expanded 10 nodes, DFS 58"


@pytest.mark.parametrize(("rules", "where", "message"), [
    ('order = "N,Q"\n', ":6:9", "order: "),
    ('order = ["N", "E"]\n', ":6:9", "order: expected a string"),
    ('corners = "sometimes"\n', ":6:11", "corners: 'sometimes': use always, one, never"),
    ('visit = "later"\n', ":6:9", "visit: 'later': use generate, expand"),
    ('goal_test = "never"\n', ":6:13", "goal_test: 'never': use generate, expand"),
    ('heuristic = "guess"\n', ":6:13", "heuristic: 'guess': use octile"),
    ('tree_search = "yes"\n', ":6:15", "tree_search: expected true or false"),
    ('tree_search = true\nvisit = "expand"\n', ":7:9", "visit: does not apply with tree_search"),
    ('visit = "expand"\n', ":6:9", "visit: the visit rule does not apply to A*"),
])
def test_a_bad_rule_names_its_line_and_column(tmp_path: Path, rules: str, where: str,
                                              message: str) -> None:
    (tmp_path / "squeeze.txt").write_text("S#\n#G\n")
    path = write(tmp_path, SQUEEZE + rules, "rules.toml")
    with pytest.raises(MapError) as caught:
        load_exercise(path)
    assert str(caught.value).startswith(f"{path}{where}: {message}"), str(caught.value)


def test_a_heuristic_for_searches_that_use_none_is_refused(tmp_path: Path) -> None:
    (tmp_path / "squeeze.txt").write_text("S#\n#G\n")
    path = write(tmp_path, SQUEEZE.replace('"astar"', '"dfs"') + 'heuristic = "zero"\n')
    with pytest.raises(MapError) as caught:
        load_exercise(path)
    assert str(caught.value) == (f"{path}:6:13: heuristic: none of the searches uses a "
                                 "heuristic (greedy and astar do)")


def test_a_verdict_groups_its_figures_in_thousands() -> None:
    """A corridor 1,200 moves long: "both paths have 1,200 moves", as every count is said;
    the comparison's sentence too."""
    from tui_search.engine.maps.grid import Grid
    from tui_search.engine.search.compare import comparison, summary_sentence

    corridor = Grid(1, 1201, start=(0, 0), goal=(0, 1200))
    verdict = grade(built_in_exercise(2), corridor)
    assert verdict.reason.startswith("both paths have 1,200 moves; BFS expanded 1,200 nodes")
    outcomes = [out for _, _, out in verdict.outcomes]
    assert summary_sentence(comparison(["BFS", "DFS"], outcomes)) == (
        "BFS expanded 1,200 nodes, DFS 1,200; both paths have 1,200 moves")

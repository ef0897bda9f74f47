"""Bidirectional search on the command line: ``-a bibfs|biucs|biastar`` headless, ``--stop
proven|first-meeting``, the trace's ``"dir"`` on every line, the JSON's meeting and why it
stopped, compare mode's ``biastar:first-meeting``, and PathFinding.js #28's map remade
(``maps/pathfinding-js-28.txt``): the first meeting answers 14.24 (10 + 3·sqrt 2), the proven
one 13.66 (8 + 4·sqrt 2)."""

from __future__ import annotations

import json
from math import sqrt

import pytest

from tests.helpers import MAPS, grid_from_rows
from tests.test_cli import TUTORIAL, run_cli

TRAP = str(MAPS / "pathfinding-js-28.txt")


def _json(capsys, *argv: str) -> dict:
    code, out, err = run_cli(capsys, "--headless", "--json", *argv)
    assert code == 0 and err == ""
    result: dict = json.loads(out)
    return result


def test_the_trap_first_meeting_answers_the_longer_path(capsys) -> None:
    first = _json(capsys, TRAP, "-a", "biastar", "--stop", "first-meeting")
    assert round(first["cost"], 2) == 14.24
    assert first["cost"] == pytest.approx(10 + 3 * sqrt(2), abs=1e-6)
    assert first["meeting"] == [7, 3] and first["semantics"]["stop"] == "first-meeting"
    assert "both searches reached (7,3): with first-meeting this is the path, cost 14.24" in (
        first["stopped"])


def test_the_trap_proven_answers_the_optimum(capsys) -> None:
    proven = _json(capsys, TRAP, "-a", "biastar")
    astar = _json(capsys, TRAP, "-a", "astar")
    assert round(proven["cost"], 2) == 13.66
    assert proven["cost"] == pytest.approx(8 + 4 * sqrt(2), abs=1e-6)
    assert proven["cost"] == pytest.approx(astar["cost"], abs=1e-9)
    assert proven["semantics"]["stop"] == "proven" and proven["meeting"] == [8, 3]
    assert "proven the cheapest" in proven["stopped"] and "front-to-end" in proven["stopped"]
    assert proven["semantics"]["goal_test"] is None


def test_compare_shows_first_meeting_beside_proven(capsys) -> None:
    code, out, _ = run_cli(capsys, TRAP, "--headless", "--compare",
                           "biastar:first-meeting,biastar")
    assert code == 0
    first, proven = [line for line in out.splitlines() if line.startswith("  BiA*")][:2]
    assert "BiA* (first-meeting)" in first and "14.243" in first
    assert "13.657 *" in proven


def test_every_trace_line_says_its_direction(capsys) -> None:
    code, out, _ = run_cli(capsys, TRAP, "--headless", "-a", "bibfs", "--trace", "-")
    lines = [json.loads(line) for line in out.splitlines()]
    assert code == 0 and lines
    assert [line["dir"] for line in lines] == [("forward", "backward")[i % 2]
                                               for i in range(len(lines))]
    assert lines[0]["node"] == [5, 4] and lines[1]["node"] == [15, 4]
    one_way = run_cli(capsys, TRAP, "--headless", "-a", "bfs", "--trace", "-")[1]
    assert '"dir": "forward"' not in one_way


def test_the_text_says_why_it_stopped(capsys) -> None:
    code, out, _ = run_cli(capsys, TUTORIAL, "--headless", "-a", "bibfs")
    assert code == 0 and "Bidirectional BFS" in out
    assert "stopped:      the best meeting" in out and "smallest depths sum to" in out


def test_on_a_graph_the_backward_search_takes_the_roads_backwards(capsys) -> None:
    first = _json(capsys, "romania", "-a", "biucs", "--stop", "first-meeting")
    proven = _json(capsys, "romania", "-a", "biucs")
    assert first["cost"] == 450 and proven["cost"] == 418  # the book's cheapest: 418
    assert _json(capsys, "romania", "-a", "biastar")["semantics"]["heuristic"] == "euclidean"


@pytest.mark.parametrize(("argv", "said"), [
    ((TRAP, "-a", "biastar", "--replay", str(MAPS / "tutorial.txt")),
     "--replay shows a trace beside a one-way search; biastar's trace is checked by"),
    ((TRAP, "--headless", "-a", "astar", "--stop", "proven"), "--stop applies to -a bibfs"),
    ((TRAP, "--headless", "-a", "bibfs", "--visit", "expand"), "visit rule does not apply"),
    ((TRAP, "--headless", "-a", "biastar", "--weight", "2"), "--weight applies to -a astar"),
    (("romania", "--headless", "-a", "biastar", "--heuristic", "table"),
     "needs one to the start"),
    ((TRAP, "--headless", "--compare", "astar:first-meeting,ucs"),
     "a stopping rule or a turn applies to bibfs"),
    ((TRAP, "--headless", "-a", "bfs", "--turn", "smaller"), "--turn applies to -a bibfs"),
])
def test_what_a_bidirectional_search_refuses(capsys, argv, said: str) -> None:
    code, out, err = run_cli(capsys, *argv)
    assert code == 2 and out == "" and said in err and len(err.strip().splitlines()) == 1


TRAP_EXERCISE = """\
title = "The first meeting"
text = "Find a map where stopping at the first meeting costs more than the proven meeting."
map = "pathfinding-js-28.txt"
searches = ["biastar:first-meeting", "biastar", "bibfs"]
edits = ["obstacles"]
solved = "biastar_first_meeting.cost > biastar.cost and bibfs.expanded > 0"
"""


def test_an_exercise_names_a_bidirectional_search_and_grades_it() -> None:
    from tui_search.engine.course.exercise_file import parse_exercise
    from tui_search.engine.course.grading import grade
    from tui_search.engine.maps.load import parse_map_text

    exercise = parse_exercise(TRAP_EXERCISE, str(MAPS / "trap.toml"))
    assert [name for name, _ in exercise.searches] == ["biastar_first_meeting", "biastar",
                                                        "bibfs"]
    verdict = grade(exercise, exercise.board)
    assert verdict.solved
    assert round(verdict.figures["biastar_first_meeting.cost"], 2) == 14.24
    assert round(verdict.figures["biastar.cost"], 2) == 13.66
    open_map = parse_map_text("S...\n....\n...G\n", "open.txt")
    assert not grade(exercise, open_map).solved  # no wall: the first meeting is the best


def test_an_exercise_with_a_bidirectional_search_is_graded_headless(capsys,
                                                                     tmp_path) -> None:
    (tmp_path / "pathfinding-js-28.txt").write_text((MAPS / "pathfinding-js-28.txt")
                                                    .read_text("utf-8"), "utf-8")
    path = tmp_path / "trap.toml"
    path.write_text(TRAP_EXERCISE, "utf-8")
    code, out, _ = run_cli(capsys, "--exercise", str(path), "--headless")
    assert code == 0 and "solved" in out


def test_the_pseudocode_moves_its_lines_with_the_stopping_rule(capsys) -> None:
    from tui_search.engine.search.choices import Semantics
    from tui_search.engine.search.pseudocode import pseudocode
    from tui_search.engine.search.registry import get_algorithm

    proven = pseudocode(get_algorithm("biastar"), Semantics())
    first = pseudocode(get_algorithm("biastar"), Semantics(stop="first-meeting"))
    assert proven.number("proven") == proven.number("take") - 1  # checked before each take
    assert "front-to-end" in proven.lines[proven.number("proven") - 1].text
    assert first.number("proven") is None and first.number("first") == first.number("meet") + 1
    bfs = pseudocode(get_algorithm("bibfs"), Semantics())
    assert "smallest depth forward + smallest depth backward ≥ μ" in bfs.lines[
        bfs.number("proven") - 1].text
    assert bfs.number("cost") is None and bfs.number("discard") is None
    code, out, _ = run_cli(capsys, "--pseudocode", "-a", "biucs", "--stop", "first-meeting")
    assert code == 0 and out.startswith("BiUCS: Bidirectional uniform-cost search (stop at "
                                        "the first meeting)")


def student_bibfs(rows: list[str], first_meeting: bool, backward_forwards: bool = False,
                  meet_on_expand: bool = False) -> list[dict]:
    """A student's bidirectional BFS written again with no tui_search search code, on the
    default eight moves: its trace lines.  ``backward_forwards``: the backward search lists
    a cell's neighbours as the forward one does (the moves not reversed);
    ``meet_on_expand``: the classroom version, which stops when it takes off a cell the
    other search reached (that line adds nothing)."""
    from collections import deque

    from tui_search.engine.maps.grid import DEFAULT_ORDER, DELTAS

    grid = grid_from_rows(rows)
    start, goal = grid.start, grid.goal
    assert start is not None and goal is not None

    def neighbours(cell: tuple[int, int], back: bool) -> list[tuple[int, int]]:
        out = []
        for move in DEFAULT_ORDER:
            dx, dy = DELTAS[move]
            if back and not backward_forwards:
                dx, dy = -dx, -dy
            near = (cell[0] + dx, cell[1] + dy)
            if grid.is_free(near):
                out.append(near)
        return out

    queues = (deque([start]), deque([goal]))
    depths: tuple[dict, dict] = ({start: 0}, {goal: 0})
    best, lines, side = float("inf"), [], 0
    while queues[0] and queues[1]:
        if (not first_meeting and not meet_on_expand
                and depths[0][queues[0][0]] + depths[1][queues[1][0]] >= best):
            break
        node, added, met = queues[side].popleft(), [], False
        if meet_on_expand and node in depths[1 - side]:
            lines.append({"step": len(lines) + 1, "node": list(node),
                          "dir": ("forward", "backward")[side], "successors": []})
            break
        for near in neighbours(node, side == 1):
            if near in depths[side]:
                continue
            depths[side][near] = depths[side][node] + 1
            queues[side].append(near)
            added.append(near)
            if near in depths[1 - side] and depths[0][near] + depths[1][near] < best:
                best = depths[0][near] + depths[1][near]
                met = first_meeting and not meet_on_expand
                if met:
                    break
        lines.append({"step": len(lines) + 1, "node": list(node),
                      "dir": ("forward", "backward")[side],
                      "successors": [{"node": list(a)} for a in added]})
        if met:
            break
        side = 1 - side
    return lines


TRAP_ROWS = (MAPS / "pathfinding-js-28.txt").read_text("utf-8").splitlines()
TRAP_ROWS = [row for row in TRAP_ROWS if not row.startswith(";")]


def _check(capsys, tmp_path, lines: list[dict], *argv: str, board: str = TRAP
           ) -> tuple[int, dict]:
    path = tmp_path / "student.jsonl"
    path.write_text("".join(json.dumps(line) + "\n" for line in lines), "utf-8")
    code, out, err = run_cli(capsys, board, "--headless", "--json", "-a", "bibfs",
                             "--check-trace", str(path), *argv)
    assert err == ""
    return code, json.loads(out)


def test_a_students_bidirectional_bfs_matches_the_reference(capsys, tmp_path) -> None:
    """Written again with no tui_search code, it is the reference step for step, under
    either rule, and the app's own --trace is its lines."""
    proven = student_bibfs(TRAP_ROWS, first_meeting=False)
    code, verdict = _check(capsys, tmp_path, proven)
    assert code == 0 and verdict["matches"] and verdict["steps"] == len(proven)
    own = run_cli(capsys, TRAP, "--headless", "-a", "bibfs", "--trace", "-")[1].splitlines()
    assert [json.loads(line)["node"] for line in own] == [line["node"] for line in proven]
    first = student_bibfs(TRAP_ROWS, first_meeting=True)
    code, verdict = _check(capsys, tmp_path, first, "--stop", "first-meeting")
    assert code == 0 and verdict["matches"]


def test_a_student_who_stops_at_the_first_meeting_is_told_so(capsys, tmp_path) -> None:
    first = student_bibfs(TRAP_ROWS, first_meeting=True)
    code, verdict = _check(capsys, tmp_path, first)
    assert code == 1 and verdict["cause"] == "stopping rule"
    assert "your search stops at the first meeting: both searches reached" in verdict["text"]
    proven = student_bibfs(TRAP_ROWS, first_meeting=False)
    code, verdict = _check(capsys, tmp_path, proven, "--stop", "first-meeting")
    assert code == 1 and verdict["cause"] == "stopping rule"
    assert "your search goes on, as proven does" in verdict["text"]


def test_a_student_who_tests_the_meeting_on_taking_a_cell_off_is_told_so(capsys,
                                                                        tmp_path) -> None:
    """The classroom version: no stop at a push; it stops when it takes off a cell the other
    search reached.  On the trap's map that is 75 steps, 12 moves."""
    lines = student_bibfs(TRAP_ROWS, first_meeting=False, meet_on_expand=True)
    assert len(lines) == 75 and lines[-1]["successors"] == []
    for stop in ((), ("--stop", "first-meeting")):
        code, verdict = _check(capsys, tmp_path, lines, *stop)
        assert code == 1 and verdict["cause"] == "stopping rule"
        assert ("your search tests the meeting when it takes a cell off: it took off (8,2), "
                "which the other search had reached") in verdict["text"]
        assert "tests it when it pushes one (meeting on generation)" in verdict["text"]


def test_a_backward_search_that_does_not_reverse_its_moves(capsys, tmp_path) -> None:
    """The goal in the open (on the trap's map, the goal on the edge, both orders add the
    cells to its left alike): the backward search's second step lists them in another
    order."""
    rows = ["S......", ".......", ".......", "...G...", ".......", "......."]
    board = tmp_path / "open.txt"
    board.write_text("\n".join(rows) + "\n", "utf-8")
    lines = student_bibfs(rows, first_meeting=False, backward_forwards=True)
    code, verdict = _check(capsys, tmp_path, lines, board=str(board))
    assert code == 1 and verdict["cause"] == "successors" and verdict["matched_steps"] == 1
    assert "the backward search adds" in verdict["text"]
    for first in (False, True):  # the moves reversed: the reference, either rule
        lines = student_bibfs(rows, first_meeting=first)
        stop = ("--stop", "first-meeting") if first else ()
        assert _check(capsys, tmp_path, lines, *stop, board=str(board))[1]["matches"]


def test_a_search_that_does_not_take_turns(capsys, tmp_path) -> None:
    one_way = [json.loads(line) for line in run_cli(
        capsys, TRAP, "--headless", "-a", "bfs", "--trace", "-")[1].splitlines()]
    code, verdict = _check(capsys, tmp_path, one_way)
    assert code == 1 and verdict["cause"] == "turn" and verdict["matched_steps"] == 1
    assert "one step each in turn, forward first" in verdict["text"]


def _diagnose(capsys, tmp_path, lines: list[dict], *argv: str, board: str = TRAP
              ) -> tuple[int, str]:
    """``--check-trace`` without ``-a``: the exit code and what it printed."""
    path = tmp_path / "student.jsonl"
    path.write_text("".join(json.dumps(line) + "\n" for line in lines), "utf-8")
    code, out, err = run_cli(capsys, board, "--headless", "--check-trace", str(path), *argv)
    assert err == ""
    return code, out


def test_without_a_a_bidirectional_trace_is_diagnosed(capsys, tmp_path) -> None:
    """The diagnosis tries the bidirectional searches too: a student's first-meeting BiBFS
    is named with its rule (exit 0), in text and in JSON."""
    first = student_bibfs(TRAP_ROWS, first_meeting=True)
    code, out = _diagnose(capsys, tmp_path, first)
    assert code == 0
    assert out.splitlines()[0] == ("your trace is BiBFS (stop: first-meeting; order "
                                   f"N,NW,W,SW,S,SE,E,NE), for all {len(first)} steps")
    code, out = _diagnose(capsys, tmp_path, first, "--json")
    obj = json.loads(out)
    assert code == 0 and obj["verdict"] == "match" and obj["bidirectional"] is True
    top = obj["candidates"][0]
    assert (top["algorithm"], top["choices"]["stop"], top["verdict"]) == (
        "bibfs", "first-meeting", "match")


def test_without_a_a_broken_bidirectional_trace_is_told_its_nearest(capsys, tmp_path) -> None:
    """Its backward search lists a cell's neighbours as the forward one does: with the
    start in the open, the forward step says the order, and the backward one parts from it
    (with the start in a corner, the moves not reversed are the moves reversed in another
    order: a BiBFS, and named so)."""
    rows = [".......", ".S.....", ".......", ".......", ".......", ".....G.", "......."]
    board = tmp_path / "open.txt"
    board.write_text("\n".join(rows) + "\n", "utf-8")
    lines = student_bibfs(rows, first_meeting=False, backward_forwards=True)
    code, out = _diagnose(capsys, tmp_path, lines, board=str(board))
    assert code == 1
    text = out.splitlines()
    assert text[0] == "closest:"
    assert text[1].startswith("  BiBFS (stop: proven; order N,NW,W,SW,S,SE,E,NE) up to step "
                              "1; then step 2 (line 2): from (5,5) your search added (5,4), "
                              "(4,4), ")
    assert text[1].endswith("(backward, a cell's successors are the cells a move reaches "
                            "it from)")
    code, out = _diagnose(capsys, tmp_path, lines, "--json", board=str(board))
    obj = json.loads(out)
    assert code == 1 and obj["verdict"] == "closest"
    assert obj["candidates"][0]["cause"] == "successors"


def test_without_a_a_one_way_trace_is_diagnosed_as_before(capsys, tmp_path) -> None:
    one_way = [json.loads(line) for line in run_cli(
        capsys, TRAP, "--headless", "-a", "bfs", "--trace", "-")[1].splitlines()]
    code, out = _diagnose(capsys, tmp_path, one_way)
    assert code == 0 and out.startswith("your trace is BFS (order N,NW,W,SW,S,SE,E,NE; ")
    assert "Bi" not in out
    code, out = _diagnose(capsys, tmp_path, one_way, "--json")
    assert code == 0 and json.loads(out)["bidirectional"] is False

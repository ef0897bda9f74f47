"""Students' searches and the code they copy (``tests/students/``, plain Python): the
diagnosis names each, ``-a`` with its flags matches it all through, and checked against the
search without the flag that models it, the first difference names that one cause."""

from __future__ import annotations

import importlib
import json
from pathlib import Path
from typing import NamedTuple

import pytest

from tests.helpers import grid_from_rows
from tests.test_cli import run_cli
from tui_search.engine.traces.diagnose import diagnose
from tui_search.engine.traces.read import read_trace

ROOT = Path(__file__).resolve().parents[1]
STUDENTS = ROOT / "tests" / "students"

#: The 6x6 map the diagnosis tests use (tests/engine/test_trace_diagnose.py).
ROWS = ["S.....", ".##.#.", "...#..", ".#...#", "...#.G", "......"]
#: Maps where a choice shows: A* with Manhattan beside diagonals re-opens a cell; uniform-cost
#: reaches a cell again cheaper by rounding only; greedy reaches a cell cheaper while it waits.
REOPENS = ["S......", "#.#....", "...#...", "....#.#", "#.#.##.", "#..#.#.", ".##..#G"]
ROUNDING = ["S#..#.#.", "........", ".#......", "....#...", "........", "........",
            "..#.....", "#......G"]
GREEDY = ["S.#....", "#.###..", "..#####", ".#.....", "...#..#", "....#..", "...##.G"]
SMALL = ["S..", ".#.", "..G"]
#: Greedy meets a tie of h whose newer entry was reached more cheaply (found among random
#: 7x7 maps: the first where a greedy search taking the lower g of a tie parts from one
#: taking the oldest).
LOW_G = ["....#..", "...#...", "#...#.#", ".....#G", ".....#.", "S.....#", "......."]
#: A* meets a tie of f whose entries differ in h, and the older has the lower h (found among
#: random 6x6 maps, as LOW_G was).
HIGH_H = ["......", ".....#", "S.#...", "...#.G", "......", "......"]
#: The order of the students' four moves.
NESW = ["--order", "N,E,S,W"]


class Student(NamedTuple):
    module: str
    rows: list[str]
    flags: list[str]  # -a and its flags, which match the trace all through
    named: str  # how the diagnosis's first line names it
    without: list[str]  # the flags without the one that models it
    cause: str  # what the first difference then says


STUDENT_SEARCHES = [
    Student("bfs_goal_on_pop", ROWS, ["-a", "bfs", "--goal-test", "expand", *NESW],
            "BFS (order E,S,W; visit on generate; goal test on expand)",
            ["-a", "bfs", "--order", "E,S,W"],
            "BFS stops when it adds the goal (the goal tested on generate), yours goes on"),
    Student("bfs_visited_on_pop", ROWS,
            ["-a", "bfs", "--visit", "expand-again", "--goal-test", "expand", *NESW],
            "BFS (order E,W,N,S; visit on expand, expanded again; goal test on expand)",
            ["-a", "bfs", "--visit", "expand", "--goal-test", "expand", "--order", "E,W,N,S"],
            "was expanded already at step 19: your search expanded it twice, as a search "
            "that marks cells visited when it takes them off, but does not check the node it "
            "takes off, does"),
    Student("bfs_with_a_stack", ROWS, ["-a", "dfs", *NESW],
            "DFS (order N,E,S; visit on generate; goal test on generate)",
            ["-a", "bfs", "--order", "N,E,S"],
            "BFS takes (1,0), the oldest cell on its queue; your trace takes (0,1), the newest, "
            "as a stack does (a DFS: -a dfs)"),
    Student("dfs_recursive_neighbours", ROWS, ["-a", "dfs", "--recursive", "--goal-test",
                                               "expand", *NESW],
            "a recursive DFS (order E,S,W; a line lists the neighbours; goal test on expand)",
            ["-a", "dfs", "--visit", "expand", "--goal-test", "expand", "--order", "E,S,W"],
            "DFS takes (0,1), the last cell step 1 pushed; your trace takes (1,0), the first it "
            "listed, and then a cell it added, as a recursion calling itself on each neighbour "
            "in turn does (--recursive)"),
    Student("dfs_recursive_calls", ROWS, ["-a", "dfs", "--recursive-lines", "calls", *NESW],
            "a recursive DFS (order E,S,W; a line lists the calls; goal test on generate)",
            ["-a", "dfs", "--recursive", "--order", "E,S,W"],
            "your line lists the cells the call recursed into, not all the neighbours it "
            "would try (--recursive-lines calls)"),
    Student("astar_heapq_tuples", ROWS,
            ["-a", "astar", "--heuristic", "manhattan", "--ties", "node", *NESW],
            "A* (manhattan; ties: smallest cell first; order E,N,S; goal test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", "--order", "E,N,S"],
            "and your search takes the smallest cell of the tie, as a heap of (f, (x, y)) "
            "tuples does; this search takes the oldest entry (--ties node)"),
    Student("astar_closed_set", REOPENS,
            ["-a", "astar", "--heuristic", "manhattan", "--reopen", "no", "--order",
             "N,NE,E,SE,S,SW,W,NW"],
            "A* (manhattan; no re-opening; order N,NE,E,SE,S,SW; goal test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", "--order", "N,NE,E,SE,S,SW,W,NW"],
            "your trace does not: it never re-opens a cell (a closed set: --reopen no)"),
    Student("greedy_closed_set", GREEDY,
            ["-a", "greedy", "--heuristic", "manhattan", "--reopen", "no", "--order",
             "N,E,S,W"],
            "Greedy (manhattan; no re-opening; order E,W,N,S; goal test on expand)",
            ["-a", "greedy", "--heuristic", "manhattan", "--order", "N,E,S,W"],
            "it never re-opens a cell (a closed set: --reopen no)"),
    Student("ucs_float_compare", ROUNDING,
            ["-a", "ucs", "--cost-tolerance", "0", "--order", "N,NE,E,SE,S,SW,W,NW"],
            "UCS (exact costs; order NE,E,SE,S; goal test on expand)",
            ["-a", "ucs", "--order", "N,NE,E,SE,S,SW,W,NW"],
            "which UCS calls no cheaper (cost tolerance 1e-09); yours compares costs exactly "
            "(--cost-tolerance 0)"),
    Student("bfs_tree_search", SMALL,
            ["-a", "bfs", "--tree-search", "--no-path-check", "--goal-test", "expand", *NESW],
            "BFS (order N,E,S,W; tree search, no path check; goal test on expand)",
            ["-a", "bfs", "--tree-search", "--goal-test", "expand", *NESW],
            "it is on the path to (1,0), which tree search with a path check skips; yours "
            "skips nothing (--no-path-check)"),
    Student("iddfs_recursive", SMALL,
            ["-a", "iddfs", "--recursive", "--tree-search", "--no-path-check", "--goal-test",
             "expand", *NESW],
            "a recursive IDDFS (order N,E,S,W; a line lists the neighbours; tree search, no "
            "path check; goal test on expand)",
            ["-a", "iddfs", "--tree-search", "--no-path-check", "--goal-test", "expand",
             *NESW],
            "IDDFS takes (0,1), the last cell step 2 pushed; your trace takes (1,0), the first "
            "it listed, and then a cell it added, as a recursion calling itself on each "
            "neighbour in turn does (--recursive)"),
    Student("astar_library_start_again", ROWS,
            ["-a", "astar", "--heuristic", "manhattan", "--mark-start", "no", *NESW],
            "A* (manhattan; start not marked; order E,S,W; goal test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", "--order", "E,S,W"],
            "your trace pushes the start (0,0) again: A* marks the start reached when it "
            "begins"),
    Student("astar_ties_low_h", ROWS,
            ["-a", "astar", "--heuristic", "manhattan", "--ties", "low-h", *NESW],
            "A* (manhattan; ties: lower h first; order E,S,W; goal test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", "--order", "E,S,W"],
            "and your search takes the lower h of the tie (7.00, not 8.00); this search takes "
            "the oldest entry (--ties low-h)"),
    Student("astar_sorted_list", ROWS,
            ["-a", "astar", "--heuristic", "manhattan", "--ties", "lifo", *NESW],
            "A* (manhattan; ties: newest first; order E,N,S; goal test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", "--order", "E,N,S"],
            # (0,1) is the newest entry and the smallest cell: the trace goes on as the newest
            "and your search takes the newest entry of the tie; this search takes the oldest "
            "entry (--ties lifo)"),
    Student("greedy_ties_low_g", LOW_G,
            ["-a", "greedy", "--heuristic", "manhattan", "--ties", "low-g", *NESW],
            "Greedy (manhattan; ties: lower g first; order N,E,S,W; goal test on expand)",
            ["-a", "greedy", "--heuristic", "manhattan", *NESW],
            "h ties at 6.00, and your search takes the lower g of the tie (4.00, not 6.00); "
            "this search takes the oldest entry (--ties low-g)"),
    Student("astar_ties_high_h", HIGH_H,
            ["-a", "astar", "--heuristic", "manhattan", "--ties", "high-h", *NESW],
            "A* (manhattan; ties: higher h first; order N,E,S; goal test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", *NESW],
            "f ties at 8.00, and your search takes the higher h of the tie (5.00, not 4.00); "
            "this search takes the oldest entry (--ties high-h)"),
    Student("greedy_ties_high_g", REOPENS,
            ["-a", "greedy", "--heuristic", "manhattan", "--ties", "high-g", *NESW],
            "Greedy (manhattan; ties: higher g first; order E,S,W; goal test on expand)",
            ["-a", "greedy", "--heuristic", "manhattan", *NESW],
            "h ties at 6.00, and your search takes the higher g of the tie (10.00, not 6.00); "
            "this search takes the oldest entry (--ties high-g)"),
    Student("astar_heapq_diagonal", REOPENS,
            ["-a", "astar", "--heuristic", "manhattan", "--ties", "node", "--cost-tolerance",
             "0", "--order", "N,NE,E,SE,S,SW,W,NW"],
            "A* (manhattan; ties: smallest cell first; exact costs; order N,NE,E,SE,S,SW; goal "
            "test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", "--cost-tolerance", "0", "--order",
             "N,NE,E,SE,S,SW,W,NW"],
            # an out-of-date entry taken off at a tie: a tie rule, not a cell expanded twice
            "your trace expands (2,5): f ties at 11.66, and your search takes the smallest "
            "cell of the tie"),
    Student("astar_red_blob", ROWS,
            ["-a", "astar", "--heuristic", "manhattan", "--ties", "node", "--order",
             "E,W,N,S", "--flip-even"],
            "A* (manhattan; ties: smallest cell first; order E,N,S, reversed where x + y is "
            "even; goal test on expand)",
            ["-a", "astar", "--heuristic", "manhattan", "--ties", "node", "--order",
             "E,W,N,S"],
            "the reverse of its order, as a grid reversing its moves on every other cell "
            "does (--flip-even)"),
    Student("dfs_autograder", ROWS,
            ["-a", "dfs", "--visit", "expand", "--goal-test", "expand", "--order", "N,S,E,W"],
            "DFS (order N,S,E,W; visit on expand; goal test on generate)",
            ["-a", "dfs", "--order", "N,S,E,W"],
            "a search that marks cells visited when it takes them off goes on as yours does "
            "(--visit expand)"),
]


def trace_of(student: Student) -> str:
    module = importlib.import_module(f"tests.students.{student.module}")
    return module.search(student.rows)


def files(tmp_path: Path, student: Student) -> tuple[str, str]:
    map_file, trace_file = tmp_path / "map.txt", tmp_path / "trace.jsonl"
    map_file.write_text("\n".join(student.rows) + "\n")
    trace_file.write_text(trace_of(student))
    return str(map_file), str(trace_file)


def test_the_students_searches_are_plain_python() -> None:
    """Each is a program of its own: no tui_search, and it runs as a script."""
    for path in sorted(STUDENTS.glob("*.py")):
        if path.stem != "__init__":
            assert "tui_search" not in path.read_text(), path.name
    assert {s.module for s in STUDENT_SEARCHES} == {
        p.stem for p in STUDENTS.glob("*.py") if p.stem != "__init__"}


@pytest.mark.parametrize("student", STUDENT_SEARCHES, ids=lambda s: s.module)
def test_the_diagnosis_names_it(student: Student) -> None:
    grid = grid_from_rows(student.rows)
    diagnosis = diagnose(read_trace(trace_of(student), grid, "t"), grid)
    first = diagnosis.text().splitlines()[0]
    assert diagnosis.matches, diagnosis.text()
    assert first == f"your trace is {student.named}, for all {diagnosis.best[0].steps} steps"


@pytest.mark.parametrize("student", STUDENT_SEARCHES, ids=lambda s: s.module)
def test_a_with_its_flags_matches_it_all_through(capsys, tmp_path: Path,
                                                  student: Student) -> None:
    map_file, trace_file = files(tmp_path, student)
    code, out, err = run_cli(capsys, map_file, "--headless", "--check-trace", trace_file,
                             *student.flags)
    assert (code, err) == (0, "") and out.startswith("matches "), out


@pytest.mark.parametrize("student", STUDENT_SEARCHES, ids=lambda s: s.module)
def test_without_its_flag_the_difference_names_its_cause(capsys, tmp_path: Path,
                                                         student: Student) -> None:
    map_file, trace_file = files(tmp_path, student)
    code, out, _ = run_cli(capsys, map_file, "--headless", "--check-trace", trace_file,
                           *student.without, "--json")
    assert code == 1
    message = json.loads(out)["first_difference"]["message"]
    assert student.cause in message
    assert "reached already, or the corner rule refuses it" not in message

"""``--check-search-py``: a student's ``search.py`` run fenced on the problem the app gives
it, each ``getSuccessors`` call an expansion, checked as an expansions-only trace.  Our own
student's file matches the course's four searches; a file for each common bug is named at its
first difference; a hostile file for each limit ends in one line naming the file and the
line, exit 2, never a traceback, and a file outside the working folder survives."""

from __future__ import annotations

import json
import socket
from pathlib import Path

import pytest

from tests.test_cli import run_cli
from tests.tui.test_app import sync
from tui_search.cli.flags import EXIT_BAD_INPUT, UsageError
from tui_search.cli.main import build_app
from tui_search.cli.parse import parse_options
from tui_search.engine.traces.sandbox import isolation

ROOT = Path(__file__).resolve().parents[1]
STUDENT = str(ROOT / "examples" / "cs188_style" / "search.py")
TWISTY = str(ROOT / "examples" / "cs188_style" / "layouts" / "twistyMaze.lay")
BUGS = ROOT / "tests" / "data" / "cs188"
GRAPH_BFS = str(ROOT / "examples" / "cs188_style" / "tests" / "graph_bfs.test")


@pytest.mark.parametrize(("key", "line"), [
    ("bfs", "your breadthFirstSearch is BFS (order N,S,E,W; visit on expand; goal test on "
     "expand), for all 200 expansions"),
    ("dfs", "your depthFirstSearch is DFS (order N,S,E,W; visit on expand; goal test on "
     "expand), for all 151 expansions"),
    ("ucs", "your uniformCostSearch is UCS (no re-opening; order N,S,E,W; goal test on "
     "expand), for all 200 expansions"),
    ("astar", "your aStarSearch is A* (manhattan; no re-opening; order N,S,E,W; goal test on "
     "expand), for all 114 expansions"),
])
def test_our_students_file_is_the_courses_four_searches(capsys, key: str, line: str) -> None:
    code, out, err = run_cli(capsys, "--check-search-py", STUDENT, TWISTY, "-a", key,
                             "--headless")
    assert (code, err) == (0, "")
    assert out.splitlines()[0] == line
    assert out.splitlines()[-1] == ("  returned: 90 actions, a path to the goal" if key == "dfs"
                                    else "  returned: 58 actions, a path to the goal")


def test_not_served_nor_with_another_search(capsys) -> None:
    """A class server would run the student's file for every visitor: refused, as is a
    search the course's search.py has no function for."""
    code, _, err = run_cli(capsys, "--check-search-py", STUDENT, TWISTY, "--serve")
    assert code == EXIT_BAD_INPUT
    assert err == "tui-search: error: --check-search-py checks one search: leave out --serve\n"
    code, _, err = run_cli(capsys, "--check-search-py", STUDENT, TWISTY, "-a", "iddfs",
                           "--headless")
    assert code == EXIT_BAD_INPUT and err.startswith("tui-search: error: -a iddfs: a student's")


def test_as_json_and_on_a_course_test(capsys) -> None:
    code, out, _ = run_cli(capsys, "--check-search-py", STUDENT, GRAPH_BFS, "--headless",
                           "--json")
    result = json.loads(out)
    assert code == 0 and result["function"] == "breadthFirstSearch"
    assert result["expansions"] == 4 and result["returned"] == ["1:A->C", "0:C->G"]
    assert result["path"] == "2 actions, a path to the goal"


@pytest.mark.parametrize(("student", "board", "key", "first"), [
    ("dfs_visited_on_push.py", TWISTY, "dfs", "your depthFirstSearch: step 16: DFS expands "
     "(33,4) next (the stack's top); your depthFirstSearch expands (29,6), which DFS would "
     "expand at step 17"),
    ("bfs_with_a_stack.py", TWISTY, "bfs", "your breadthFirstSearch: step 4: BFS takes (33,4), "
     "the oldest cell on its queue; your breadthFirstSearch takes (32,3), the newest, as a "
     "stack does (a DFS)"),
    ("goal_on_generate.py", GRAPH_BFS, "bfs", "your breadthFirstSearch: step 4: your "
     "breadthFirstSearch ends after step 3; BFS goes on and expands D (the queue's front)"),
    ("ucs_update.py", str(BUGS / "ties.graph"), "ucs", "your uniformCostSearch: step 3: UCS "
     "expands C next; your uniformCostSearch expands B: g ties at 2.00"),
])
def test_each_common_bug_is_named_at_its_first_difference(capsys, student: str, board: str,
                                                          key: str, first: str) -> None:
    """A DFS marking a state visited when it is pushed; a BFS with a stack; the goal tested
    on generation (the graph test's A B C, not A B C D); and ``PriorityQueue.update``, which
    keeps a state's place among equal priorities where the course's search (a re-push, as
    ``examples/cs188_style/search.py``) puts it last: on ties.graph, S -> A1 B3 C2, then A
    lowers B to 2 -- C (pushed before the re-push) comes out first, B with update."""
    code, out, _ = run_cli(capsys, "--check-search-py", str(BUGS / student), board, "-a", key,
                           "--headless")
    assert code == 1
    assert out.splitlines()[0].startswith(first)
    update = ("  note: a tie of the priority taken another way; PriorityQueue.update keeps a "
              "lowered entry's place among equal priorities, where a re-push (the course's "
              "search) puts it last")
    assert (update in out.splitlines()) == (student == "ucs_update.py")


def test_the_re_push_matches_where_update_parts(capsys) -> None:
    code, out, _ = run_cli(capsys, "--check-search-py", STUDENT, str(BUGS / "ties.graph"),
                           "-a", "ucs", "--headless")
    assert code == 0 and out.startswith("your uniformCostSearch is UCS")


HOSTILE = {
    "loop": ("def breadthFirstSearch(problem):\n    while True:\n        pass\n",
             ":2: breadthFirstSearch still running after 1 s (an endless loop?)"),
    "loop_that_catches": ("def breadthFirstSearch(problem):\n    while True:\n        try:\n"
                          "            while True:\n                pass\n"
                          "        except BaseException:\n            pass\n",
                          ": breadthFirstSearch still running after 1 s (an endless loop "
                          "that ignores the time limit?)"),
    "gigabyte": ("def breadthFirstSearch(problem):\n    return [0] * (1024 ** 3 // 8)\n",
                 ":2: breadthFirstSearch used more than the memory limit (512 MB)"),
    "flood": ("def breadthFirstSearch(problem):\n    while True:\n        print('x' * 999)\n",
              ":3: breadthFirstSearch printed more than 64 KB"),
    "exit": ("import sys\n\ndef breadthFirstSearch(problem):\n    sys.exit(3)\n",
             ":4: breadthFirstSearch called exit (3) instead of returning"),
    "hard_exit": ("import os\n\ndef breadthFirstSearch(problem):\n    os._exit(0)\n",
                  ": breadthFirstSearch ended the process (exit code 0) before returning"),
    "fork": ("import os\n\ndef breadthFirstSearch(problem):\n    os.fork()\n    return []\n",
             ":4: breadthFirstSearch raised PermissionError: starting a process is not "
             "allowed here"),
    "stdin": ("def breadthFirstSearch(problem):\n    return input()\n",
              ":2: breadthFirstSearch raised EOFError: EOF when reading a line"),
    "wrong_type": ("def breadthFirstSearch(problem):\n    return {'a': 1}\n",
                   ":1: breadthFirstSearch returned dict, not a list of actions"),
    "missing": ("def depthFirstSearch(problem):\n    return []\n",
                " has no function breadthFirstSearch"),
    "syntax": ("def breadthFirstSearch(problem)\n    return []\n",
               ":1:32: SyntaxError: expected ':'"),
    "indentation": ("def breadthFirstSearch(problem):\nreturn []\n",
                    ":2:1: IndentationError: expected an indented block after function "
                    "definition on line 1"),
}


@pytest.mark.parametrize("name", list(HOSTILE))
def test_a_hostile_search_py_is_one_line_exit_2(capsys, tmp_path: Path, name: str) -> None:
    text, message = HOSTILE[name]
    student = tmp_path / f"{name}.py"
    student.write_text(text)
    code, out, err = run_cli(capsys, "--check-search-py", str(student), TWISTY, "-a", "bfs",
                             "--headless", "--time-limit", "1")
    assert (code, out) == (EXIT_BAD_INPUT, "")
    assert err == f"tui-search: {student}{message}\n"


def test_a_search_that_never_calls_get_successors_is_a_difference(capsys, tmp_path: Path
                                                                   ) -> None:
    """Returning at once is a search of the wrong kind, in the student's words (exit 1), not
    a trace the app cannot read (exit 2); its JSON and ``--replay`` say the same."""
    student = tmp_path / "lazy.py"
    student.write_text("def breadthFirstSearch(problem):\n    return ['West']\n")
    code, out, err = run_cli(capsys, "--check-search-py", str(student), TWISTY, "-a", "bfs",
                             "--headless")
    assert (code, err) == (1, "")
    assert out.splitlines() == [
        "your breadthFirstSearch never called getSuccessors: it expanded nothing",
        "  returned: action 1, West, walks into a wall"]
    code, out, _ = run_cli(capsys, "--check-search-py", str(student), TWISTY, "-a", "bfs",
                           "--headless", "--json")
    result = json.loads(out)
    assert code == 1 and result["verdict"] == "difference" and result["expansions"] == 0
    assert result["first_difference"]["message"] == (
        "your breadthFirstSearch never called getSuccessors: it expanded nothing")
    with pytest.raises(UsageError) as raised:  # the app's replay of it
        parse_options(["--check-search-py", str(student), TWISTY, "-a", "bfs"])
    assert str(raised.value) == (
        "your breadthFirstSearch never called getSuccessors: it expanded nothing: nothing to "
        "replay")


def test_expanding_nothing_is_right_where_the_start_is_a_goal(capsys, tmp_path: Path) -> None:
    """The course's search takes the start off, finds it a goal and returns [] without one
    call of getSuccessors (as the app's own search of the test expands nothing)."""
    test = tmp_path / "same.test"
    test.write_text('algorithm: "breadthFirstSearch"\ngraph: """\nstart_state: A\n'
                    'goal_states: A\nA 0:A->B B\n"""\n')
    code, out, err = run_cli(capsys, "--check-search-py", STUDENT, str(test), "--headless")
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        "your breadthFirstSearch is right to expand nothing: the start is a goal",
        "  returned: 0 actions, a path to the goal"]


#: A maze whose dot is walled off: no path (BFS expands the start and its one free cell).
WALLED = "%%%%%%\n%P %.%\n%%%%%%\n"


@pytest.mark.parametrize("answer", ["[]", "None"])
def test_no_path_where_none_exists_passes(capsys, tmp_path: Path, answer: str) -> None:
    """Where the search finds no path, an empty answer (``[]``, or ``None`` as the course
    allows) is right: the search matches and Gradescope's "its path" test passes.  Where a
    path exists, ``None`` is still no list of actions (exit 2)."""
    maze = tmp_path / "walled.lay"
    maze.write_text(WALLED)
    student = tmp_path / "search.py"
    student.write_text(Path(STUDENT).read_text().replace(
        "    return []\n", f"    return {answer}\n"))
    out_json = tmp_path / "results.json"
    code, out, err = run_cli(capsys, "--check-search-py", str(student), str(maze), "-a", "bfs",
                             "--headless", "--gradescope", str(out_json))
    assert (code, err) == (0, "")
    lines = out.splitlines()
    assert lines[0] == ("your breadthFirstSearch is BFS (order N,S,E,W; visit on expand; goal "
                        "test on expand), for all 2 expansions")
    assert lines[-1] == "  returned: none, and no path to the goal exists: right"
    data = json.loads(out_json.read_text())
    assert [t["score"] for t in data["tests"]] == [1, 1] and data["score"] == 2
    nothing = tmp_path / "none.py"
    nothing.write_text("def breadthFirstSearch(problem):\n    problem.getSuccessors("
                       "problem.getStartState())\n    return None\n")
    code, _, err = run_cli(capsys, "--check-search-py", str(nothing), TWISTY, "-a", "bfs",
                           "--headless")
    assert code == EXIT_BAD_INPUT
    assert err == (f"tui-search: {nothing}:1: breadthFirstSearch returned NoneType, not a "
                   "list of actions\n")


def test_what_fenced_the_run_is_said(capsys, monkeypatch: pytest.MonkeyPatch) -> None:
    """``--json`` names what fenced the student's process in; where neither Landlock nor a
    network namespace did, one line on stderr says so (the child's Landlock and the
    namespaces made unavailable here by standing in for what the child reported)."""
    from tui_search.engine.traces import sandbox

    code, out, _ = run_cli(capsys, "--check-search-py", STUDENT, GRAPH_BFS, "--headless",
                           "--json")
    assert code == 0
    assert json.loads(out)["isolation"] == isolation(landlock_abi())
    assert json.loads(out)["isolation"].startswith("time, memory, CPU and file-size limits; ")
    real = sandbox.run_student

    def without_landlock(*args: object, **kwargs: object) -> sandbox.StudentRun:
        run = real(*args, **kwargs)  # type: ignore[arg-type]
        return run.replace(landlock=0)

    monkeypatch.setattr(sandbox, "run_student", without_landlock)
    monkeypatch.setattr(sandbox, "_namespaces", False)
    code, out, err = run_cli(capsys, "--check-search-py", STUDENT, GRAPH_BFS, "--headless",
                             "--json")
    assert code == 0 and "writes NOT fenced (no Landlock here)" in json.loads(out)["isolation"]
    assert err == ("tui-search: note: neither Landlock nor a network namespace was available "
                   "here: the student's code ran with the network and could write wherever "
                   "you can (see docs/14-cs188.md)\n")


def test_the_recorded_expansions_are_no_list_on_the_problem(capsys, tmp_path: Path) -> None:
    """The calls of getSuccessors are recorded out of the problem's attributes: a search.py
    that sets ``problem.expanded`` changes nothing of what is checked (code that digs for the
    record can still reach it: the docs say so)."""
    student = tmp_path / "forger.py"
    student.write_text("def breadthFirstSearch(problem):\n"
                       "    problem.getSuccessors(problem.getStartState())\n"
                       "    problem.expanded = [list(problem.getStartState())] * 50\n"
                       "    return []\n")
    code, out, _ = run_cli(capsys, "--check-search-py", str(student), TWISTY, "-a", "bfs",
                           "--headless", "--json")
    assert code == 1 and json.loads(out)["expansions"] == 1


def test_a_file_outside_the_working_folder_survives(capsys, tmp_path: Path) -> None:
    """Where the OS offers Landlock, writes outside the fresh working folder are refused; the
    docs say so, and what is not fenced where it does not."""
    outside = tmp_path / "keep.txt"
    outside.write_text("kept")
    student = tmp_path / "vandal.py"
    student.write_text(f"import os\n\ndef breadthFirstSearch(problem):\n"
                       f"    open({str(outside)!r}, 'w').write('lost')\n    return []\n")
    code, _, err = run_cli(capsys, "--check-search-py", str(student), TWISTY, "-a", "bfs",
                           "--headless")
    if "writes only in its working folder" in isolation(landlock_abi()):
        assert code == EXIT_BAD_INPUT
        assert err == (f"tui-search: {student}:4: breadthFirstSearch raised PermissionError: "
                       f"[Errno 13] Permission denied: {str(outside)!r}\n")
        assert outside.read_text() == "kept"
    else:  # no Landlock: the docs say writes are not fenced here
        assert outside.read_text() == "lost"


def landlock_abi() -> int:
    """The Landlock ABI this kernel offers (0: none)."""
    import ctypes
    import sys

    if sys.platform != "linux":
        return 0
    libc = ctypes.CDLL(None, use_errno=True)
    return max(0, int(libc.syscall(444, None, 0, 1)))


def test_no_network(capsys, tmp_path: Path) -> None:
    """A server listening on this machine's loopback is out of the student's reach (its own
    network namespace, or Landlock's TCP rule)."""
    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen()
        port = server.getsockname()[1]
        student = tmp_path / "net.py"
        student.write_text("import socket\n\ndef breadthFirstSearch(problem):\n"
                           f"    socket.create_connection(('127.0.0.1', {port}), timeout=2)\n"
                           "    return []\n")
        code, _, err = run_cli(capsys, "--check-search-py", str(student), TWISTY, "-a", "bfs",
                               "--headless")
    assert code == EXIT_BAD_INPUT
    assert err.startswith(f"tui-search: {student}:4: breadthFirstSearch raised ")
    assert "Error" in err and len(err.splitlines()) == 1


@sync
async def test_without_headless_the_app_replays_the_students_run() -> None:
    app = build_app(parse_options(["--check-search-py", STUDENT, TWISTY, "-a", "bfs"]))
    async with app.run_test(size=(100, 32)) as pilot:
        await pilot.pause()
        session = app.session
        assert session.algorithm == "bfs" and session.semantics.visit == "expand"
        assert app.session.jumps is not None


def test_an_expansions_only_traces_replay_adds_the_tree_unlisted() -> None:
    """``--replay`` of a trace of expansions only (as a search.py gives): each step adds the
    neighbours it reaches first that a later step expands, marked unlisted, so the replay has a
    tree and the check still compares only the expansions' order."""
    from tui_search.engine.maps.load import load_map
    from tui_search.engine.search.choices import Semantics
    from tui_search.engine.traces.read import read_trace
    from tui_search.engine.traces.replay import replay_of, with_tree

    grid = load_map(ROOT / "maps" / "tutorial.txt")
    text = "".join(f'{{"node": [{x}, {y}]}}\n' for x, y in ((0, 0), (0, 1), (0, 2), (1, 2)))
    trace = read_trace(text, grid, "t.jsonl")
    tree = with_tree(trace, grid, Semantics())  # (0,1)'s neighbours: S (0,2), SE (1,2)
    assert [(s.node, s.successors, s.listed) for s in tree.steps] == [
        ((0, 0), ((0, 1),), False), ((0, 1), ((0, 2), (1, 2)), False),
        ((0, 2), (), False), ((1, 2), (), False)]
    replay = replay_of(trace, grid, "bfs", Semantics(), 100)
    assert replay.verdict.matched == 4

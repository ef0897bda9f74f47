"""``tui-search FILE.test``: the course's test files on the command line -- headless as text
and JSON in the course's words with the ``.solution``'s verdict and its exit code, ``-a``
checked against the test, and the app opened on the test's graph or layout."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from tests.test_cli import run_cli
from tests.tui.test_app import sync
from tui_search.cli.flags import EXIT_BAD_INPUT
from tui_search.cli.main import build_app
from tui_search.cli.parse import parse_options

ROOT = Path(__file__).resolve().parents[1]
TESTS = ROOT / "examples" / "cs188_style" / "tests"
BFS = str(TESTS / "graph_bfs.test")


def test_a_graph_test_headless_in_the_courses_words(capsys) -> None:
    code, out, err = run_cli(capsys, BFS, "--headless")
    assert code == 0 and err == ""
    assert out.splitlines() == [
        f"GraphSearchTest {BFS}: breadthFirstSearch on a graph",
        "  semantics:       visit on expand · goal test on expand",
        "  solution:        1:A->C 0:C->G",
        "  expanded_states: A B C D",
        "  rev_expanded:    A D C B",
        "  the .solution:   agrees with the .solution's solution and expanded_states",
    ]


def test_as_json(capsys) -> None:
    code, out, _ = run_cli(capsys, str(TESTS / "graph_dfs.test"), "--headless", "--json")
    result = json.loads(out)
    assert code == 0
    assert result["solution"] == ["2:A->D", "0:D->G"] and result["expanded_states"] == ["A", "D"]
    assert result["rev_expanded_states"] == ["A", "B", "D"] and result["agrees"] is True
    assert result["algorithm"] == "depthFirstSearch" and result["class"] == "GraphSearchTest"


def test_a_solution_it_disagrees_with_exits_1(capsys, tmp_path: Path) -> None:
    """A ``.solution`` made for BFS that tests the goal when it is pushed (expanded A B C:
    G is found among C's successors) disagrees with the course's BFS."""
    shutil.copy(BFS, tmp_path / "t.test")
    (tmp_path / "t.solution").write_text('solution: "1:A->C 0:C->G"\n'
                                         'expanded_states: "A B C"\n')
    code, out, _ = run_cli(capsys, str(tmp_path / "t.test"), "--headless")
    assert code == 1
    assert out.splitlines()[-1] == ("  the .solution:   disagrees with the .solution: it "
                                    "expects expanded_states 'A B C' and solution "
                                    "'1:A->C 0:C->G'")
    # the choices can still be changed: BFS as the app's default, goal test on generate
    code, out, _ = run_cli(capsys, str(tmp_path / "t.test"), "--headless", "--goal-test",
                           "generate", "--visit", "generate")
    assert "expanded_states: A B C" in out


def test_a_layout_test_and_its_course_count(capsys) -> None:
    code, out, _ = run_cli(capsys, str(TESTS / "pacman_bfs.test"), "--headless")
    assert code == 0
    assert "  expanded_nodes:  29 (rev 29)" in out.splitlines()
    assert out.splitlines()[-1].endswith("agrees with the .solution's solution and "
                                         "expanded_nodes")


def test_a_wrong_search_flag_and_a_bad_file_are_one_line(capsys, tmp_path: Path) -> None:
    code, _, err = run_cli(capsys, BFS, "-a", "dfs", "--headless")
    assert code == EXIT_BAD_INPUT
    assert err == (f"tui-search: error: -a dfs: {BFS} tests breadthFirstSearch (leave -a "
                   "out)\n")
    bad = tmp_path / "bad.test"
    bad.write_text('algorithm: "bfs"\ncostFn: "lambda pos: pos[1]"\nlayout: """\n%P.%\n"""\n')
    code, _, err = run_cli(capsys, str(bad), "--headless")
    assert code == EXIT_BAD_INPUT and len(err.splitlines()) == 1
    assert err.startswith(f"tui-search: {bad}:2:10: costFn 'lambda pos: pos[1]' is not one")


@sync
async def test_the_app_opens_a_tests_graph_and_a_tests_layout() -> None:
    app = build_app(parse_options([BFS]))
    async with app.run_test(size=(100, 32)) as pilot:
        await pilot.pause()
        session = app.session
        assert session.graph is not None and session.graph.start == "A"
        assert session.algorithm == "bfs" and session.semantics.visit == "expand"
    app = build_app(parse_options([str(TESTS / "pacman_stay_east.test")]))
    async with app.run_test(size=(100, 32)) as pilot:
        await pilot.pause()
        session = app.session
        assert session.algorithm == "ucs" and session.map_path is None  # never saved over
        assert session.grid.cost((10, 1)) == 0.5 ** 10
        assert session.semantics.order == ("N", "S", "E", "W")

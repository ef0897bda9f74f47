"""Exercises on graphs (``graph = "FILE"``): read with a graph's rules and edits, graded on a
student's .graph by what it changed (its roads, start, goal, closed nodes: a ``closed`` line),
and the class report over graph files; each bad key one line at its place."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_cli import run_cli
from tui_search.engine.course.exercise_file import load_exercise, parse_exercise
from tui_search.engine.course.grading import grade
from tui_search.engine.maps.graph_file import load_graph, parse_graph
from tui_search.engine.maps.read import MapError

ROOT = Path(__file__).resolve().parents[2]
EXERCISE = ROOT / "tests" / "data" / "exercises" / "romania-greedy.toml"
ROMANIA = ROOT / "maps" / "graphs" / "romania.graph"


def student(tmp_path: Path, name: str, *lines: str, change: tuple[str, str] | None = None
            ) -> Path:
    """Romania with ``lines`` added (and one line changed), as a student hands it in."""
    text = ROMANIA.read_text()
    if change is not None:
        text = text.replace(*change)
    path = tmp_path / f"{name}.graph"
    path.write_text(text + "".join(f"{line}\n" for line in lines))
    return path


def test_the_exercise_reads_with_a_graph_s_rules() -> None:
    ex = load_exercise(EXERCISE)
    assert ex.graph is not None and ex.graph.start == "Arad"
    assert ex.semantics.order == ("file",) and ex.semantics.heuristic == "table"
    assert ex.edits == {"closed"}
    assert [label for label, _ in ex.searches] == ["greedy", "astar"]


def test_a_closed_line_closes_a_node() -> None:
    graph = parse_graph("edge A B\nedge B C\nedge A C 5\nstart A\ngoal C\nclosed B\n", "c.graph")
    assert graph.closed == {"B"}
    with pytest.raises(MapError, match=r"c\.graph:1:8: unknown node 'X'"):
        parse_graph("closed X\nedge A B\n", "c.graph")


def test_graded_on_students_graphs(tmp_path: Path) -> None:
    ex = load_exercise(EXERCISE)
    solved = grade(ex, load_graph(student(tmp_path, "ana", "closed Fagaras")))
    assert solved.solved and solved.reason == "both found the goal; both paths cost 418.00"
    unsolved = grade(ex, ex.board.copy())
    assert not unsolved.solved
    assert unsolved.reason.endswith("Greedy (table)'s path costs 450.00, A* (table)'s 418.00")
    roads = grade(ex, load_graph(student(tmp_path, "bo", "closed Fagaras",
                                         change=("Arad Zerind 75", "Arad Zerind 74"))))
    assert not roads.solved
    assert roads.reason == ("changed the graph's nodes and roads, which the exercise does not "
                            "allow")
    start = grade(ex, load_graph(student(tmp_path, "cy", change=("start Arad", "start Sibiu"))))
    assert start.reason == "changed the start, which the exercise does not allow"


def test_the_class_report_over_graph_files(capsys, tmp_path: Path) -> None:
    files = [student(tmp_path, "ana", "closed Fagaras"), student(tmp_path, "bo"),
             tmp_path / "broken.graph"]
    files[2].write_text("edge A B -1\n")
    code, out, _ = run_cli(capsys, "--exercise", str(EXERCISE), "--headless",
                           *map(str, files))
    lines = out.splitlines()
    assert code == 1
    assert lines[1] == f"{files[0]}: solved — both found the goal; both paths cost 418.00"
    assert lines[2].startswith(f"{files[1]}: not solved")
    assert lines[3] == (f"{files[2]}: unreadable — line 1, column 10: the cost '-1' is not "
                        "above 0")
    assert lines[4] == "1 of 3 solved, 1 not solved, 1 unreadable"


@pytest.mark.parametrize(("extra", "message"), [
    ('corners = "never"\n', "corners: is a grid's rule: a graph has no cells"),
    ('order = "N,E"\n', "order: 'N,E': on this graph use file, name"),
    ('heuristic = "octile"\n', "heuristic: 'octile': on this graph use table, euclidean, zero"),
    ('map = "x.txt"\n', "graph: give the exercise a map, a generate or a graph (one)"),
])
def test_a_rule_that_does_not_fit_a_graph_is_named_at_its_key(extra: str, message: str) -> None:
    text = EXERCISE.read_text() + extra
    with pytest.raises(MapError) as caught:
        parse_exercise(text, str(EXERCISE))
    assert message in str(caught.value)
    assert caught.value.line is not None


def test_a_grid_s_edit_on_a_graph_is_refused() -> None:
    text = EXERCISE.read_text().replace('edits = ["closed"]', 'edits = ["obstacles"]')
    with pytest.raises(MapError, match="unknown edit 'obstacles' on a graph"):
        parse_exercise(text, str(EXERCISE))

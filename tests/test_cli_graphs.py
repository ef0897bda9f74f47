"""Graphs on the command line: ``tui-search romania`` and ``FILE.graph`` headless (text, JSON,
``--trace`` naming the nodes, ``--compare``), their start and goal by name, the choices that
apply (``--order file|name``, ``--heuristic table|euclidean|zero``), a table checked against
the roads, ``--check-trace`` with and without ``-a``, and each bad input one line, exit 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.test_cli import run_cli
from tui_search.cli.flags import EXIT_BAD_INPUT

ROOT = Path(__file__).resolve().parents[1]
GRAPHS = ROOT / "maps" / "graphs"
DFS_BACKTRACKS = str(GRAPHS / "dfs-backtracks.graph")
GREEDY = str(GRAPHS / "greedy-not-optimal.graph")


def test_romania_under_a_star_as_text(capsys) -> None:
    code, out, err = run_cli(capsys, "romania", "-a", "astar", "--headless")
    assert code == 0 and err == ""
    assert out.splitlines() == [
        "A* search on romania (built-in): path found",
        "  path:         4 roads (Arad, Sibiu, Rimnicu, Pitesti, Bucharest)",
        "  cost:         418",
        "  expanded:     6",
        "  generated:    11",
        "  max frontier: 6",
    ]


@pytest.mark.parametrize(("key", "path", "cost"), [
    ("astar", ["Arad", "Sibiu", "Rimnicu", "Pitesti", "Bucharest"], 418),
    ("ucs", ["Arad", "Sibiu", "Rimnicu", "Pitesti", "Bucharest"], 418),
    ("greedy", ["Arad", "Sibiu", "Fagaras", "Bucharest"], 450),
    ("bfs", ["Arad", "Sibiu", "Fagaras", "Bucharest"], 450),
])
def test_romania_as_json_names_the_nodes(capsys, key: str, path: list[str], cost: float) -> None:
    code, out, _ = run_cli(capsys, "romania", "-a", key, "--headless", "--json")
    result = json.loads(out)
    assert code == 0
    assert result["path"] == path and result["moves"] == path[1:]
    assert result["cost"] == cost and result["length"] == len(path) - 1
    assert result["semantics"]["order"] == ["file"]
    assert result["semantics"]["corners"] is None  # a grid's choice
    assert result["semantics"]["heuristic"] == ("table" if key in ("astar", "greedy") else None)


def test_the_trace_names_the_nodes_and_is_checked_back(capsys, tmp_path: Path) -> None:
    trace = tmp_path / "bfs.jsonl"
    assert run_cli(capsys, "romania", "-a", "bfs", "--headless", "--trace", str(trace))[0] == 0
    first = json.loads(trace.read_text().splitlines()[0])
    assert first == {"step": 1, "node": "Arad", "successors": ["Zerind", "Sibiu", "Timisoara"]}
    code, out, _ = run_cli(capsys, "romania", "-a", "bfs", "--headless", "--check-trace",
                           str(trace))
    assert code == 0
    assert out.startswith("matches BFS (order file; visit on generate; goal test on generate)")
    code, out, _ = run_cli(capsys, "romania", "-a", "dfs", "--headless", "--check-trace",
                           str(trace))
    assert code == 1 and out.startswith("step 2: DFS takes Timisoara")


@pytest.mark.parametrize("key", ["bfs", "dfs", "ucs", "astar"])
def test_a_graph_trace_is_diagnosed_as_the_search_that_wrote_it(capsys, tmp_path: Path,
                                                                 key: str) -> None:
    trace = tmp_path / f"{key}.jsonl"
    run_cli(capsys, "romania", "-a", key, "--headless", "--trace", str(trace))
    code, out, _ = run_cli(capsys, "romania", "--headless", "--check-trace", str(trace),
                           "--json")
    assert code == 0
    best = json.loads(out)["candidates"][0]
    assert best["algorithm"] in ({key, "ucs", "astar"} if key in ("ucs", "astar") else {key})


def test_order_name_and_the_ends_by_name(capsys) -> None:
    code, out, _ = run_cli(capsys, DFS_BACKTRACKS, "-a", "dfs", "--headless", "--json")
    assert json.loads(out)["path"] == ["S", "B", "G"]
    code, out, _ = run_cli(capsys, DFS_BACKTRACKS, "-a", "dfs", "--headless", "--json",
                           "--order", "name")
    result = json.loads(out)
    assert result["semantics"]["order"] == ["name"] and result["path"] == ["S", "B", "G"]
    code, out, _ = run_cli(capsys, "romania", "-a", "ucs", "--headless", "--json",
                           "--start", "Oradea", "--goal", "Eforie")
    path = json.loads(out)["path"]
    assert path[0] == "Oradea" and path[-1] == "Eforie"


def test_a_comparison_on_a_graph(capsys) -> None:
    code, out, _ = run_cli(capsys, GREEDY, "--headless", "--compare", "greedy,astar", "--json")
    runs = json.loads(out)["runs"]
    assert [r["cost"] for r in runs] == [11, 4]


def test_a_table_that_says_too_much_is_warned_of(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "bad.graph"
    bad.write_text("edge A B 2\nedge B C 3\nstart A\ngoal C\nh A 5\nh B 9\nh C 0\n")
    code, out, _ = run_cli(capsys, str(bad), "-a", "astar", "--headless")
    assert code == 0
    assert ("  warning:      the table estimate is not admissible: h(B) = 9 but the cheapest "
            "way to a goal costs 3 (A* may miss the cheapest path)") in out.splitlines()
    code, out, _ = run_cli(capsys, str(bad), "-a", "bfs", "--headless")
    assert "warning" not in out  # BFS uses no estimate


@pytest.mark.parametrize(("argv", "message"), [
    (["romania", "--start", "Paris"], "--start 'Paris': romania.graph has no node of that name"),
    (["romania", "--order", "N,E"], "--order 'N,E': a graph's order is file or name"),
    (["romania", "-a", "astar", "--heuristic", "octile"],
     "--heuristic octile: a graph's heuristics are table, euclidean, zero"),
    ([DFS_BACKTRACKS, "-a", "astar", "--heuristic", "table"],
     "--heuristic table: dfs-backtracks.graph has no h lines"),
    ([DFS_BACKTRACKS, "-a", "astar", "--heuristic", "euclidean"],
     "--heuristic euclidean: dfs-backtracks.graph's nodes have no places"),
    (["romania", "--corners", "never"], "--corners is a grid's: a graph has no cells"),
    (["romania", "--terrain", "x.terrain"], "--terrain is a grid's: a graph has no cells"),
])
def test_a_flag_that_does_not_fit_a_graph_is_one_line(capsys, argv: list[str],
                                                       message: str) -> None:
    code, out, err = run_cli(capsys, *argv, "--headless")
    assert code == EXIT_BAD_INPUT and out == ""
    assert len(err.splitlines()) == 1 and message in err


def test_a_bad_graph_file_names_its_line_and_column(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "bad.graph"
    bad.write_text("edge A B 2\nedge B C -3\nstart A\ngoal C\n")
    code, out, err = run_cli(capsys, str(bad), "--headless")
    assert code == EXIT_BAD_INPUT and out == ""
    assert len(err.splitlines()) == 1 and f"{bad}:2:" in err

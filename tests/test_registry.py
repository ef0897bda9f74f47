"""The algorithm registry is the one place that names and describes algorithms."""

from __future__ import annotations

import ast
from pathlib import Path

from textual.binding import Binding

from tui_search.cli.parser import build_parser
from tui_search.engine.search.registry import ALGORITHMS, BIDIRECTIONAL, Frontier
from tui_search.tui.dialogs.help import KEYS
from tui_search.tui.screens.main import MainScreen

TUI = Path(__file__).resolve().parents[1] / "tui_search" / "tui"


def test_no_ui_module_compares_algorithm_names() -> None:
    """What a panel shows follows from the registry entry (its frontier, whether it
    iterates), never from an ``algorithm == "bfs"`` test."""
    keys = set(ALGORITHMS)
    found = []
    for path in TUI.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text("utf-8"))):
            if isinstance(node, ast.Compare):
                for operand in [node.left, *node.comparators]:
                    if isinstance(operand, ast.Constant) and operand.value in keys:
                        found.append(f"{path.name}:{node.lineno}")
    assert found == []


def test_the_keys_the_cli_and_the_help_come_from_the_registry() -> None:
    bindings = {b.action: b for b in Binding.make_bindings(MainScreen.BINDINGS)}
    for algo in ALGORITHMS.values():
        binding = bindings[f"algorithm({algo.key!r})"]
        assert binding.key == algo.app_key and binding.description == algo.short
    choices = next(a for a in build_parser()._actions if a.dest == "algorithm").choices
    assert list(choices) == [*ALGORITHMS, *BIDIRECTIONAL]
    keys_line = dict(KEYS)[" ".join(a.app_key for a in ALGORITHMS.values())]
    assert keys_line == ("BFS / DFS / IDDFS / UCS / Greedy / A* / IDA* "
                         "(a new search, same map)")


def test_a_priority_queue_is_titled_by_its_order() -> None:
    titles = {a.key: a.frontier_title for a in ALGORITHMS.values()}
    assert titles["astar"] == "Priority queue (A*: f = g + h)"
    assert titles["ucs"] == "Priority queue (UCS: g)"
    assert titles["greedy"] == "Priority queue (Greedy: h)"
    assert titles["bfs"] == "Queue (FIFO)"
    assert titles["idastar"] == "Stack (LIFO) (IDA*: f = g + h ≤ limit)"
    assert [a.key for a in ALGORITHMS.values() if a.informed] == ["greedy", "astar", "idastar"]
    assert [a.key for a in ALGORITHMS.values() if a.queued] == ["ucs", "greedy", "astar"]
    assert all(a.goal_test == "expand" for a in ALGORITHMS.values() if a.weighted)


def test_frontier_words() -> None:
    assert Frontier.FIFO.title == "Queue (FIFO)" and Frontier.LIFO.title == "Stack (LIFO)"
    assert Frontier.FIFO.count_text("4") == "4 in the queue"
    assert Frontier.LIFO.count_text("5") == "5 on the stack"

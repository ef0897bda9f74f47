"""The ``util`` module a student's ``search.py`` gets under ``--check-search-py`` behaves as
the course documents its own: a stack, a queue, a priority queue whose ties come out in the
order pushed, and whose ``update`` lowers a priority in place (keeping the entry's age), does
nothing for an equal or higher one, and pushes an item not there."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def util() -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "course_util", ROOT / "tui_search" / "engine" / "traces" / "course_util.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def drain(queue) -> list:
    out = []
    while not queue.isEmpty():
        out.append(queue.pop())
    return out


def test_a_stack_and_a_queue(util: ModuleType) -> None:
    stack, queue = util.Stack(), util.Queue()
    for item in "abc":
        stack.push(item)
        queue.push(item)
    assert drain(stack) == ["c", "b", "a"] and drain(queue) == ["a", "b", "c"]


def test_priority_ties_come_out_in_the_order_pushed(util: ModuleType) -> None:
    pq = util.PriorityQueue()
    for item, priority in (("a", 2), ("b", 1), ("c", 2), ("d", 1)):
        pq.push(item, priority)
    assert drain(pq) == ["b", "d", "a", "c"]


def test_update_lowers_in_place_and_never_raises(util: ModuleType) -> None:
    pq = util.PriorityQueue()
    pq.push("a", 3)
    pq.push("b", 2)
    pq.update("a", 2)  # lowered: its age is kept, so it comes before b at 2
    pq.update("b", 5)  # higher: nothing
    pq.update("c", 2)  # not there: pushed, the newest
    assert drain(pq) == ["a", "b", "c"]
    pq.push("x", 1)
    pq.update("x", 1)  # equal: nothing (no second entry)
    assert drain(pq) == ["x"]


def test_with_a_function_and_the_helpers(util: ModuleType) -> None:
    pq = util.PriorityQueueWithFunction(lambda item: -item)
    for item in (1, 3, 2):
        pq.push(item)
    assert drain(pq) == [3, 2, 1]
    assert util.manhattanDistance((1, 2), (4, 0)) == 5
    with pytest.raises(util.NotDefined):
        util.raiseNotDefined()

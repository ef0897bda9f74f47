"""The ``util`` module a student's ``search.py`` imports under ``--check-search-py``: copied
into the sandbox's working folder as ``util.py``, never imported by tui-search itself.

Written here to behave as the course's does (its documented behaviour, not its code):
``Stack`` pops the newest item, ``Queue`` the oldest; ``PriorityQueue`` pops the lowest
priority, and of equal priorities the one pushed first (it orders ``(priority, count, item)``);
``update(item, priority)`` lowers an item's priority when it is on the queue with a higher one
(it keeps its place among equals: its count), does nothing when it is there with an equal or
lower one, and pushes it when it is not there.  ``PriorityQueueWithFunction`` pushes with the
priority its function gives.  ``manhattanDistance`` and ``raiseNotDefined`` as the course's.
"""

import heapq
from collections.abc import Callable
from typing import Any


class Stack:
    """Last in, first out."""

    def __init__(self) -> None:
        self.list: list[Any] = []

    def push(self, item: Any) -> None:
        self.list.append(item)

    def pop(self) -> Any:
        return self.list.pop()

    def isEmpty(self) -> bool:
        return len(self.list) == 0


class Queue:
    """First in, first out."""

    def __init__(self) -> None:
        self.list: list[Any] = []

    def push(self, item: Any) -> None:
        self.list.insert(0, item)

    def pop(self) -> Any:
        return self.list.pop()

    def isEmpty(self) -> bool:
        return len(self.list) == 0


class PriorityQueue:
    """The lowest priority first; equal priorities in the order pushed."""

    def __init__(self) -> None:
        self.heap: list[tuple[Any, int, Any]] = []
        self.count = 0

    def push(self, item: Any, priority: Any) -> None:
        heapq.heappush(self.heap, (priority, self.count, item))
        self.count += 1

    def pop(self) -> Any:
        return heapq.heappop(self.heap)[2]

    def isEmpty(self) -> bool:
        return len(self.heap) == 0

    def update(self, item: Any, priority: Any) -> None:
        for at, (old, count, there) in enumerate(self.heap):
            if there == item:
                if old > priority:
                    self.heap[at] = (priority, count, item)
                    heapq.heapify(self.heap)
                return
        self.push(item, priority)


class PriorityQueueWithFunction(PriorityQueue):
    """A priority queue whose priorities a function of the item gives."""

    def __init__(self, priorityFunction: Callable[[Any], Any]) -> None:
        self.priorityFunction = priorityFunction
        super().__init__()

    def push(self, item: Any) -> None:  # type: ignore[override]
        super().push(item, self.priorityFunction(item))


def manhattanDistance(xy1: Any, xy2: Any) -> Any:
    return abs(xy1[0] - xy2[0]) + abs(xy1[1] - xy2[1])


class NotDefined(Exception):
    """A function the student has not written yet."""


def raiseNotDefined() -> None:
    raise NotDefined("not written yet (util.raiseNotDefined())")

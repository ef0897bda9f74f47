"""The frontier of a recorded run at its position: which generation events wait, in the order
they will come out.

A step takes one event off (the one the record says it expanded) and pushes the events it
generated; stepping back undoes exactly that.  Each discipline keeps what it needs to do both in
time proportional to the step, and to rebuild itself in bulk for a long jump:

* :class:`FifoFrontier` (a queue): events leave in the order they were generated, so the queue
  is always the run of events between the next one out and the newest -- two counters.
* :class:`LifoFrontier` (a stack): pushed in generation order, popped at the top, so after any
  steps it is the events generated and not yet taken off, in generation order.

The run is the same for every discipline: it asks its frontier model, never which algorithm it
runs.
"""

from __future__ import annotations

from collections.abc import Iterable

from tui_search.engine.algorithms import Frontier


class FifoFrontier:
    """The queue as ``head .. tail - 1``: the next event out, and one past the newest."""

    def __init__(self) -> None:
        self.head = self.tail = 0

    def reset(self, root: int) -> None:
        self.head, self.tail = root, root + 1

    def forward(self, g: int, succ: range) -> None:
        assert g == self.head, "the recorded step does not match the queue"
        self.head += 1
        self.tail = succ.stop if succ else self.tail

    def backward(self, g: int, succ: range) -> None:
        self.head = g
        if succ:
            self.tail = succ.start

    def rebuild(self, root: int, end: int, expanded: Iterable[int]) -> None:
        """After expanding ``expanded`` of the events ``root .. end - 1``."""
        self.head = root + sum(1 for _ in expanded)
        self.tail = end

    def __len__(self) -> int:
        return self.tail - self.head

    def entries(self, start: int, stop: int) -> list[int]:
        """Entries ``start .. stop - 1`` counted from the next one out."""
        return list(range(self.head + start, min(self.head + stop, self.tail)))


class LifoFrontier:
    """The stack as a list of events, top last."""

    def __init__(self) -> None:
        self.stack: list[int] = []

    def reset(self, root: int) -> None:
        self.stack = [root]

    def forward(self, g: int, succ: range) -> None:
        top = self.stack.pop()
        assert top == g, "the recorded step does not match the stack"
        self.stack.extend(succ)

    def backward(self, g: int, succ: range) -> None:
        del self.stack[len(self.stack) - len(succ):]
        self.stack.append(g)

    def rebuild(self, root: int, end: int, expanded: Iterable[int]) -> None:
        open_ = bytearray(b"\x01") * (end - root)
        for g in expanded:
            open_[g - root] = 0
        self.stack = [g for g in range(root, end) if open_[g - root]]

    def __len__(self) -> int:
        return len(self.stack)

    def entries(self, start: int, stop: int) -> list[int]:
        s, n = self.stack, len(self.stack)
        return [s[n - 1 - i] for i in range(start, min(stop, n))]


FrontierModel = FifoFrontier | LifoFrontier


def frontier_model(kind: Frontier) -> FrontierModel:
    return FifoFrontier() if kind is Frontier.FIFO else LifoFrontier()

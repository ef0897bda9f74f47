"""The frontier of a recorded run at its position: which generation events wait, in the order
they will come out.

A step takes one event off (the one the record says it expanded) and pushes the events it
generated; stepping back undoes exactly that.  Each discipline keeps what it needs to do both in
time proportional to the step, and to rebuild itself in bulk for a long jump:

* :class:`FifoFrontier` (a queue): events leave in the order they were generated, so the queue
  is always the run of events between the next one out and the newest -- two counters.
* :class:`LifoFrontier` (a stack): pushed in generation order, popped at the top, so after any
  steps it is the events generated and not yet taken off, in generation order (a recursion's:
  each step's successors last first, the first call on top).
* :class:`PriorityFrontier` (a priority queue): the events generated and not yet taken off,
  kept sorted by ``(priority, event)`` (a tie rule's key beside the priority) in a
  :class:`sortedcontainers.SortedList`, so a step costs O(log n) in the frontier's size and
  the panel reads any window without sorting.

* :class:`AddedFrontier` (a replayed trace's, :mod:`~tui_search.engine.traces.as_run`): the
  events generated and not yet taken off, in the order added; any of them may leave next.

The run is the same for every discipline: it asks its frontier model, never which algorithm it
runs.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import TYPE_CHECKING, Any

from tui_search.engine.run.rebuild import kernels
from tui_search.engine.search.registry import Frontier

if TYPE_CHECKING:
    from sortedcontainers import SortedList

#: Events a piece of a bulk rebuild handles (a few milliseconds of work).
PIECE = 1 << 14


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

    @staticmethod
    def rebuild_work(root: int, end: int, expanded: int) -> int:
        """Units of work :meth:`rebuild_pieces` takes (for a progress figure)."""
        return expanded

    def rebuild_pieces(self, root: int, end: int, expanded: Iterable[Sequence[int]]
                       ) -> Iterator[int]:
        """Become the queue after the pieces of ``expanded`` were taken off the events
        ``root .. end - 1``, yielding the work done by each piece."""
        n = 0
        for piece in expanded:
            n += len(piece)
            yield len(piece)
        self.head, self.tail = root + n, end

    def __len__(self) -> int:
        return self.tail - self.head

    def entries(self, start: int, stop: int) -> list[int]:
        """Entries ``start .. stop - 1`` counted from the next one out."""
        return list(range(self.head + start, min(self.head + stop, self.tail)))


class LifoFrontier:
    """The stack as a list of events, top last.  A recursion's (``calls``: the step that
    generated an event, for a rebuild) has each step's successors pushed last first, so that
    the first comes out first, as the first call is made first."""

    def __init__(self, calls: Callable[[int], int] | None = None) -> None:
        self.stack: list[int] = []
        self.calls = calls

    def reset(self, root: int) -> None:
        self.stack = [root]

    def forward(self, g: int, succ: range) -> None:
        top = self.stack.pop()
        assert top == g, "the recorded step does not match the stack"
        self.stack.extend(reversed(succ) if self.calls is not None else succ)

    def backward(self, g: int, succ: range) -> None:
        del self.stack[len(self.stack) - len(succ):]
        self.stack.append(g)

    @staticmethod
    def rebuild_work(root: int, end: int, expanded: int) -> int:
        return expanded + (end - root)

    def rebuild_pieces(self, root: int, end: int, expanded: Iterable[Sequence[int]]
                       ) -> Iterator[int]:
        """Become the stack after the pieces of ``expanded`` were taken off the events
        ``root .. end - 1``: the events not taken off, in generation order (every event is
        pushed in that order and only the top is popped)."""
        stack: list[int] = []
        yield from _open_events(root, end, expanded, stack.extend)
        if self.calls is not None:  # each step's successors last first
            stack = _blocks_reversed(stack, self.calls)
        self.stack = stack

    def __len__(self) -> int:
        return len(self.stack)

    def entries(self, start: int, stop: int) -> list[int]:
        s, n = self.stack, len(self.stack)
        return [s[n - 1 - i] for i in range(start, min(stop, n))]


def _blocks_reversed(events: list[int], step_of: Callable[[int], int]) -> list[int]:
    """``events`` (ascending) with each run of events one step generated reversed."""
    out: list[int] = []
    block: list[int] = []
    step = -1
    for g in events:
        k = step_of(g)
        if k != step:
            out.extend(reversed(block))
            block, step = [], k
        block.append(g)
    out.extend(reversed(block))
    return out


def _open_events(root: int, end: int, expanded: Iterable[Sequence[int]],
                 take: Callable[[list[int]], object]) -> Iterator[int]:
    """Hand ``take`` the events ``root .. end - 1`` not in the pieces of ``expanded``, in
    generation order, a piece at a time, yielding the work done by each piece."""
    open_ = bytearray(b"\x01") * (end - root)
    loops = kernels()
    for piece in expanded:
        loops.clear_events(open_, piece, root)
        yield len(piece)
    for lo in range(root, end, PIECE):
        hi = min(lo + PIECE, end)
        take(loops.open_events(open_, root, lo, hi))
        yield hi - lo


class PriorityFrontier:
    """The priority queue as a sorted list of ``(priority, event)``: the next out first (the
    lowest priority; the oldest event among equals, as the heap of the loops takes them).
    ``keys`` gives the priorities of ascending events (a step's successors, the open events
    of a rebuild), the same floats the loop pushed them with, in bulk: the record derives an
    event's g from its generating step's, which is then looked up once a step."""

    def __init__(self, keys: Callable[[Sequence[int]], list[Any]]) -> None:
        # imported with the first priority queue, not at start-up (benchmarks/README.md,
        # "startup")
        from sortedcontainers import SortedList

        self._sorted = SortedList
        self.keys = keys
        self.queue: SortedList = SortedList()

    def reset(self, root: int) -> None:
        self.queue = self._sorted([(self.keys((root,))[0], root)])

    def forward(self, g: int, succ: range) -> None:
        _, first = self.queue.pop(0)
        assert first == g, "the recorded step does not match the priority queue"
        self.queue.update(zip(self.keys(succ), succ, strict=True))

    def backward(self, g: int, succ: range) -> None:
        queue = self.queue
        for entry in zip(self.keys(succ), succ, strict=True):
            queue.remove(entry)
        queue.add((self.keys((g,))[0], g))

    @staticmethod
    def rebuild_work(root: int, end: int, expanded: int) -> int:
        return expanded + 2 * (end - root)

    def rebuild_pieces(self, root: int, end: int, expanded: Iterable[Sequence[int]]
                       ) -> Iterator[int]:
        """Become the queue after the pieces of ``expanded`` were taken off the events
        ``root .. end - 1``: the events not taken off, sorted by priority."""
        keys = self.keys
        entries: list[tuple[Any, int]] = []

        def take(open_: list[int]) -> None:
            entries.extend(zip(keys(open_), open_, strict=True))

        yield from _open_events(root, end, expanded, take)
        self.queue = self._sorted(entries)
        yield end - root

    def __len__(self) -> int:
        return len(self.queue)

    def entries(self, start: int, stop: int) -> list[int]:
        return [h for _, h in self.queue.islice(start, stop)]

    def position(self, g: int) -> int:
        """Where event ``g`` (on the frontier) stands in the order: 0 is the next out."""
        place: int = self.queue.index((self.keys((g,))[0], g))  # SortedList ships no types
        return place


class AddedFrontier:
    """What a replayed trace added and has not taken off, in the order added (oldest first):
    the trace does not say its discipline, so any entry may be the next out.  A step that
    takes off an event no longer on it (a trace that expands a cell twice) is counted in
    ``absent``, so that stepping back leaves it off again."""

    def __init__(self) -> None:
        from sortedcontainers import SortedList

        self._sorted = SortedList
        self.events: SortedList = SortedList()
        self.absent: dict[int, int] = {}

    def reset(self, root: int) -> None:
        self.events = self._sorted([root])
        self.absent = {}

    def forward(self, g: int, succ: range) -> None:
        if g in self.events:
            self.events.remove(g)
        else:
            self.absent[g] = self.absent.get(g, 0) + 1
        self.events.update(succ)

    def backward(self, g: int, succ: range) -> None:
        events = self.events
        for h in succ:
            events.discard(h)
        if self.absent.get(g):
            self.absent[g] -= 1
        else:
            events.add(g)

    @staticmethod
    def rebuild_work(root: int, end: int, expanded: int) -> int:
        return expanded + (end - root)

    def rebuild_pieces(self, root: int, end: int, expanded: Iterable[Sequence[int]]
                       ) -> Iterator[int]:
        """Become the events of ``root .. end - 1`` not in the pieces of ``expanded`` (an
        event taken off more than once counted absent for each time after the first)."""
        events: list[int] = []
        seen: set[int] = set()
        absent: dict[int, int] = {}

        def watched() -> Iterator[Sequence[int]]:
            for piece in expanded:
                for g in piece:
                    if g in seen:
                        absent[g] = absent.get(g, 0) + 1
                    seen.add(g)
                yield piece

        yield from _open_events(root, end, watched(), events.extend)
        self.events, self.absent = self._sorted(events), absent

    def __len__(self) -> int:
        return len(self.events)

    def entries(self, start: int, stop: int) -> list[int]:
        return list(self.events.islice(start, stop))


FrontierModel = FifoFrontier | LifoFrontier | PriorityFrontier | AddedFrontier


def frontier_model(kind: Frontier, keys: Callable[[Sequence[int]], list[Any]] | None = None,
                   calls: Callable[[int], int] | None = None) -> FrontierModel:
    """The model of ``kind``; a priority queue needs ``keys``, ascending events' priorities
    (their tie rule's key beside, when it has one); a recursion's stack ``calls``, the step
    that generated an event."""
    if kind is Frontier.FIFO:
        return FifoFrontier()
    if kind is Frontier.LIFO:
        return LifoFrontier(calls)
    if kind is Frontier.ADDED:
        return AddedFrontier()
    assert keys is not None, "a priority queue needs its events' priorities"
    return PriorityFrontier(keys)

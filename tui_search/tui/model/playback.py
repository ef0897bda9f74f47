"""Moving the runs' positions: a step of the lockstep, time-boxed slices, and what a move
changes on screen.

Plain functions over :class:`~tui_search.engine.run.recorded.Run` (no Textual), so the app's
playback timer, its ``end`` key and the tests share them.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from time import perf_counter
from typing import TYPE_CHECKING

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun

#: Playback speeds in expansions per second (``+``/``-`` walk this list).
SPEEDS: tuple[int, ...] = (1, 2, 5, 10, 20, 50, 100, 300, 1_000, 10_000, 100_000, 1_000_000)
DEFAULT_SPEED = 2  # index: 5 steps/s, slow enough to follow the tutorial's story
#: The timer never fires faster than this; faster speeds take several steps per tick.
MAX_TICKS_PER_SECOND = 30
#: The longest a tick or a slice of ``end`` may keep the event loop busy.
SLICE_SECONDS = 0.03
#: The pause between two slices of ``end``, in which the event loop answers keys.
SLICE_PAUSE = 0.002


def tick_interval(speed: int) -> float:
    return max(1.0 / speed, 1.0 / MAX_TICKS_PER_SECOND)


def steps_per_tick(speed: int) -> int:
    return max(1, round(speed * tick_interval(speed)))


def speed_text(speed: int) -> str:
    if speed >= 1_000_000:
        return f"{speed // 1_000_000}M/s"
    if speed >= 1_000:
        return f"{speed // 1_000}k/s"
    return f"{speed}/s"

#: Where each run was before a move: its step, and whether it was at its end.
Before = list[tuple[int, bool]]


def where(runs: Sequence[Run | BiRun]) -> Before:
    return [(r.k, r.at_end) for r in runs]


def advance(runs: Sequence[Run | BiRun], forward: bool) -> Before | None:
    """One step of the lockstep: forwards, every run not at its end; backwards, the runs
    at the latest step (one that ended earlier stays on its last screen).  Where they
    were before, or None when none moved."""
    if not runs:
        return None
    before = where(runs)
    if forward:
        moved = [r.forward() for r in runs]
    else:
        latest = max(r.k for r in runs)
        moved = [r.k == latest and r.backward() for r in runs]
    return before if any(moved) else None


def forward_for(runs: Sequence[Run | BiRun], steps: int, seconds: float = SLICE_SECONDS) -> int:
    """Up to ``steps`` steps forwards of every run in lockstep (each recording as needed and
    staying at its end once there), stopping early when all are at their ends or when
    ``seconds`` have passed.  Returns the number of lockstep steps taken."""
    deadline = perf_counter() + seconds
    forwards = [run.forward for run in runs]
    taken = 0
    while taken < steps:
        moved = False
        for forward in forwards:
            if forward():
                moved = True
        if not moved:
            break
        taken += 1
        if not taken & 63 and perf_counter() > deadline:
            break
    return taken


def rebuild_for(pieces: Iterator[float], seconds: float | None = None) -> float | None:
    """Run pieces of :meth:`Run.rebuild_pieces` for about ``seconds`` (default SLICE_SECONDS;
    one piece at least): the fraction done, or None once the run is at its new position."""
    deadline = perf_counter() + (SLICE_SECONDS if seconds is None else seconds)
    for fraction in pieces:
        if perf_counter() > deadline:
            return fraction
    return None


def record_for(run: Run | BiRun, seconds: float | None = None) -> bool:
    """Record more of the search for about ``seconds`` (default SLICE_SECONDS; one chunk at
    least); True when the whole search is recorded."""
    deadline = perf_counter() + (SLICE_SECONDS if seconds is None else seconds)
    while not run.advance_some():
        if perf_counter() > deadline:
            return False
    return True


def step_changes(run: Run | BiRun, old_k: int, was_at_end: bool) -> list[State] | None:
    """The cells whose look differs between position ``old_k`` and the run's position, when
    they moved by one step within one iteration; ``None`` (redraw everything) otherwise."""
    k = run.k
    if k == old_k:
        return []
    if not isinstance(run, Run):  # a bidirectional search's: its two halves, the meeting
        return None
    if abs(k - old_k) != 1 or run.steps.iteration_of(k) != run.steps.iteration_of(old_k):
        return None
    step = max(k, old_k)
    cells = run.now.changed_cells(step)
    if step > 1:  # the marker of the node being expanded moves from or to step-1's node
        cells.append(run.nodes.cell(run.steps.expanded_event(step - 1)))
    if run.found and (was_at_end or run.at_end):
        cells.extend(run.path() or [])
    return cells

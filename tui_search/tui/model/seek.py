"""Moving runs to step 0 or to their ends in time-boxed slices (no Textual).

``end`` on a big map first records the search, then rebuilds the run's state at the last step;
both can take seconds, so :meth:`Seek.work` does a slice of at most ``seconds`` and returns
how far it is, and the screen answers keys between slices (esc, or any key that moves the
position, abandons the seek: what was recorded is kept).  One run after another; a run a few
steps from its target moves at once.
"""

from __future__ import annotations

from collections.abc import Iterator
from time import perf_counter
from typing import TYPE_CHECKING

from tui_search.engine.run.recorded import Run
from tui_search.engine.util.numbers import group_digits
from tui_search.tui.model import playback

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun


class Seek:
    """Move each run of ``targets`` to its step (0, or None: its end).  ``labels`` name the
    runs in the progress text ("" for none); ``before`` is where every run was."""

    def __init__(self, targets: list[tuple[Run | BiRun, int | None]], labels: list[str],
                 before: list[tuple[int, bool]], then_play: bool = False) -> None:
        self.queue = list(zip(targets, labels, strict=True))
        self.before = before
        self.then_play = then_play  # play once there (space at the last step)
        self.noted = False  # a progress text was given: the note is the seek's
        self._moves: Iterator[float] | None = None  # the pieces of a move, once recorded
        self._to = 0

    def work(self, seconds: float | None = None) -> str | None:
        """About ``seconds`` of work (default SLICE_SECONDS; one piece at least): what it is
        doing (a line) while not done, else None."""
        deadline = perf_counter() + (playback.SLICE_SECONDS if seconds is None else seconds)
        while self.queue:
            (run, target), label = self.queue[0]
            text = self._work_on(run, target, deadline)
            if text is not None:
                self.noted = True
                text = f"{label}: {text[0].lower()}{text[1:]}" if label else text
                return f"{text} — esc to stop"
            self.queue.pop(0)
            self._moves = None
        return None

    def _work_on(self, run: Run | BiRun, target: int | None, deadline: float) -> str | None:
        """A slice of one run's move: a progress text, or None once it is there."""
        if target is None and run.at_end or target == 0 and run.k == 0:
            return None
        if target == 0 and run.k <= run.REBUILD_AFTER:
            run.goto(0)
            return None
        if self._moves is None:
            if target == 0:
                self._moves, self._to = run.rebuild_pieces(0), 0
            else:
                if not playback.record_for(run, max(0.0, deadline - perf_counter())):
                    return f"Computing the search… {group_digits(run.recorded)} steps recorded"
                if run.recorded - run.k <= run.REBUILD_AFTER:  # a few steps: at once
                    run.goto(run.recorded)
                    return None
                self._moves, self._to = run.rebuild_pieces(run.recorded), run.recorded
        fraction = playback.rebuild_for(self._moves, max(0.0, deadline - perf_counter()))
        if fraction is not None:
            return f"Moving to step {group_digits(self._to)}… {fraction:.0%}"
        return None


__all__ = ["Seek"]

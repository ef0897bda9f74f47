"""The session's replay (``--replay FILE``): a trace beside the search it matches, where they
first part, and the key that jumps there and back.

A part the :class:`~tui_search.tui.model.session.Session` has (``session.jumps``; no Textual): the
replay itself
(:class:`~tui_search.engine.traces.replay.Replay`) gives the two runs, the cells to mark and
the sentence; the session shows them while the map, the rules and the searches shown stay as
they were.  A run stepped by hand matches its search (a wrong step was never taken): its
replay's jumps are the steps where a mistake was made, each said and marked at its step.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.registry import ALGORITHMS
from tui_search.engine.search.state import State

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.traces.hand import Mistake
    from tui_search.engine.traces.replay import Replay

#: Said when an edit ends the replay.
REPLAY_ENDED = "The map changed: the replay of your trace is over"
_FIRST, *_, _LAST = (a.app_key for a in ALGORITHMS.values())
_KEYS = f"{_FIRST}-{_LAST}"  # the keys that add or take out a search: "1-7"
LOCKSTEP = ("Lockstep: n steps every search not done yet, p steps back the latest, "
            f"end runs them all to the end · {_KEYS} add or take out a search · c back to one")
#: The same where the long one would take two lines (the panes need them more).
LOCKSTEP_SHORT = (f"Lockstep: n, p and end move every search · {_KEYS} add or take out · c back "
                  "to one")


class ReplayJumps:
    """The replay's first difference: its step, its marks, its sentence, the jump.  ``runs``
    gives the session's runs as they are now, ``goto`` moves them all to a step."""

    def __init__(self, replay: Replay | None, runs: Callable[[], list[Run | BiRun]],
                 goto: Callable[[int], None]) -> None:
        #: ``--replay``: a trace beside the search it matches (None: none, or it is over).
        self.replay = replay
        self._runs, self._goto = runs, goto
        self._back: int | None = None  # the step the difference key came from

    def end(self) -> None:
        """The replay is over (the map, the rules or the searches changed)."""
        self.replay, self._back = None, None

    @property
    def difference_step(self) -> int | None:
        """The step where the replayed trace first parts from its search (None: no replay,
        or it never parts); a run stepped by hand: the first step with a mistake."""
        if self.replay is None or not self._runs():
            return None
        mistakes = self.replay.mistakes
        return mistakes[0].step if mistakes else self.replay.step

    def _mistake(self) -> Mistake | None:
        """A run stepped by hand: the mistake made at the step just shown (None: none)."""
        if self.replay is None or not self.replay.mistakes or not self._runs():
            return None
        k = self._runs()[0].k
        return next((m for m in self.replay.mistakes if m.step == k), None)

    def marks(self) -> list[State | None]:
        """The cell to mark on each pane's map: where the replay parts, or the mistake made
        at this step (else none)."""
        if self.replay is None:
            return [None] * len(self._runs())
        if self.replay.mistakes:
            mistake = self._mistake()
            return [None, None] if mistake is None else [mistake.got, mistake.expected]
        return self.replay.marks()

    def lockstep_sentence(self, width: int) -> str:
        """What the line under the panes says of the lockstep, ``width`` cells wide: the
        replay's first difference (a run by hand: the mistake made at this step, or how
        many there were), else how the lockstep goes."""
        replay = self.replay
        if replay is not None and replay.mistakes:
            mistake = self._mistake()
            if mistake is not None:
                return (f"Here you first tried: {mistake.message} · d: the next step with a "
                        "mistake")
            n = len(replay.mistakes)
            return (f"{replay.sentence()}; you made {n} mistake{'s' if n != 1 else ''} on "
                    "the way · d: to each")
        if replay is not None:
            return f"{replay.sentence()} · d: to it and back"
        return LOCKSTEP if len(LOCKSTEP) + 2 <= width else LOCKSTEP_SHORT

    def to_difference(self) -> None:
        """Every run to the replay's first difference, or back from it to where they were; a
        run stepped by hand: to the next step with a mistake (after the last, the first)."""
        step = self.difference_step
        if step is None:
            return
        replay = self.replay
        here = self._runs()[0].k
        if replay is not None and replay.mistakes:
            steps = sorted({m.step for m in replay.mistakes})
            self._goto(next((s for s in steps if s > here), steps[0]))
            return
        if here == step and self._back is not None:
            target, self._back = self._back, None
        else:
            target, self._back = step, here
        self._goto(target)

"""The session's replay (``--replay FILE``): a trace beside the search it matches, where they
first part, and the key that jumps there and back.

A part the :class:`~tui_search.tui.model.session.Session` has (``session.jumps``; no Textual): the
replay itself
(:class:`~tui_search.engine.traces.replay.Replay`) gives the two runs, the cells to mark and
the sentence; the session shows them while the map, the rules and the searches shown stay as
they were.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State

if TYPE_CHECKING:
    from tui_search.engine.traces.replay import Replay

#: Said when an edit ends the replay.
REPLAY_ENDED = "The map changed: the replay of your trace is over"
LOCKSTEP = ("Lockstep: n steps every search not done yet, p steps back the latest, "
            "end runs them all to the end · 1-6 add or take out a search · c back to one")
#: The same where the long one would take two lines (the panes need them more).
LOCKSTEP_SHORT = "Lockstep: n, p and end move every search · 1-6 add or take out · c back to one"


class ReplayJumps:
    """The replay's first difference: its step, its marks, its sentence, the jump.  ``runs``
    gives the session's runs as they are now, ``goto`` moves them all to a step."""

    def __init__(self, replay: Replay | None, runs: Callable[[], list[Run]],
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
        or it never parts)."""
        return None if self.replay is None or not self._runs() else self.replay.step

    def marks(self) -> list[State | None]:
        """The cell to mark on each pane's map: where the replay parts (else none)."""
        if self.replay is None:
            return [None] * len(self._runs())
        return self.replay.marks()

    def lockstep_sentence(self, width: int) -> str:
        """What the line under the panes says of the lockstep, ``width`` cells wide: the
        replay's first difference, else how the lockstep goes."""
        if self.replay is not None:
            return f"{self.replay.sentence()} · d: to it and back"
        return LOCKSTEP if len(LOCKSTEP) + 2 <= width else LOCKSTEP_SHORT

    def to_difference(self) -> None:
        """Every run to the replay's first difference, or back from it to where they were."""
        step = self.difference_step
        if step is None:
            return
        here = self._runs()[0].k
        if here == step and self._back is not None:
            target, self._back = self._back, None
        else:
            target, self._back = step, here
        self._goto(target)

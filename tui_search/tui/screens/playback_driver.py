"""Driving playback and seeks on the screen of panes: a part the
:class:`~tui_search.tui.screens.panes.PanesScreen` has (``screen.playback``), not a base class.

Playback is a paused interval timer whose ticks do what ``n`` does, several steps per tick at
high speeds; ``end`` and ``home`` on a big run move in time-boxed slices
(:class:`~tui_search.tui.model.seek.Seek`) so keys are still answered.  The session decides where
the runs go; this part only times it and asks the screen to show what changed.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.search.state import State
from tui_search.tui.model import playback

if TYPE_CHECKING:  # (the protocol too: nothing of it is needed to run, so no class is made)
    from collections.abc import Callable
    from typing import Protocol

    from textual.timer import Timer

    from tui_search.tui.model.session import Before, Session

    class Host(Protocol):
        """What the driver needs of the screen it drives (the screen of panes: named here,
        not imported, so the two modules make no circle)."""

        session: Session

        @property
        def is_attached(self) -> bool: ...

        def set_interval(self, interval: float, callback: Callable[[], None], *,
                         pause: bool = False) -> Timer: ...

        def set_timer(self, delay: float, callback: Callable[[], None]) -> Timer: ...

        def moved(self, before: Before | None) -> None:
            """Show the runs after a move from ``before``."""

        def present(self, changed: list[State] | None = None) -> None:
            """Show the runs where they are (``changed``: only those cells of the maps)."""

        def show_status(self) -> None:
            """Show the status lines anew (the session's note changed)."""


class PlaybackDriver:
    """The playback timer of ``screen`` and the slices of its seeks."""

    def __init__(self, screen: Host) -> None:
        self.screen = screen
        self._timer: Timer  # made on mount (start)

    def start(self) -> None:
        """On mount: the timer, paused, at the session's speed."""
        self._timer = self.screen.set_interval(1.0, self.tick, pause=True)
        self.set_speed(self.screen.session.speed_index)

    def pause(self) -> None:
        """Pause the timer (the session's position is about to move another way)."""
        self._timer.pause()

    def set_speed(self, index: int) -> None:
        session = self.screen.session
        session.set_speed(index)
        interval = playback.tick_interval(session.speed)
        self._timer.stop()
        self._timer = self.screen.set_interval(interval, self.tick, pause=not session.playing)

    def tick(self) -> None:
        """What the timer calls: a playback tick (paused: nothing moves)."""
        before = self.screen.session.tick()
        if not self.screen.session.playing:
            self._timer.pause()
        self.screen.moved(before)

    def play(self) -> None:
        if self.screen.session.play():
            self.seek_slice()
        else:
            self._timer.resume()
            self.screen.present()

    def stop(self) -> None:
        self.screen.session.stop()
        self._timer.pause()

    def seek(self, to_end: bool) -> None:
        self.screen.session.start_seek(to_end)
        self._timer.pause()
        self.seek_slice()

    def seek_slice(self) -> None:
        """A slice of the seek, then the next one after a pause (what its timer calls)."""
        screen, session = self.screen, self.screen.session
        seek = session.seek
        if seek is None or not screen.is_attached:
            return  # stopped or replaced
        progress = seek.work()
        if progress is not None:
            session.note = progress
            screen.show_status()  # only the note: the panes show where the runs were till the end
            screen.set_timer(playback.SLICE_PAUSE, self.seek_slice)
            return
        before = session.seek_done()
        if session.playing:
            self._timer.resume()
            screen.present()
        else:
            screen.moved(before) if before != session.where() else screen.present(changed=[])

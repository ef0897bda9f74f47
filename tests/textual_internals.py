"""The few private names of Textual the tests need, gathered here (they follow textual 8.2.8:
re-check them when the pin moves).  ``tui_search/`` itself uses Textual's public API only.

Textual has no public way to see the terminal as painted (its compositor's cached lines), to
let an app handle what is queued and paint without Pilot's idle waits (20 ms or more each,
which would make a test of hundreds of steps slow) or until nothing is queued, to read the
notifications shown, or (for the benchmarks) to count the lines it draws afresh.  The benchmarks
import these too: one module holds every private name outside ``tui_search``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.app import App
from textual.notifications import Notification, Notifications
from textual.pilot import Pilot

if TYPE_CHECKING:
    import pytest


def composited(app: App) -> list[list[tuple]]:
    """The terminal as the app has painted it (from the widgets' caches of drawn lines): each
    line's segments as (text, style)."""
    strips = app.screen._compositor.render_strips()
    return [[(segment.text, segment.style) for segment in strip] for strip in strips]


async def settle(pilot: Pilot) -> None:
    """Let the app handle what is queued and paint now (``pilot.pause()`` without its idle
    wait), twice: a layout that shows or hides a scrollbar asks for another one, which
    Textual does on its next update (a frame later)."""
    for _ in range(2):
        await pilot._wait_for_screen()
        await pilot._wait_for_screen()
        pilot.app.screen._on_timer_update()


def nothing_queued(app: App) -> bool:
    """No message waits in the app's queue nor in any of the top screen's widgets'."""
    if not app.screen_stack:  # the app has exited
        return True
    nodes = [app, *app.screen.walk_children(with_self=True)]
    return all(node._message_queue.empty() for node in nodes)


async def drain(pilot: Pilot) -> None:
    """Let the app handle what is queued until nothing is: a key goes from the app to the
    focused widget and bubbles up to the bindings, a message at a time.  (Pilot's own wait
    is for the process to look idle, and a process starved of the CPU by a loaded machine
    looks idle too.)"""
    for _ in range(100):
        await pilot._wait_for_screen()
        if nothing_queued(pilot.app):
            return


async def repainted(pilot: Pilot) -> list[list[tuple]]:
    """The terminal with every widget drawn afresh, nothing from a cache (scrollbars too:
    they are not in the DOM, but they are on screen)."""
    app = pilot.app
    for widget in app.screen._compositor.visible_widgets:
        widget.refresh()
    await settle(pilot)
    return composited(app)


class DrawnLines:
    """Counts the lines Textual draws afresh (each one a widget's line with its border and
    padding: ``StylesCache.render_line``; a line left unchanged comes from its cache), while
    in a ``with`` block."""

    def __enter__(self) -> DrawnLines:  # noqa: PYI034 -- returns self, as written
        from textual._styles_cache import StylesCache

        self.count, self._cls = 0, StylesCache
        self._original = original = StylesCache.render_line

        def counted(*args, **kwargs):
            self.count += 1
            return original(*args, **kwargs)

        StylesCache.render_line = counted  # type: ignore[method-assign]
        return self

    def __exit__(self, *exc) -> None:
        self._cls.render_line = self._original  # type: ignore[method-assign]


def notifications(app: App) -> list[Notification]:
    """Every notification the app has shown, in order, its time on screen over or not.

    Textual drops the notifications whose time is over each time one is added, so on a
    loaded machine a test that checks after the third of three could see only the last one:
    :func:`keep_every_notification` (installed for the UI tests by their conftest) keeps a
    log of each one added."""
    return list(getattr(app._notifications, "every", []))


def keep_every_notification(monkeypatch: pytest.MonkeyPatch) -> None:
    """Make Textual's collection of notifications also keep each one added, in ``every``."""
    add = Notifications.add

    def add_and_keep(self: Notifications, notification: Notification) -> Notifications:
        self.__dict__.setdefault("every", []).append(notification)
        return add(self, notification)

    monkeypatch.setattr(Notifications, "add", add_and_keep)

"""Pilot's ``press`` and ``pause()`` return once the app has handled what they set off.

Textual's own wait after a key or a pause is for the process to look idle (its CPU time not
advancing for 20 ms); on a loaded machine a process starved of the CPU looks idle too, and a
test then checks the state before the key has reached its binding.  Here both also wait until
no message is queued on the app or its top screen (:func:`tests.textual_internals.drain`).
A pause of a given time is left as it is (tests wait for what they check instead).

Every notification shown is kept for the tests to read, its time on screen over or not
(:func:`tests.textual_internals.notifications`)."""

from __future__ import annotations

import pytest
from textual.pilot import Pilot

from tests.textual_internals import drain, keep_every_notification


@pytest.fixture(autouse=True)
def _pilot_waits_until_nothing_is_queued(monkeypatch: pytest.MonkeyPatch) -> None:
    press, pause = Pilot.press, Pilot.pause

    async def press_and_drain(self: Pilot, *keys: str) -> None:
        await press(self, *keys)
        await drain(self)

    async def pause_and_drain(self: Pilot, delay: float | None = None) -> None:
        await pause(self, delay)
        if delay is None:
            await drain(self)

    monkeypatch.setattr(Pilot, "press", press_and_drain)
    monkeypatch.setattr(Pilot, "pause", pause_and_drain)


@pytest.fixture(autouse=True)
def _every_notification_kept(monkeypatch: pytest.MonkeyPatch) -> None:
    keep_every_notification(monkeypatch)

"""Driving a Textual app under ``run_test`` for the jump and step sections: the app to
measure, and a key press that waits for no idle-detection sleeps."""

from __future__ import annotations

from tests.textual_internals import settle
from tui_search.engine.run.recorded import Run

TERMINAL = (160, 50)  # columns, rows of the headless and pty runs


def search_app_class():
    """SearchApp, or None with the reason (the app may not be written yet)."""
    try:
        from tui_search.tui.app import SearchApp
    except Exception as exc:  # noqa: BLE001 -- any failure means "no app to measure"
        return None, f"app not available ({type(exc).__name__}: {exc})"
    return SearchApp, ""


def app_run(app) -> Run | None:
    """The app's current Run: its session's first pane's."""
    return app.session.run




async def fast_press(pilot, key: str) -> None:
    from textual import events

    pilot.app.post_message(events.Key(key, key if len(key) == 1 else None))
    await settle(pilot)

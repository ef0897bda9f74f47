"""What the search settings screen dismisses with (a plain value, so the app imports it
without the screen: start-up time)."""

from __future__ import annotations

from typing import NamedTuple

from tui_search.engine.semantics import Semantics


class SettingsChoice(NamedTuple):
    """The search choices, and the searches compare mode compares (``bfs,dfs``)."""

    semantics: Semantics
    compare: str


__all__ = ["SettingsChoice"]

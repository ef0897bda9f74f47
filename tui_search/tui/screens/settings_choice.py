"""What the search settings screen dismisses with (a plain value, so the app imports it
without the screen: start-up time)."""

from __future__ import annotations

from dataclasses import dataclass

from tui_search.engine.semantics import Semantics


@dataclass(frozen=True)
class SettingsChoice:
    """The search choices, and the searches compare mode compares (``bfs,dfs``)."""

    semantics: Semantics
    compare: str


__all__ = ["SettingsChoice"]

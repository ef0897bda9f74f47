"""What the search settings screen dismisses with (a plain value, so the app imports it
without the screen: start-up time)."""

# No `from __future__ import annotations`: typing compiles a NamedTuple's string
# annotations one by one at import (~5 M instructions of every start in all: session 14).
from typing import NamedTuple

from tui_search.engine.search.choices import Semantics


class SettingsChoice(NamedTuple):
    """The search choices, and the searches c compares (``bfs,dfs``)."""

    semantics: Semantics
    comparison: str


__all__ = ["SettingsChoice"]

"""What the search settings screen dismisses with (a plain value, so the app imports it
without the screen: start-up time)."""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import NamedTuple

from tui_search.engine.search.choices import Semantics


class SettingsChoice(NamedTuple):
    """The search choices, and the searches c compares (``bfs,dfs``)."""

    semantics: Semantics
    comparison: str


__all__ = ["SettingsChoice"]

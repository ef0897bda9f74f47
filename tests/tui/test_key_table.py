"""The key table: no key does two jobs by accident (two features once both took ``m``)."""

from __future__ import annotations

from collections import Counter

from textual.binding import Binding

from tui_search.tui.screens.keys import KEYS

#: Keys bound twice on purpose: one hint each way (space: play / pause), or a lesson's
#: section keys over the cursor's page keys (pgdn / pgup).
SHARED = {"space", "pagedown", "pageup"}


def test_no_key_is_bound_to_two_actions_but_the_shared_ones() -> None:
    keys = Counter(key.strip() for b in KEYS if isinstance(b, Binding) for key in b.key.split(","))
    assert {key for key, n in keys.items() if n > 1} == SHARED

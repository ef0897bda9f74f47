"""Parts of a screen or a pane that a layout may leave hidden, mounted the first time one is
shown: a first frame without them neither composes nor styles them (Textual styles every
mounted widget and each of its component classes, hidden or not)."""

from __future__ import annotations

from collections.abc import Sequence

from textual.widget import Widget


def show_part(parent: Widget, part: Widget, shown: bool, order: Sequence[Widget]) -> None:
    """Mount ``part`` in ``parent`` the first time it is ``shown``, before the first of the
    widgets after it in ``order`` (``parent``'s children as composed) that is mounted."""
    if not shown or part.parent is not None:
        return
    later = [w for w in order[list(order).index(part) + 1:] if w.parent is not None]
    parent.mount(part, before=later[0] if later else None)

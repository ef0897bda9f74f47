"""Parts of a screen or a pane that a layout may leave hidden, mounted the first time one is
shown: a first frame without them neither composes nor styles them (Textual styles every
mounted widget and each of its component classes, hidden or not).  Those most starts never
show (the comparison table, the challenge, the Code panel) are made when first asked for too
(:class:`Later`): their modules imported, their classes set up and the widgets made then."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Generic, TypeVar

from textual.widget import Widget

if TYPE_CHECKING:
    from tui_search.tui.widgets.challenge import ChallengePanel
    from tui_search.tui.widgets.code_panel import CodePanel
    from tui_search.tui.widgets.compare_table import CompareTable

W = TypeVar("W", bound=Widget)


def show_part(parent: Widget, part: Widget, shown: bool,
              order: Sequence[Widget | None]) -> None:
    """Mount ``part`` in ``parent`` the first time it is ``shown``, before the first of the
    widgets after it in ``order`` (``parent``'s children as composed; None: one not made yet)
    that is mounted."""
    if not shown or part.parent is not None:
        return
    later = [w for w in order[list(order).index(part) + 1:]
             if w is not None and w.parent is not None]
    parent.mount(part, before=later[0] if later else None)


class Later(Generic[W]):
    """A part made by ``make`` the first time it is asked for (:meth:`get`); :attr:`made` is
    None until then: a first frame that does not show the part neither imports, composes nor
    styles it (benchmarks/README.md, "startup")."""

    def __init__(self, make: Callable[[], W]) -> None:
        self._build = make
        self.made: W | None = None

    def get(self) -> W:
        if self.made is None:
            self.made = self._build()
        return self.made


# What each part needs is imported when it is first made.
def compare_table() -> CompareTable:
    from tui_search.tui.widgets.compare_table import CompareTable

    table = CompareTable(id="compare-table")
    table.display = False  # until a layout shows it (PanesScreen.fit_panes)
    return table


def challenge_panel() -> ChallengePanel:
    from tui_search.tui.widgets.challenge import ChallengePanel

    return ChallengePanel(id="challenge")


def code_panel() -> CodePanel:
    from tui_search.tui.widgets.code_panel import CodePanel

    return CodePanel(classes="pane-code -folded")

"""The end of a run by hand: its steps, its mistakes by cause, the time it took, the hints and
undos, the exercise's verdict; then the replay of the run beside the search (``r``), the run
again (``a``), or back (escape)."""

from __future__ import annotations

from typing import ClassVar

from textual.binding import Binding, BindingType

from tui_search.tui.dialogs.question import QuestionScreen
from tui_search.tui.model.by_hand import ByHand
from tui_search.tui.view.by_hand_text import summary_lines

#: What the dialog dismisses with.
REPLAY, AGAIN, BACK = "replay", "again", "back"


class ByHandSummaryScreen(QuestionScreen):
    """The summary; ``r`` replays, ``a`` starts again, escape (or ``b``) goes back."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("r", "choose('replay')", "Replay"),
        Binding("a", "choose('again')", "Again"),
        Binding("b,escape", "choose('back')", "Back"),
    ]
    AUTO_FOCUS = "#replay"
    DEFAULT_CSS = """
    ByHandSummaryScreen > Vertical { width: 76; border: round $accent; }
    """

    def __init__(self, by_hand: ByHand) -> None:
        summary = by_hand.summary()
        lines = summary_lines(summary, by_hand.name)
        super().__init__(
            f"By hand: {by_hand.name} · done", "\n".join(lines),
            [(REPLAY, f"Replay beside {by_hand.name} (r)", "primary"),
             (AGAIN, "Again (a)", "default"), (BACK, "Back (esc)", "default")])
        self.lines = lines


__all__ = ["AGAIN", "BACK", "REPLAY", "ByHandSummaryScreen"]

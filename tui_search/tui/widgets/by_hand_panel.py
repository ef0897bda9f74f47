"""The by-hand panel, over the panes: what to do now, a mistake named the moment it is made
(or a hint), and the counts so far (:mod:`~tui_search.tui.view.by_hand_text` says it)."""

from __future__ import annotations

from typing import ClassVar

from rich.text import Text
from textual.widgets import Static

from tui_search.tui.model.by_hand import ByHand
from tui_search.tui.view.by_hand_text import panel_lines, title


class ByHandPanel(Static):
    """The by-hand run's words; :meth:`show` after every move."""

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "by-hand--prompt", "by-hand--mistake", "by-hand--said", "by-hand--counts",
        "by-hand--solved", "by-hand--unsolved",
    }

    DEFAULT_CSS = """
    ByHandPanel {
        height: auto;
        max-height: 8;
        padding: 0 1;
        border: round $accent;
        border-title-align: left;
        border-title-color: $text-accent;
        & > .by-hand--prompt { color: $foreground; }
        & > .by-hand--mistake { color: $text-warning; text-style: bold; }
        & > .by-hand--said { color: $text-accent; }
        & > .by-hand--counts { color: $text-muted; }
        & > .by-hand--solved { color: $text-success; text-style: bold; }
        & > .by-hand--unsolved { color: $text-warning; }
    }
    """

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.text = ""  # what it says, as plain text (for tests)

    def show(self, by_hand: ByHand) -> None:
        self.border_title = title(by_hand)
        style = self.get_component_rich_style
        out = Text()
        for i, line in enumerate(panel_lines(by_hand)):
            if i:
                out.append("\n")
            for text, kind in line:
                out.append(text, style(f"by-hand--{kind}"))
        self.text = out.plain
        self.update(out)


__all__ = ["ByHandPanel"]

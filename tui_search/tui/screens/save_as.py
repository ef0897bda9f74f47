"""Ask for a file name (ctrl+s on a map that has none): dismisses with a Path, or None."""

from __future__ import annotations

from pathlib import Path
from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Input, Label


class SaveAsScreen(ModalScreen[Path | None]):
    """A one-line prompt; enter saves, escape cancels."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]
    AUTO_FOCUS = "Input"

    DEFAULT_CSS = """
    SaveAsScreen {
        align: center middle;
        & > Vertical {
            width: 60;
            max-width: 95%;
            height: auto;
            border: round $primary;
            background: $surface;
            padding: 0 1;
        }
        & Label { margin-bottom: 1; }
        & .hint { color: $text-muted; margin: 0; }
    }
    """

    def __init__(self, suggestion: str = "map.txt") -> None:
        super().__init__()
        self.suggestion = suggestion

    def compose(self) -> ComposeResult:
        with Vertical() as box:
            box.border_title = "Save the map as"
            yield Label("File name (text map: # obstacle, S start, G goal):")
            yield Input(value=self.suggestion, id="filename")
            yield Label("enter to save · escape to cancel", classes="hint")

    def on_input_submitted(self, event: Input.Submitted) -> None:
        name = event.value.strip()
        if name:
            self.dismiss(Path(name).expanduser())

    def action_cancel(self) -> None:
        self.dismiss(None)

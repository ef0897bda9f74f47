"""Quitting with unsaved edits asks first: save, quit anyway, or stay."""

from __future__ import annotations

from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Label

#: What the screen dismisses with.
SAVE, QUIT, STAY = "save", "quit", "stay"


class ConfirmQuitScreen(ModalScreen[str]):
    """``s`` saves then quits, ``y`` quits without saving, ``n`` or escape stays."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("s", "choose('save')", "Save and quit"),
        Binding("y", "choose('quit')", "Quit without saving"),
        Binding("n,escape", "choose('stay')", "Stay"),
    ]
    AUTO_FOCUS = "#stay"

    DEFAULT_CSS = """
    ConfirmQuitScreen {
        align: center middle;
        & > Vertical {
            width: 64;
            max-width: 95%;
            height: auto;
            border: round $warning;
            background: $surface;
            padding: 0 1;
        }
        & Label { width: 100%; }
        & Horizontal { height: auto; margin-top: 1; }
        & Button { margin-right: 1; min-width: 10; }
    }
    """

    def __init__(self, name: str) -> None:
        super().__init__()
        self.map_name = name

    def compose(self) -> ComposeResult:
        with Vertical() as box:
            box.border_title = "Unsaved edits"
            yield Label(f"The map {self.map_name} has edits that are not saved. Quit anyway?")
            with Horizontal():
                yield Button("Save and quit (s)", id=SAVE, variant="primary")
                yield Button("Quit (y)", id=QUIT, variant="error")
                yield Button("Stay (n)", id=STAY)

    def on_button_pressed(self, event: Button.Pressed) -> None:
        self.dismiss(event.button.id or STAY)

    def action_choose(self, choice: str) -> None:
        self.dismiss(choice)

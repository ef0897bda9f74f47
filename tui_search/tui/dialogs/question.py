"""A question with a row of buttons, each also a key: the base of the unsaved-edits and the
overwrite questions."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Label


class QuestionScreen(ModalScreen[str]):
    """Dismisses with the id of the button pressed, or of the choice a key binding names
    (subclasses bind their keys to ``choose('<id>')``)."""

    DEFAULT_CSS = """
    QuestionScreen {
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

    def __init__(self, title: str, text: str, buttons: list[tuple[str, str, str]]) -> None:
        """``buttons``: (id, label, variant) from left to right."""
        super().__init__()
        self.title_text = title
        self.question_text = text
        self.buttons = buttons

    def compose(self) -> ComposeResult:
        with Vertical() as box:
            box.border_title = self.title_text
            yield Label(self.question_text, markup=False)  # names in it are typed
            with Horizontal():
                for choice, label, variant in self.buttons:
                    yield Button(label, id=choice, variant=variant)  # type: ignore[arg-type]

    def on_button_pressed(self, event: Button.Pressed) -> None:
        self.dismiss(event.button.id or "")

    def action_choose(self, choice: str) -> None:
        self.dismiss(choice)

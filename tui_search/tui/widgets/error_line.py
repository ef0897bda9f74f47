"""A prompt's error: one line under its field, shown only while there is one (the name and
the recipe prompts use it).  Without markup: what it quotes was typed by the user."""

from __future__ import annotations

from textual.widgets import Static


class ErrorLine(Static):
    """The error under a prompt's field ("" and hidden when there is none)."""

    DEFAULT_CSS = """
    ErrorLine { color: $text-error; display: none; width: 100%; height: auto; }
    ErrorLine.-shown { display: block; }
    """

    def __init__(self) -> None:
        super().__init__(id="error", markup=False)

    @property
    def message(self) -> str:
        return str(self.content)

    def say(self, message: str) -> None:
        """Show ``message`` (hide the line for "")."""
        self.update(message)
        self.set_class(bool(message), "-shown")

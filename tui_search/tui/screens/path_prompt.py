"""A one-line file-name prompt that stays open until its action succeeds: the base of the
save-as and open prompts.

What went wrong (a directory, no permission, a malformed map) is shown inside the prompt,
one line, and the name typed stays there to be corrected; escape cancels.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import ClassVar, TypeVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Input, Label, Static

T = TypeVar("T")


class PathPrompt(ModalScreen[T]):
    """Subclasses set the texts and implement :meth:`submit`."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]
    AUTO_FOCUS = "Input"

    DEFAULT_CSS = """
    PathPrompt {
        align: center middle;
        & > Vertical {
            width: 72;
            max-width: 95%;
            height: auto;
            border: round $primary;
            background: $surface;
            padding: 0 1;
        }
        /* a label longer than the box wraps, never cut */
        & Label { width: 100%; height: auto; margin-bottom: 1; }
        & #error { color: $text-error; display: none; width: 100%; height: auto; }
        & #error.-shown { display: block; }
        & .hint { color: $text-muted; margin: 0; }
    }
    """

    TITLE_TEXT = ""
    LABEL_TEXT = ""
    HINT_TEXT = "enter to confirm · escape to cancel"

    def __init__(self, suggestion: str = "", to_path: Callable[[str], Path] | None = None) -> None:
        """``to_path`` turns the name typed into the file it stands for, or raises ValueError
        with the one-line reason it is refused (the served app's
        :meth:`~tui_search.tui.file_access.FileAccess.path_for`); by default any path, ``~``
        expanded."""
        super().__init__()
        self.suggestion = suggestion
        self.to_path = to_path or (lambda name: Path(name).expanduser())

    def compose(self) -> ComposeResult:
        with Vertical() as box:
            box.border_title = self.TITLE_TEXT
            yield Label(self.LABEL_TEXT)
            yield Input(value=self.suggestion, id="filename")
            yield Static(id="error")
            yield Label(self.HINT_TEXT, classes="hint")

    @property
    def error(self) -> str:
        """The error shown in the prompt ("" when none)."""
        return str(self.query_one("#error", Static).content)

    def show_error(self, message: str) -> None:
        error = self.query_one("#error", Static)
        error.update(message)
        error.set_class(bool(message), "-shown")
        self.query_one(Input).focus()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        name = event.value.strip()
        if name:
            self.show_error("")
            try:
                path = self.to_path(name)
            except ValueError as exc:
                self.show_error(str(exc))
                return
            self.submit(path)

    def on_input_changed(self, event: Input.Changed) -> None:
        self.show_error("")  # the error was about the name as it was

    def submit(self, path: Path) -> None:
        """Act on ``path``: dismiss on success, or :meth:`show_error` and stay."""
        raise NotImplementedError

    def action_cancel(self) -> None:
        self.dismiss(None)

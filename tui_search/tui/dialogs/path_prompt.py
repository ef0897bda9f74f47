"""A one-line file-name prompt, with a file picker beside it, that stays open until its
action succeeds: the base of the save-as and open prompts.

What went wrong (a directory, no permission, a malformed map, a name no file can have) is
shown inside the prompt, one line, and the name typed stays there to be corrected; escape
cancels.  No name typed or picked raises: every one ends as an action or a line in the prompt.
The name field has the focus; choosing a file in the picker (enter, a click) puts its name
in the field, and choosing it again acts on it.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import ClassVar, TypeVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical
from textual.screen import ModalScreen
from textual.widgets import DirectoryTree, Input, Label

from tui_search.tui.model.file_rules import FileAccess, name_or_problem, one_line
from tui_search.tui.widgets.error_line import ErrorLine
from tui_search.tui.widgets.map_tree import MapTree

T = TypeVar("T")


class PathPrompt(ModalScreen[T]):
    """Subclasses set the texts and implement :meth:`submit`."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]
    AUTO_FOCUS = "#filename"

    DEFAULT_CSS = """
    PathPrompt {
        align: center middle;
        & > Vertical {
            width: 78;
            max-width: 98%;
            height: auto;
            border: round $primary;
            background: $surface;
            padding: 0 1;
        }
        /* a label longer than the box wraps, never cut */
        & Label { width: 100%; height: auto; margin-bottom: 1; }
        & Horizontal { height: auto; }
        & MapTree { margin-right: 1; }
        & #fields { width: 1fr; height: auto; }
        & .hint { color: $text-muted; margin: 0; }
    }
    """

    TITLE_TEXT = ""
    LABEL_TEXT = ""
    HINT_TEXT = "enter to confirm · escape to cancel"

    def __init__(self, suggestion: str = "", to_path: Callable[[str], Path] | None = None, *,
                 folder: Path | None = None, flat: bool = False, error: str = "") -> None:
        """``to_path`` turns the name typed into the file it stands for, or raises ValueError
        with the one-line reason it is refused (the served app's
        :meth:`~tui_search.tui.model.file_rules.FileAccess.path_for`); by default any path, ``~``
        expanded.  ``folder``: where the file picker starts (no picker without it);
        ``flat``: the picker shows that folder's map files only, and picks their plain names
        (the served app).  ``error``: shown at once (why the prompt was opened)."""
        super().__init__()
        self.suggestion = suggestion
        self.served = flat
        self.to_path = to_path or FileAccess().path_for
        self.folder = folder
        self.first_error = error
        self.error_about: str | None = None  # the name the error shown is about

    def compose(self) -> ComposeResult:
        with Vertical() as box:
            box.border_title = self.TITLE_TEXT
            yield Label(self.LABEL_TEXT)
            with Horizontal():
                if self.folder is not None:
                    yield MapTree(self.folder, flat=self.served, id="picker")
                with Vertical(id="fields"):
                    yield Input(value=self.suggestion, id="filename")
                    yield ErrorLine()
                    yield Label(self.HINT_TEXT, classes="hint")

    def on_mount(self) -> None:
        if self.first_error:
            self.show_error(self.first_error)

    @property
    def error(self) -> str:
        """The error shown in the prompt ("" when none)."""
        return self.query_one(ErrorLine).message

    def show_error(self, message: str) -> None:
        self.query_one(ErrorLine).say(message)
        field = self.query_one("#filename", Input)
        self.error_about = field.value if message else None
        field.focus()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        self.attempt(event.value)

    def attempt(self, typed: str) -> None:
        """What enter does with the name ``typed``: act on its file, or say why not."""
        if not typed.strip():
            return
        self.show_error("")
        path = name_or_problem(typed, self.to_path)
        if isinstance(path, str):
            self.show_error(path)
            return
        try:
            self.submit(path)
        except (OSError, ValueError) as exc:  # what a name may still do: never end the app
            self.show_error(one_line(exc))

    def on_input_changed(self, event: Input.Changed) -> None:
        if event.value != self.error_about:
            self.show_error("")  # the error was about the name as it was

    def on_directory_tree_file_selected(self, event: DirectoryTree.FileSelected) -> None:
        """A file chosen in the picker: its name in the field; chosen again, acted on."""
        event.stop()
        name = event.path.name if self.served else str(event.path)
        field = self.query_one("#filename", Input)
        if field.value == name:
            self.attempt(name)
        else:
            field.value = name
            field.cursor_position = len(name)

    def on_directory_tree_directory_selected(self, event: DirectoryTree.DirectorySelected) -> None:
        """A folder chosen: the field starts with it, to type the file's name after."""
        event.stop()
        if not self.served and event.path != self.folder:
            field = self.query_one("#filename", Input)
            field.value = f"{event.path}/"
            field.cursor_position = len(field.value)

    def submit(self, path: Path) -> None:
        """Act on ``path``: dismiss on success, or :meth:`show_error` and stay."""
        raise NotImplementedError

    def action_cancel(self) -> None:
        self.dismiss(None)

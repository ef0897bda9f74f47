"""Leaving a map with unsaved edits asks first: save, go on without saving, or stay.

Quitting asks it, and so does anything that replaces the map (opening another file, an
exercise): :class:`Leaving` holds the words for each.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from textual.binding import Binding, BindingType

from tui_search.tui.dialogs.question import QuestionScreen

#: What the screen dismisses with.
SAVE, QUIT, STAY = "save", "quit", "stay"


@dataclass(frozen=True)
class Leaving:
    """The question's last sentence and its three buttons, for one way of leaving a map."""

    question: str
    save: str
    discard: str
    stay: str


QUITTING = Leaving("Quit anyway?", "Save and quit", "Quit", "Stay")


def replacing(new_name: str) -> Leaving:
    """The words for replacing the map with ``new_name``."""
    return Leaving(f"Open {new_name} anyway?", "Save, then open", "Discard edits", "Cancel")


def generating(title: str) -> Leaving:
    """The words for replacing the map with the generated map ``title``."""
    return Leaving(f"Generate {title} anyway?", "Save, then generate", "Discard edits", "Cancel")


class ConfirmQuitScreen(QuestionScreen):
    """``s`` saves then goes on, ``y`` goes on without saving, ``n`` or escape stays."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("s", "choose('save')", "Save and quit"),
        Binding("y", "choose('quit')", "Quit without saving"),
        Binding("n,escape", "choose('stay')", "Stay"),
    ]
    AUTO_FOCUS = "#stay"

    def __init__(self, name: str, leaving: Leaving = QUITTING) -> None:
        super().__init__(
            "Unsaved edits",
            f"The map {name} has edits that are not saved. {leaving.question}",
            [(SAVE, f"{leaving.save} (s)", "primary"),
             (QUIT, f"{leaving.discard} (y)", "error"),
             (STAY, f"{leaving.stay} (n)", "default")],
        )
        self.map_name = name
        self.leaving = leaving

"""The questions a refused save asks: the file changed on disk (overwrite, reload, save as,
cancel), reloading drops the app's edits (reload, keep them), and the file has other names
(write in place, don't save)."""

from __future__ import annotations

from typing import ClassVar

from textual.binding import Binding, BindingType

from tui_search.tui.dialogs.question import QuestionScreen

#: What the screens dismiss with.
OVERWRITE, RELOAD, SAVE_AS, CANCEL, YES = "overwrite", "reload", "save-as", "cancel", "yes"


class ChangedOnDiskScreen(QuestionScreen):
    """``o`` overwrites, ``r`` reloads, ``a`` saves as, ``c`` or escape cancels (focused)."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("o", "choose('overwrite')", "Overwrite"),
        Binding("r", "choose('reload')", "Reload"),
        Binding("a", "choose('save-as')", "Save as"),
        Binding("c,escape", "choose('cancel')", "Cancel"),
    ]
    AUTO_FOCUS = "#cancel"

    def __init__(self, name: str) -> None:
        """``name``: the file, as shown (escaped)."""
        super().__init__(
            "Changed on disk",
            f"{name} changed on disk since it was opened or saved: saving would lose "
            "those changes.",
            [(OVERWRITE, "Overwrite (o)", "error"),
             (RELOAD, "Reload (r)", "warning"),
             (SAVE_AS, "Save as… (a)", "primary"),
             (CANCEL, "Cancel (c)", "default")],
        )


class YesNoScreen(QuestionScreen):
    """``y`` does what the question offers, ``n`` or escape does not (focused)."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("y", "choose('yes')", "Yes"),
        Binding("n,escape", "choose('cancel')", "No"),
    ]
    AUTO_FOCUS = "#cancel"

    def __init__(self, title: str, text: str, yes: str, no: str) -> None:
        """``yes`` and ``no``: the buttons' words (the keys are added)."""
        super().__init__(title, text, [(YES, f"{yes} (y)", "error"),
                                       (CANCEL, f"{no} (n)", "primary")])


class DropEditsScreen(YesNoScreen):
    """Reload, dropping the app's edits?"""

    def __init__(self, name: str) -> None:
        super().__init__("Drop your edits?",
                         f"Reloading {name} drops the edits made in the app. Reload anyway?",
                         "Reload, drop my edits", "Keep my edits")


class InPlaceScreen(YesNoScreen):
    """Write a file with hard links in place?"""

    def __init__(self, name: str, others: int) -> None:
        names = f"{others} other name{'s' if others != 1 else ''}" if others else "other names"
        super().__init__("Hard links",
                         f"{name}: this file has {names}; write it in place so they all change?",
                         "Write in place", "Don't save")

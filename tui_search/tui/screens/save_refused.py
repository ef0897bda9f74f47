"""The questions a refused save asks: the file changed on disk (overwrite, reload, save as,
cancel), reloading drops the app's edits (reload, keep them), and the file has other names
(write in place, don't save)."""

from __future__ import annotations

from typing import ClassVar

from textual.binding import Binding, BindingType

from tui_search.tui.screens.question import QuestionScreen

#: What the screens dismiss with.
OVERWRITE, RELOAD, SAVE_AS, CANCEL, IN_PLACE = "overwrite", "reload", "save-as", "cancel", "in-place"


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


class DropEditsScreen(QuestionScreen):
    """``y`` reloads and drops the edits, ``n`` or escape keeps them (focused)."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("y", "choose('reload')", "Reload"),
        Binding("n,escape", "choose('cancel')", "Keep my edits"),
    ]
    AUTO_FOCUS = "#cancel"

    def __init__(self, name: str) -> None:
        super().__init__(
            "Drop your edits?",
            f"Reloading {name} drops the edits made in the app. Reload anyway?",
            [(RELOAD, "Reload, drop my edits (y)", "error"),
             (CANCEL, "Keep my edits (n)", "primary")],
        )


class InPlaceScreen(QuestionScreen):
    """``y`` writes the file in place, ``n`` or escape does not save (focused)."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("y", "choose('in-place')", "Write in place"),
        Binding("n,escape", "choose('cancel')", "Don't save"),
    ]
    AUTO_FOCUS = "#cancel"

    def __init__(self, name: str, others: int) -> None:
        names = f"{others} other name{'s' if others != 1 else ''}" if others else "other names"
        super().__init__(
            "Hard links",
            f"{name}: this file has {names}; write it in place so they all change?",
            [(IN_PLACE, "Write in place (y)", "warning"),
             (CANCEL, "Don't save (n)", "primary")],
        )

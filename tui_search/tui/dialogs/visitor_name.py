"""Who is this?  A served app with records (``--serve --records DIR``) asks its visitor before
anything else: a name, or -- with the teacher's class list (``--class FILE``) -- one of its
names, found by typing a part of it.  Dismisses with the name (cleaned as the records keep
it); there is no way round it, as the records are the class's.
"""

from __future__ import annotations

from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Input, Label, OptionList

from tui_search.engine.course.records import MAX_NAME, clean_name
from tui_search.tui.widgets.error_line import ErrorLine

#: The class list's names shown at once (the rest found by typing).
SHOWN = 200


class VisitorNameScreen(ModalScreen[str]):
    """Type a name and enter; with a class list, the names that match what is typed are
    listed (up and down choose, enter takes the one chosen)."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("down", "choose(1)", "Next name", show=False),
        Binding("up", "choose(-1)", "Name before", show=False),
    ]
    AUTO_FOCUS = "#name"
    DEFAULT_CSS = """
    VisitorNameScreen {
        align: center middle;
        & > Vertical {
            width: 64;
            max-width: 95%;
            height: auto;
            max-height: 90%;
            border: round $accent;
            background: $surface;
            padding: 0 1;
        }
        & Label { width: 100%; }
        & OptionList { height: auto; max-height: 12; }
    }
    """

    def __init__(self, class_list: tuple[str, ...] = ()) -> None:
        super().__init__()
        self.class_list = class_list

    def compose(self) -> ComposeResult:
        with Vertical() as box:
            box.border_title = "Who are you?"
            if self.class_list:
                yield Label("Your teacher keeps a record of this class's work. Type a part "
                            "of your name, choose it (up, down) and press enter:")
            else:
                yield Label("Your teacher keeps a record of this class's work. Your name, "
                            "then enter:")
            yield Input(placeholder="your name", id="name", max_length=MAX_NAME)
            yield ErrorLine()
            if self.class_list:
                yield OptionList(*self.class_list[:SHOWN], id="names")

    def matches(self, typed: str) -> list[str]:
        """The class list's names that hold ``typed`` (case aside), in the list's order."""
        key = clean_name(typed).casefold()
        return [n for n in self.class_list if key in n.casefold()]

    def on_input_changed(self, event: Input.Changed) -> None:
        if not self.class_list:
            return
        names = self.query_one("#names", OptionList)
        names.clear_options()
        names.add_options(self.matches(event.value)[:SHOWN])
        names.highlighted = 0 if names.option_count else None
        self.query_one(ErrorLine).say("")

    def action_choose(self, by: int) -> None:
        if not self.class_list:
            return
        names = self.query_one("#names", OptionList)
        if names.option_count:
            now = names.highlighted if names.highlighted is not None else -by
            names.highlighted = max(0, min(names.option_count - 1, now + by))

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        self.dismiss(str(event.option.prompt))

    def on_input_submitted(self, event: Input.Submitted) -> None:
        error = self.query_one(ErrorLine)
        if self.class_list:
            names = self.query_one("#names", OptionList)
            chosen = names.highlighted
            if chosen is None or not names.option_count:
                error.say("No name of the class list holds that: type a part of yours")
                return
            self.dismiss(str(names.get_option_at_index(chosen).prompt))
            return
        name = clean_name(event.value)
        if not name:
            error.say("Type your name (your teacher sees it with your work)")
            return
        self.dismiss(name)


__all__ = ["VisitorNameScreen"]

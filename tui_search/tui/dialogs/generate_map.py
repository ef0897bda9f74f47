"""Ask for a map to generate (``ctrl+n``): ``KIND WxH SEED``, typed or as suggested (the same
kind and size with the next seed).  Dismisses with the recipe, or None on escape; a recipe
that is wrong keeps the prompt open with the one-line reason."""

from __future__ import annotations

from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Input, Label

from tui_search.engine.maps.generate import MAX_SIDE, Recipe, parse_recipe
from tui_search.tui.widgets.error_line import ErrorLine

KINDS_TEXT = ("Kinds: maze (the recursive backtracker: DFS carving its maze), prim, kruskal, "
              f"division, rooms, random:P (P% obstacles). At most {MAX_SIDE}x{MAX_SIDE}; the "
              "seed is a whole number or any text.")


class GenerateScreen(ModalScreen[Recipe | None]):
    """Enter generates, escape cancels."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]
    AUTO_FOCUS = "#recipe"

    DEFAULT_CSS = """
    GenerateScreen {
        align: center middle;
        & > Vertical {
            width: 70;
            max-width: 98%;
            height: auto;
            border: round $primary;
            background: $surface;
            padding: 0 1;
        }
        & Label { width: 100%; height: auto; }
        & .hint { color: $text-muted; }
    }
    """

    def __init__(self, suggestion: str) -> None:
        super().__init__()
        self.suggestion = suggestion

    def compose(self) -> ComposeResult:
        with Vertical() as box:
            box.border_title = "Generate a map"
            yield Label("KIND WxH SEED, e.g. maze 21x15 7:")
            yield Input(value=self.suggestion, id="recipe")
            yield ErrorLine()
            yield Label(KINDS_TEXT, classes="hint")
            yield Label("enter to generate · escape to cancel", classes="hint")

    @property
    def error(self) -> str:
        return self.query_one(ErrorLine).message

    def show_error(self, message: str) -> None:
        self.query_one(ErrorLine).say(message)

    def on_input_submitted(self, event: Input.Submitted) -> None:
        try:
            recipe = parse_recipe(event.value)
        except ValueError as exc:
            self.show_error(str(exc))
            return
        self.dismiss(recipe)

    def on_input_changed(self, event: Input.Changed) -> None:
        self.show_error("")

    def action_cancel(self) -> None:
        self.dismiss(None)

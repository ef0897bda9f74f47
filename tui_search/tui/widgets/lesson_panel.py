"""The lesson beside the panes: the section shown, as Markdown (Textual's ``Markdown``
widget), its place in the lesson in the border.

Imported only when a lesson is open (``--lesson``), so the app's start-up without one does not
load the Markdown widget.  It never takes the focus: every key still acts on the app, and
``pgdn`` / ``pgup`` move between sections (the main screen's keys).
"""

from __future__ import annotations

from textual.app import ComposeResult
from textual.containers import VerticalScroll
from textual.widgets import Markdown


class LessonPanel(VerticalScroll, can_focus=False):
    """A lesson's section, scrolled by the mouse wheel if it is longer than the panel."""

    DEFAULT_CSS = """
    LessonPanel {
        border: round $primary;
        border-title-color: $text;
        border-subtitle-color: $text-muted;
        padding: 0;
        scrollbar-size-vertical: 1;
    }
    LessonPanel Markdown {
        padding: 0 1;
    }
    LessonPanel MarkdownHeader {
        margin: 0 0 1 0;
    }
    """

    def __init__(self, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.document = Markdown(open_links=False)

    def compose(self) -> ComposeResult:
        yield self.document

    def show(self, where: str, text: str) -> None:
        """Show ``text`` (Markdown), ``where`` (``tutorial 2/10``) in the border."""
        self.border_title = f"Lesson {where}"
        self.border_subtitle = "pgdn next · pgup back"
        self.document.update(text)
        self.scroll_home(animate=False)

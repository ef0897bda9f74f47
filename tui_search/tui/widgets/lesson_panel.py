"""The lesson beside the panes: the section shown, as Markdown (Textual's ``Markdown``
widget), its place in the lesson in the border.

Imported only when a lesson is open (``--lesson``), so the app's start-up without one does not
load the Markdown widget.  It never takes the focus: every key still acts on the app, and
``pgdn`` / ``pgup`` (or shift+right / shift+left) move between sections, shift+down / shift+up
scroll a text longer than the panel (the main screen's keys; its border says them).
"""

from __future__ import annotations

from textual import events
from textual.app import ComposeResult
from textual.containers import VerticalScroll
from textual.widgets import Markdown

#: The keys the border says, the longest that fits the panel's width first.
KEY_HINTS = ("pgdn/⇧→ next · pgup/⇧← back · ⇧↑↓ scroll", "⇧→ next · ⇧← back · ⇧↑↓ scroll",
             "⇧←→ section · ⇧↑↓ scroll")


class LessonPanel(VerticalScroll, can_focus=False):
    """A lesson's section, scrolled by shift+down / shift+up or the mouse wheel if it is
    longer than the panel."""

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
        self._say_keys()
        self.document.update(text)
        self.scroll_home(animate=False)

    def scroll_by_half(self, by: int) -> None:
        """Scroll half the panel's height down (``by`` 1) or up (-1)."""
        half = max(1, self.scrollable_content_region.height // 2)
        self.scroll_relative(y=by * half, animate=False)

    def _say_keys(self) -> None:
        room = self.size.width - 4  # the border's corners, a space each side
        hint = next((h for h in KEY_HINTS if len(h) <= room), KEY_HINTS[-1])
        if self.border_subtitle != hint:
            self.border_subtitle = hint

    def on_resize(self, event: events.Resize) -> None:
        self._say_keys()

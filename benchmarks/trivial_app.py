"""The baseline: the least a Textual app can do -- one line-API widget whose line 5 changes
when n or p is pressed.

The step section drives it under ``run_test``; the start-up section runs this file by path
(``python benchmarks/trivial_app.py``) in a pseudo-terminal, as a user would start a script, so
it imports nothing but Textual and Rich.
"""

from __future__ import annotations

from typing import ClassVar

from rich.segment import Segment
from textual.app import App, ComposeResult
from textual.geometry import Region
from textual.strip import Strip
from textual.widget import Widget


class Lines(Widget, can_focus=True):
    """Line *y* says ``line y``; line 5 also counts the presses."""

    count = 0

    def render_line(self, y: int) -> Strip:
        text = f"line {y}" + (f": pressed {self.count} times" if y == 5 else "")
        return Strip([Segment(text.ljust(self.size.width))], self.size.width)


class TrivialApp(App):
    """``n`` / ``p`` change line 5 and repaint that one line; ``m`` makes the same change and
    repaints the whole widget; ``f`` makes it and repaints the first ``first`` lines (as many
    as a step of the real app draws)."""

    BINDINGS: ClassVar = [
        ("n", "bump(1)", "Next"), ("p", "bump(-1)", "Prev"), ("m", "all", "All"),
        ("f", "first", "First lines"),
    ]

    def __init__(self, first: int = 1) -> None:
        super().__init__()
        self.first = first  # lines that f redraws

    def compose(self) -> ComposeResult:
        yield Lines()

    def action_bump(self, d: int) -> None:
        lines = self.query_one(Lines)
        lines.count += d
        lines.refresh(Region(0, 5, lines.size.width, 1))

    def action_first(self) -> None:  # the same change, and the first lines repainted
        lines = self.query_one(Lines)
        lines.count += 1
        lines.refresh(Region(0, 0, lines.size.width, self.first))

    def action_all(self) -> None:  # the same change, but the whole widget is repainted
        lines = self.query_one(Lines)
        lines.count += 1
        lines.refresh()


if __name__ == "__main__":
    TrivialApp().run()

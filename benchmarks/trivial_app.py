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

    def __init__(self, first: int = 1, widgets: int = 1) -> None:
        super().__init__()
        self.first = first  # lines that f redraws
        self.widgets = widgets  # a start-up floor: that many bordered widgets in a grid

    def compose(self) -> ComposeResult:
        if self.widgets == 1:
            yield Lines()
            return
        from textual.containers import Grid

        with Grid() as grid:  # as many widgets as a screen of the real app, tiled
            grid.styles.grid_size_columns = 4
            for _ in range(self.widgets):
                lines = Lines()
                lines.styles.border = ("round", "white")
                yield lines

    def action_bump(self, d: int) -> None:
        lines = self.query(Lines).first()
        lines.count += d
        lines.refresh(Region(0, 5, lines.size.width, 1))

    def action_first(self) -> None:  # the same change, and the first lines repainted
        lines = self.query(Lines).first()
        lines.count += 1
        lines.refresh(Region(0, 0, lines.size.width, self.first))

    def action_all(self) -> None:  # the same change, but the whole widget is repainted
        lines = self.query(Lines).first()
        lines.count += 1
        lines.refresh()


if __name__ == "__main__":
    import sys

    TrivialApp(widgets=int(sys.argv[1]) if len(sys.argv) > 1 else 1).run()

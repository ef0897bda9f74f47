"""The status lines under the map: the counts, and what the search just did in the tutorial's
words (see :mod:`tui_search.tui.narration`).

Two lines redrawn on every step, so they are drawn with the line API from segments built in
:meth:`Stats.show`, with styles looked up once per style change (a ``Static`` rebuilt its
content through Textual's markup and visual pipeline on every step: a tenth of a step).
"""

from __future__ import annotations

from typing import ClassVar

from rich.cells import cell_len
from rich.segment import Segment
from textual.strip import Strip
from textual.widget import Widget

from tui_search.engine.algorithms import get_algorithm
from tui_search.engine.heuristics import INADMISSIBLE
from tui_search.engine.run import Run
from tui_search.tui.narration import narrate, result_text, status_parts
from tui_search.tui.widgets.line_panel import CachedStyles, Parts

#: What ends a line too long for the terminal.
ELLIPSIS = "…"


class Stats(CachedStyles, Widget):
    """Two lines: ``BFS │ step 4/18 │ expanded 4 │ …`` then the narration, which ends with
    the path's moves and cost once found (or says "no path").

    The app calls :meth:`show` after every change; ``note`` replaces the narration (e.g. while
    computing the end of a big run, or when the map lacks a start or a goal).  A line wider than
    the terminal ends in an ellipsis.
    """

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "stats--label", "stats--value", "stats--result", "stats--no-path", "stats--narration",
        "stats--note", "stats--play",
    }

    DEFAULT_CSS = """
    Stats {
        height: 2;
        padding: 0 1;
        background: $panel;
        & > .stats--label { color: $text-muted; }
        & > .stats--value { color: $text; text-style: bold; }
        & > .stats--result { color: $text-success; text-style: bold; }
        & > .stats--no-path { color: $text-error; text-style: bold; }
        & > .stats--narration { color: $text; }
        & > .stats--note { color: $text-warning; }
        & > .stats--play { color: $text-accent; text-style: bold; }
    }
    """

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.status_text = ""
        self.narration_text = ""
        self._lines: tuple[Parts, Parts] = ([], [])

    def show(
        self,
        run: Run | None,
        algorithm: str,
        *,
        playing: str = "",
        note: str = "",
    ) -> None:
        sep = (" │ ", "stats--label")
        status: Parts = [(get_algorithm(algorithm).short, "stats--value")]
        differences = run.semantics.differences(run.algo) if run is not None else []
        if run is not None and not run.admissible:
            differences.append(INADMISSIBLE)
        if differences:  # always say what differs
            status.append((" · " + " · ".join(differences), "stats--note"))
        if run is not None:
            for label, value in status_parts(run):
                status += [sep, (f"{label} ", "stats--label"), (value, "stats--value")]
        if playing:
            status += [sep, (playing, "stats--play")]
        line: Parts
        if note:
            line = [(note, "stats--note")]
        elif run is None:
            line = []
        else:
            failed = run.at_end and not run.found and not run.gave_up  # "no path", in red
            line = [(narrate(run), "stats--no-path" if failed else "stats--narration")]
            if run.at_end and run.found:
                line += [(" · ", "stats--label"), (result_text(run), "stats--result")]
        lines = (status, line)
        if lines != self._lines:
            self._lines = lines
            self.status_text = "".join(text for text, _ in status)
            self.narration_text = "".join(text for text, _ in line)
            self.refresh()

    def render_line(self, y: int) -> Strip:
        width = self.content_size.width
        base = self.cached_style()
        parts = self._lines[y] if 0 <= y < len(self._lines) else []
        style = self.cached_style
        segments = [Segment(text, style(cls)) for text, cls in parts]
        if sum(cell_len(text) for text, _ in parts) > width > 0:
            cut = list(Strip(segments).crop(0, width - 1))
            segments = [*cut, Segment(ELLIPSIS, cut[-1].style if cut else base)]
        return Strip(segments).crop_extend(0, width, base)

"""The status lines under the map: the counts, and what the search just did in the tutorial's
words (see :mod:`tui_search.tui.narration`)."""

from __future__ import annotations

from typing import ClassVar

from rich.text import Text
from textual.widgets import Static

from tui_search.engine.run import Run
from tui_search.tui.narration import SHORT_NAMES, narrate, result_text, status_parts


class Stats(Static):
    """Two lines: ``BFS │ step 4/18 │ expanded 4 │ …`` then the narration, which ends with
    the path's moves and cost once found (or says "no path").

    The app calls :meth:`show` after every change; ``note`` replaces the narration (e.g. while
    computing the end of a big run, or when the map lacks a start or a goal).
    """

    COMPONENT_CLASSES: ClassVar[set[str]] = {"stats--label", "stats--value", "stats--result", "stats--no-path",
                         "stats--narration", "stats--note", "stats--play"}

    DEFAULT_CSS = """
    Stats {
        height: 2;
        padding: 0 1;
        text-wrap: nowrap;
        text-overflow: ellipsis;
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
        super().__init__(id=id, markup=False)
        self.status_text = ""
        self.narration_text = ""

    def show(
        self,
        run: Run | None,
        algorithm: str,
        *,
        playing: str = "",
        note: str = "",
    ) -> None:
        style = self.get_component_rich_style
        sep = (" │ ", style("stats--label"))
        status = Text(no_wrap=False, overflow="fold")
        status.append(SHORT_NAMES[algorithm], style("stats--value"))
        if run is not None:
            for label, value in status_parts(run):
                status.append(*sep)
                status.append(f"{label} ", style("stats--label"))
                status.append(value, style("stats--value"))
        if playing:
            status.append(*sep)
            status.append(playing, style("stats--play"))
        if note:
            line = Text(note, style("stats--note"))
        elif run is None:
            line = Text()
        else:
            failed = run.at_end and not run.found and not run.gave_up  # "no path", in red
            line = Text(narrate(run), style("stats--no-path" if failed else "stats--narration"))
            if run.at_end and run.found:
                line.append(" · ", style("stats--label"))
                line.append(result_text(run), style("stats--result"))
        self.status_text = status.plain
        self.narration_text = line.plain
        self.update(Text("\n").join([status, line]), layout=False)  # always two lines

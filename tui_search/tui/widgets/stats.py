"""The status lines under the map: the counts, and what the search just did in the tutorial's
words (see :mod:`tui_search.tui.narration`).

Two lines redrawn on every step, so they are drawn with the line API from segments built in
:meth:`Stats.show`, with styles looked up once per style change (a ``Static`` rebuilt its
content through Textual's markup and visual pipeline on every step: a tenth of a step).
"""

from __future__ import annotations

from typing import ClassVar

from tui_search.engine.algorithms import get_algorithm
from tui_search.engine.heuristics import INADMISSIBLE
from tui_search.engine.run import Run
from tui_search.tui.narration import narrate, result_text, status_parts
from tui_search.tui.widgets.line_panel import Parts, PartsLines


class Stats(PartsLines):
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

    def __init__(self, *, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.status_text = ""
        self.narration_text = ""

    def show(
        self,
        run: Run | None,
        algorithm: str,
        *,
        playing: str = "",
        note: str = "",
        label: str = "",
        done: bool = False,
    ) -> None:
        """``label`` names the search (default: the algorithm's short name); ``done`` adds
        "done at step k" (a compare pane whose run ended before the others)."""
        sep = (" │ ", "stats--label")
        status: Parts = [(label or get_algorithm(algorithm).short, "stats--value")]
        if done and run is not None:
            status += [sep, (f"done at step {run.k:,}", "stats--result")]
        differences = run.semantics.differences(run.algo) if run is not None else []
        if run is not None and not run.admissible:
            differences.append(INADMISSIBLE)
        if differences:  # always say what differs
            status.append((" · " + " · ".join(differences), "stats--note"))
        if run is not None:
            for name, value in status_parts(run):
                status += [sep, (f"{name} ", "stats--label"), (value, "stats--value")]
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
        self._put_lines(status, line)

    def show_compare(self, labels: list[str], *, playing: str = "", note: str = "",
                     sentence: str = "") -> None:
        """Compare mode's lines: the searches and the playback, then a note or ``sentence``
        (how the lockstep goes)."""
        sep = (" │ ", "stats--label")
        status: Parts = [("compare ", "stats--label"), (" · ".join(labels), "stats--value")]
        if playing:
            status += [sep, (playing, "stats--play")]
        line: Parts = [(note, "stats--note")] if note else [(sentence, "stats--narration")]
        self._put_lines(status, line)

    def _put_lines(self, status: Parts, line: Parts) -> None:
        if self.set_lines([status, line]):
            self.status_text = "".join(text for text, _ in status)
            self.narration_text = "".join(text for text, _ in line)


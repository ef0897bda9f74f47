"""The status lines under the map: the counts, and what the search just did in the tutorial's
words (see :mod:`tui_search.tui.narration`).

Redrawn on every step, so they are drawn with the line API (a ``Static`` rebuilt its content
through Textual's markup and visual pipeline on every step: a tenth of a step), wrapped to the
widget's width by :class:`~tui_search.tui.widgets.parts_lines.PartsLines`: a count is never
split from its label, and when the rows run out the figures a student can do without go first
(the playing speed, the frontier's peak, ...), never the narration or the bound.
"""

from __future__ import annotations

from typing import ClassVar

from textual import events
from textual.message import Message

from tui_search.engine.algorithms import get_algorithm
from tui_search.engine.heuristics import INADMISSIBLE
from tui_search.engine.run import Run
from tui_search.tui.narration import frontier_word, narrate, result_text, status_parts
from tui_search.tui.widgets.parts_lines import Line, PartsLines, Piece, line_text

#: Between two counts on a row.
SEP = (" │ ", "stats--label")
#: At most this many rows while some piece can go; a pane's, one of several, at most
#: PANE_ROWS (its map comes first).
MAX_ROWS, PANE_ROWS = 4, 3
#: What goes first when the rows run out (the highest rank; 0 never goes).
BOUND_RANK, PLAYING_RANK, PEAK_RANK, DONE_RANK, PATH_RANK = 8, 7, 6, 5, 2
RANKS = {"discarded": 4, "expanded": 3, "generated": 3}


class Stats(PartsLines):
    """``BFS │ step 4/18 │ expanded 4 │ …`` then the narration, which ends with the path's
    moves and cost and the tutorial's bound once found (or says "no path"), each wrapped to
    as many rows as it needs (at most :attr:`MAX_ROWS` while some count can go).

    The app calls :meth:`show` after every change; ``note`` replaces the narration (e.g. the
    quiz's question, while computing the end of a big run, or when the map lacks a start or a
    goal).
    """

    MAX_ROWS: int | None = MAX_ROWS

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "stats--label", "stats--value", "stats--result", "stats--no-path", "stats--narration",
        "stats--note", "stats--play",
    }

    DEFAULT_CSS = """
    Stats {
        height: auto;
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
        self._height: int | None = None  # the rows laid out last

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
        status = [Piece([(label or get_algorithm(algorithm).short, "stats--value")])]
        if done and run is not None:
            status.append(Piece([(f"done at step {run.k:,}", "stats--result")], DONE_RANK, SEP))
        differences = run.semantics.differences(run.algo) if run is not None else []
        if run is not None and not run.admissible:
            differences.append(INADMISSIBLE)
        if differences:  # always say what differs
            status.append(Piece([("· " + " · ".join(differences), "stats--note")], 0,
                                (" ", "stats--note")))
        if run is not None:
            noun = frontier_word(run)
            for name, value in status_parts(run):
                parts = [(f"{name} ", "stats--label"), (value, "stats--value")]
                if name == noun:  # "(peak 8)": the first to go, but for the playing speed
                    short = [parts[0], (value.partition(" (")[0], "stats--value")]
                    status.append(Piece(parts, PEAK_RANK, SEP, short))
                else:
                    status.append(Piece(parts, RANKS.get(name, 1), SEP))
        if playing:
            status.append(Piece([(playing, "stats--play")], PLAYING_RANK, SEP))
        line: list[Piece]
        if note:
            line = [Piece([(note, "stats--note")])]
        elif run is None:
            line = []
        else:
            failed = run.at_end and not run.found and not run.gave_up  # "no path", in red
            line = [Piece([(narrate(run), "stats--no-path" if failed else "stats--narration")])]
            if run.at_end and run.found:  # the path, and the bound: what the lesson is about
                # (a pane of several: the comparison table says them too, and the map comes
                # first: the bound goes first, the path after the counts)
                ranks = (PATH_RANK, BOUND_RANK) if label else (0, 0)
                line += [Piece([(text, "stats--result")], rank, (" · ", "stats--label"))
                         for text, rank in zip(result_text(run).split(" · "), ranks)]
        self.MAX_ROWS = PANE_ROWS if label else MAX_ROWS
        self._put_lines(status, line)

    class HeightChanged(Message):
        """The lines took a row more or less: the room around them changed."""

    def on_resize(self, event: events.Resize) -> None:
        if event.size.height != self._height:
            if self._height is not None:
                self.post_message(self.HeightChanged())
            self._height = event.size.height

    def show_compare(self, labels: list[str], *, playing: str = "", note: str = "",
                     sentence: str = "") -> None:
        """Compare mode's lines: the searches and the playback, then a note or ``sentence``
        (how the lockstep goes)."""
        status = [Piece([("compare ", "stats--label"), (" · ".join(labels), "stats--value")])]
        if playing:
            status.append(Piece([(playing, "stats--play")], PLAYING_RANK, SEP))
        line = [Piece([(note, "stats--note")] if note else [(sentence, "stats--narration")])]
        self._put_lines(status, line)

    def _put_lines(self, status: list[Piece], line: list[Piece]) -> None:
        if self.set_lines([Line(status), Line(line, prose=True)]):
            self.status_text = line_text(status)
            self.narration_text = line_text(line)

"""Compare mode's table: a row a search with its figures at the position, live.

The cells are the command line's (:func:`~tui_search.engine.search.compare.table_cells`), so the
table on screen and ``--headless --compare`` print the same numbers; a run still going says
which step it is at, and the marks on the fewest expanded and the cheapest path appear once
every run is done.  Redrawn on every step, so drawn with the line API; a line wider than
the table (the summary sentence) wraps.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, ClassVar

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.compare import (
    MARKS_KEY,
    TableRow,
    comparison,
    summary_sentence,
    table_cells,
    table_lines,
)
from tui_search.tui.view.pieces import Parts, plain
from tui_search.tui.widgets.wrapped_lines import PartsLines

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun


def table_rows(labels: list[str], runs: Sequence[Run | BiRun]
               ) -> tuple[list[TableRow], list[int | None]]:
    """The rows at each run's position, and for each the step it is at while it is going
    (None once done)."""
    done = all(r.at_end for r in runs)
    outcomes = [r.outcome_so_far(r.k) for r in runs]
    steps = [None if r.at_end else r.k for r in runs]
    return comparison(labels, outcomes, marks=done), steps


class CompareTable(PartsLines):
    """The searches' figures side by side, and what they say in the tutorial's terms."""

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "compare-table--head", "compare-table--row", "compare-table--mark",
        "compare-table--key", "compare-table--sentence",
    }

    DEFAULT_CSS = """
    CompareTable {
        height: auto;
        padding: 0 1;
        border: round $border-blurred;
        border-title-align: left;
        border-title-color: $foreground;
        & > .compare-table--head { color: $text-muted; text-style: bold; }
        & > .compare-table--row { color: $foreground; }
        & > .compare-table--mark { color: $text-success; text-style: bold; }
        & > .compare-table--key { color: $text-muted; text-style: italic; }
        & > .compare-table--sentence { color: $text; text-style: bold; }
    }
    """

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.border_title = "Comparison"
        self.text_lines: list[str] = []  # what the table says (tests)

    def show(self, labels: list[str], runs: Sequence[Run | BiRun]) -> None:
        if not runs:
            self.text_lines = ["Place a start (s) and a goal (g) to compare"]
            self.set_lines([plain([(self.text_lines[0], "compare-table--key")], prose=True)])
            return
        rows, steps = table_rows(labels, runs)
        text = table_lines(table_cells(rows, steps))
        lines = [plain([(text[0], "compare-table--head")])]
        for line in text[1:]:
            # The marks in their own colour: "*" follows a figure, two spaces before the next.
            pieces = line.split(" *")
            parts: Parts = []
            for i, piece in enumerate(pieces):
                parts.append((piece, "compare-table--row"))
                if i < len(pieces) - 1:
                    parts.append((" *", "compare-table--mark"))
            lines.append(plain(parts))
        if all(s is None for s in steps):
            terrain = runs[0].graph is None and runs[0].grid.costs is not None
            sentence = summary_sentence(rows, terrain)
            lines += [plain([(MARKS_KEY, "compare-table--key")], prose=True),
                      plain([(sentence, "compare-table--sentence")], prose=True)]
            text += [MARKS_KEY, sentence]
        self.text_lines = text
        self.set_lines(lines)

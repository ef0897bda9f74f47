"""The settings' controls, built and read: a row of radio buttons for a choice (the word beside
each value, the buttons' ids ``name-value``, the value picked), and the *Compare (c)* boxes (one
a search of the registry: the one-directional in a row, the bidirectional in the next) with
the comparison they make, or the problem (fewer than two, more than four) shown under them."""

from __future__ import annotations

from typing import Any

from textual.app import ComposeResult
from textual.containers import Horizontal
from textual.dom import DOMNode
from textual.widget import Widget
from textual.widgets import Checkbox, Label, RadioSet

from tui_search.engine.search.choices import RECURSIVE_FORMS
from tui_search.engine.search.heuristics import HEURISTICS
from tui_search.engine.search.registry import ALGORITHMS, BIDIRECTIONAL
from tui_search.tui.model.searches import MAX_PANES, MIN_COMPARED, normal_spec, with_ticked
from tui_search.tui.widgets.pick_button import PickButton
from tui_search.tui.widgets.tick_box import TickBox

#: A word on each value, shown beside its radio button.
VALUE_WORDS: dict[str, str] = {
    "always": "always",
    "one": "if one side is free",
    "never": "if both sides are free",
    "generate": "when pushed",
    "expand": "when taken off",
    "expand-again": "taken off, not checked",
    **{name: name for name in HEURISTICS},
    "file": "as the file lists its roads", "name": "by name", "table": "the file's h table",
    "stack": "a stack",
    "neighbours": "a line lists neighbours",
    "calls": "a line lists calls",
    "fifo": "old", "lifo": "new", "node": "cell", "low-h": "low h",
    "high-h": "high h", "low-g": "low g", "high-g": "high g",
    # a bidirectional search's stopping rule and turn
    "proven": "proven", "first-meeting": "first meeting",
    "alternate": "alternate", "smaller": "smaller",
}
#: What recursion's radio buttons stand for: a stack (no recursion), or a trace's form.
RECURSION = ("stack", *RECURSIVE_FORMS)


class ChoiceRow(RadioSet):
    """A row of radio buttons that brings its pick into view only while it has the focus:
    Textual's also scrolls to each row's pick as the rows mount, so that where the settings
    opened scrolled would depend on when the layout came (to the last row's pick, on a
    terminal too short for them all)."""

    def scroll_to_widget(self, widget: Widget, **kwargs: Any) -> bool:
        """Textual's public scroll (the row's own pick is all it brings into view), only
        while the row has the focus."""
        return self.has_focus and super().scroll_to_widget(widget, **kwargs)


def radios(name: str, values: tuple[str, ...], chosen: str) -> RadioSet:
    """A row of radio buttons, one a value of choice ``name``, ``chosen`` picked: the row's id
    is ``name`` (``_`` as ``-``), a button's ``name-value``."""
    return ChoiceRow(
        *(PickButton(VALUE_WORDS[v], v == chosen, id=f"{name}-{v}") for v in values),
        id=name.replace("_", "-"),
        compact=True,
    )


def picked(screen: DOMNode, set_id: str) -> str:
    """The value picked in the row ``set_id`` of ``screen``."""
    button = screen.query_one(f"#{set_id}", RadioSet).pressed_button
    assert button is not None and button.id is not None
    return button.id.split("-", 1)[1]



# -- the compare boxes ------------------------------------------------------------------------
#: Under the boxes while the comparison is one compare mode can show.
COMPARE_EXPLAIN = "two to four searches side by side, in lockstep on the same map"


def compare_picks(comparison: str) -> ComposeResult:
    """The boxes, those of ``comparison``'s searches ticked, and the line under them."""
    named = {part.strip().partition(":")[0] for part in comparison.split(",")}
    yield Label("Compare (c)", classes="choice")
    for row, searches in (("compare-picks", ALGORITHMS), ("compare-picks-both", BIDIRECTIONAL)):
        with Horizontal(id=row, classes="picks"):
            for algo in searches.values():
                yield TickBox(algo.short, algo.key in named, id=f"compare-{algo.key}",
                              compact=True)
    yield Label(COMPARE_EXPLAIN, id="compare-explain", classes="explain extra")


def ticked_searches(screen: DOMNode) -> list[str]:
    """The keys of the searches whose box is ticked, in the registry's order."""
    return [key for key in (*ALGORITHMS, *BIDIRECTIONAL)
            if screen.query_one(f"#compare-{key}", Checkbox).value]


def picked_comparison(screen: DOMNode, comparison: str) -> str | None:
    """The comparison the boxes of ``screen`` make of ``comparison`` (unchanged: as it was,
    its order, its heuristics and rules), or None -- the problem shown under the boxes --
    when it would compare fewer than two or more than four searches."""
    spec = with_ticked(normal_spec(comparison), ticked_searches(screen))
    count = len(spec.split(",")) if spec else 0
    explain = screen.query_one("#compare-explain", Label)
    if not MIN_COMPARED <= count <= MAX_PANES:
        explain.set_class(True, "problem")
        explain.update(f"Compare: tick two to four searches ({count} ticked)")
        explain.scroll_visible()  # on a short terminal it may be below the choices shown
        return None
    explain.set_class(False, "problem")
    explain.update(COMPARE_EXPLAIN)
    return spec



__all__ = ["COMPARE_EXPLAIN", "RECURSION", "VALUE_WORDS", "ChoiceRow", "compare_picks", "picked",
           "picked_comparison", "radios", "ticked_searches"]

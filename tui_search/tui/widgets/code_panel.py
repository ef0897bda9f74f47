"""The Code panel: the pseudocode of the pane's search, generated from its algorithm and its
choices (:mod:`tui_search.engine.search.pseudocode`), with the lines the step at the run's position
executed lit (:mod:`tui_search.tui.view.code_trace`)::

      4 while the frontier is not empty:
    ▶ 5   node ← take off the front of the queue
          (pop front)

A lit line starts with ``▶`` as well as taking the lit colour, so it reads without colour.  A
line longer than the panel wraps under its own words (no number), so the code fits any width;
the panel keeps the most specific lit line in view (the skip, the discard, the goal test the
narration names: :func:`~tui_search.tui.view.code_trace.focus_line`), with the first lit one above
it when both fit.  It repaints only the rows whose text or light
changed, as the other line panels do.
"""

from __future__ import annotations

import textwrap
from typing import TYPE_CHECKING, Any, ClassVar

from textual.geometry import Region, Size

from tui_search.engine.run.recorded import Run
from tui_search.tui.view.code_trace import code_of, focus_line, lit_lines, named_lines
from tui_search.tui.view.pieces import Parts
from tui_search.tui.widgets.line_panel import LinePanel
from tui_search.tui.widgets.scrollbars import set_virtual_size

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.search.pseudocode import Pseudocode

#: The mark of a lit line, and the room a line's number takes after it.
LIT_MARK = "▶"
#: Spaces a level of indentation.
INDENT = "  "
#: The width the lines are wrapped to before the panel is laid out.
FIRST_WIDTH = 36
LEGENDS = ("▶ the lines this step ran", "▶ this step", "")
LIT = "code-panel--lit"
NUMBER = "code-panel--number"
TEXT = "code-panel--text"


def code_rows(code: Pseudocode, lit: frozenset[int], width: int) -> list[Parts]:
    """``code``'s lines as the panel's rows for ``width`` columns: the mark, the number and
    the indented words, wrapped under themselves; a lit line's pieces in the lit class."""
    digits = len(str(len(code.lines)))
    rows: list[Parts] = []
    for number, line in enumerate(code.lines, 1):
        on = number in lit
        head = f"{LIT_MARK if on else ' '} {number:>{digits}} "
        indent = INDENT * line.indent
        room = max(8, width - len(head) - len(indent))
        pieces = textwrap.wrap(line.text, room, subsequent_indent=INDENT,
                               break_on_hyphens=False) or [""]
        cls = LIT if on else TEXT
        rows.append([(head, LIT if on else NUMBER), (indent + pieces[0], cls)])
        rows.extend([(" " * len(head), cls), (indent + piece, cls)] for piece in pieces[1:])
    return rows


class CodePanel(LinePanel):
    """The pseudocode of a :class:`Run`'s search, the position's step lit.

    Call :meth:`show` after every change of run or position.
    """

    DEFAULT_CSS = """
    CodePanel {
        overflow-x: hidden;  /* the lines wrap to the panel's width */
        & > .code-panel--number { color: $text-muted; }
        & > .code-panel--text { color: $foreground; }
        & > .code-panel--lit {
            color: $text-accent; background: $accent 15%; text-style: bold;
        }
    }
    """

    COMPONENT_CLASSES: ClassVar[set[str]] = {LIT, NUMBER, TEXT}
    """
    | Class | Description |
    | :- | :- |
    | `code-panel--number` | A line's number. |
    | `code-panel--text` | A line's words. |
    | `code-panel--lit` | A line the step at the position executed (with its `▶`). |
    """

    def __init__(self, **widget_args: Any) -> None:  # name, id, classes, disabled
        super().__init__(**widget_args)
        self.code: Pseudocode | None = None
        self.lit: frozenset[int] = frozenset()
        self.focus_number: int | None = None  # the lit line kept in view (None: the first)
        self.named: list[int] = []  # the lit lines the narration names: kept in view first
        self._rows: list[Parts] = []
        self._key: tuple[object, ...] = ()

    def show(self, run: Run | BiRun) -> None:
        """Show ``run``'s code with its position's step lit, its most specific lit line in
        view (a bidirectional search's: :mod:`~tui_search.tui.view.two_way.code_lines`)."""
        code = code_of(run)
        if isinstance(run, Run):
            lit, focus, named = lit_lines(run), focus_line(run), named_lines(run)
        else:
            from tui_search.tui.view.two_way.code_lines import two_way_lines

            lit, focus, named = two_way_lines(run)
        if (code, lit, focus) == (self.code, self.lit, self.focus_number) and self._rows:
            return
        self.code, self.lit, self.focus_number = code, lit, focus
        self.named = named
        self.show_titles((f"Code · {code.title}", f"Code · {run.algo.short}", "Code"),
                         LEGENDS)
        self._lay_rows()

    def _width(self) -> int:
        return self.scrollable_content_region.width or FIRST_WIDTH

    def _lay_rows(self) -> None:
        code = self.code
        if code is None:
            return
        width = self._width()
        key = (code, self.lit, self.focus_number, width)
        if key == self._key:
            return
        self._key = key
        self._rows = code_rows(code, self.lit, width)
        set_virtual_size(self, Size(width, len(self._rows)))
        self._scroll_to_lit()
        self.refresh_changed()

    def lit_rows(self) -> list[int]:
        """The rows of the lit lines (their first rows)."""
        return [y for y, row in enumerate(self._rows) if row[0][0].startswith(LIT_MARK)]

    def line_rows(self, number: int) -> range:
        """The rows of line ``number`` (its first, and those it wrapped to)."""
        rows = self._rows
        starts = [y for y, row in enumerate(rows) if row[0][0].strip()]
        if not 1 <= number <= len(starts):
            return range(0)
        top = starts[number - 1]
        return range(top, starts[number] if number < len(starts) else len(rows))

    def _scroll_to_lit(self) -> None:
        """The lit lines in view, from the first, when they fit; else from the first down
        to the last the narration names (the push, the focus line), or as many lit lines
        above those as fit (from a line's first row); else the focus line from its top."""
        window = self.scrollable_content_region
        lit = self.lit_rows()
        if not window or not lit:
            return
        top, bottom = lit[0], lit[-1] + 1
        while bottom < len(self._rows) and not self._rows[bottom][0][0].strip():
            bottom += 1  # the last lit line's wrapped rows
        spans = [self.line_rows(n) for n in self.named]
        named = range(min(r.start for r in spans), max(r.stop for r in spans)) \
            if spans and all(spans) else range(0)
        if bottom - top > window.height and named:
            if named.stop - named.start <= window.height:  # the named lines, and above
                top = min(r.start for r in (self.line_rows(n) for n in self.lit)
                          if r and r.start >= named.stop - window.height)
                self.scroll_to(0, min(top, named.start), animate=False, immediate=True,
                               force=True)  # from a line's first row
                return
            else:  # not all at once: the focus line
                number = self.focus_number if self.focus_number is not None else self.named[0]
                focus = self.line_rows(number)
                top, bottom = focus.start, focus.stop
        self.scroll_to_region(Region(0, top, 1, min(bottom - top, window.height)),
                              animate=False, immediate=True, force=True)

    def line_parts(self, y: int) -> Parts:
        rows = self._rows
        return rows[y] if 0 <= y < len(rows) else []

    def on_resize(self) -> None:
        super().on_resize()
        self._lay_rows()


__all__ = ["CodePanel", "code_rows"]

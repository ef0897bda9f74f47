"""The frontier: BFS's FIFO queue, DFS's / iterative deepening's LIFO stack, or the priority
queue of uniform-cost, greedy best-first and A* search, one entry a line.

The panel is a line-API :class:`~textual.scroll_view.ScrollView`: it holds no copy of the
frontier, only the run and the position it was last shown.  ``render_line`` asks the run for the
one entry on that row (``run.now.frontier(i, i + 1)``), so drawing costs O(rows visible) whether the
frontier holds 3 entries or 100 000, and :meth:`FrontierPanel.show` costs O(1).

The first line counts the entries (``4 in the queue``: the border title says only what the
frontier is, since setting a title repaints the whole panel); then each line reads
``▶+ (2,1) NE`` -- a marker column (``▶`` the entry expanded next, ``+`` an entry
the step just taken added), the cell, and the move that reached it -- with ``d=3`` before the
move for iterative deepening, and the priority with what it adds up after the move for a
priority queue (``f 6.41  g 2.41  h 4.00``; an entry whose cell was pushed again with a lower g
is struck out as *stale*).  The first and last lines carry a hint (``← front (next out)`` /
``← back (newest)`` for a queue, ``← top (next out)`` / ``← bottom (oldest)`` for a stack) so a
student sees which end is which.

A narrow panel drops the hints (and "stale") before any figure, then presses the figures
closer together; an entry still wider than the panel takes more rows, its figures under its
cell (:mod:`~tui_search.tui.view.frontier_rows`: the move and the marker go first, never a
figure), and the lines above the entries wrap to the panel's width.

In the quiz the entries are the answers to pick from: a click on an entry's line, or ``up`` /
``down`` while the panel has the focus, posts :class:`FrontierPanel.EntryPicked` (a double
click asks to answer with it too); the app moves its cursor there and tells the panel which
cell to mark (:meth:`FrontierPanel.set_pick`), so the pick is always the app's cursor.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from rich.style import Style
from textual import events
from textual.binding import Binding, BindingType
from textual.geometry import Size
from textual.message import Message

from tui_search.engine.search.registry import Frontier
from tui_search.engine.search.state import State
from tui_search.engine.util.numbers import group_digits
from tui_search.tui.view.frontier_rows import (
    HINT_GAP,
    EntryRows,
    column_widths,
    entry_line,
    entry_row,
    entry_width,
    fit_entry,
)
from tui_search.tui.view.frontier_text import (
    DIR_W,
    describe_empty,
    discarded_line,
    end_hint,
    figures,
    legends,
    titles,
)
from tui_search.tui.view.pieces import Line, Parts, length, plain, wrap
from tui_search.tui.view.two_way.words import directed
from tui_search.tui.widgets.line_panel import LinePanel
from tui_search.tui.widgets.scrollbars import set_virtual_size

if TYPE_CHECKING:
    from tui_search.engine.run.recorded import Run


class FrontierPanel(LinePanel):
    """The frontier of a :class:`Run` at its position, next-to-expand first.

    Call :meth:`show` after every change of run or position.
    """

    DEFAULT_CSS = """
    FrontierPanel {
        & > .frontier-panel--entry { color: $foreground; }
        & > .frontier-panel--next {
            color: $text-accent; background: $accent 15%; text-style: bold;
        }
        & > .frontier-panel--added { color: $text-warning; }
        & > .frontier-panel--detail { color: $text-muted; }
        & > .frontier-panel--hint { color: $text-muted; text-style: italic; }
        & > .frontier-panel--empty { color: $text-muted; text-style: italic; }
        & > .frontier-panel--no-path { color: $text-error; text-style: bold; }
        & > .frontier-panel--discarded { color: $text-error; text-style: strike; }
        & > .frontier-panel--stale { color: $text-muted; text-style: strike; }
        & > .frontier-panel--picked { background: $primary 35%; }
    }
    """

    PICK = Binding.Group("Pick", compact=True)
    BINDINGS: ClassVar[list[BindingType]] = [
        # In the quiz, up / down pick an entry; else (check_action) they scroll, as the
        # ScrollView's bindings of the same keys (the next binding of a key that is disabled).
        Binding("up", "pick(-1)", "Pick", group=PICK, tooltip="Quiz: pick the entry above"),
        Binding("down", "pick(1)", "Pick", group=PICK, tooltip="Quiz: pick the entry below"),
        Binding("up", "scroll_up", "Scroll Up", show=False),
        Binding("down", "scroll_down", "Scroll Down", show=False),
    ]

    class EntryPicked(Message):  # not a dataclass: see GridView.CellClicked
        """The quiz: the student picked the entry of ``cell`` (``answer``: and answers with
        it, a double click; ``clicked``: with the mouse, not the keys)."""

        def __init__(self, panel: FrontierPanel, cell: State, answer: bool = False,
                     clicked: bool = False) -> None:
            super().__init__()
            self.panel, self.cell, self.answer, self.clicked = panel, cell, answer, clicked

        @property
        def control(self) -> FrontierPanel:
            return self.panel

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "frontier-panel--entry",
        "frontier-panel--next",
        "frontier-panel--added",
        "frontier-panel--detail",
        "frontier-panel--hint",
        "frontier-panel--empty",
        "frontier-panel--no-path",
        "frontier-panel--discarded",
        "frontier-panel--stale",
        "frontier-panel--picked",
    }
    """
    | Class | Description |
    | :- | :- |
    | `frontier-panel--entry` | An entry waiting on the frontier. |
    | `frontier-panel--next` | The entry that will be expanded next (the `▶` line). |
    | `frontier-panel--added` | The `+` marker of entries added by the step just taken. |
    | `frontier-panel--detail` | The count above the entries; iterative deepening's `d=`. |
    | `frontier-panel--hint` | The front/back or top/bottom hints. |
    | `frontier-panel--empty` | The line shown for an empty frontier. |
    | `frontier-panel--no-path` | The line shown when the search ended without a path. |
    | `frontier-panel--discarded` | The entry a discarded step threw away (visit on expand). |
    | `frontier-panel--stale` | A priority-queue entry whose cell was pushed again cheaper. |
    | `frontier-panel--picked` | The quiz: the entry at the cursor, the answer picked. |
    """

    def __init__(self, **widget_args: Any) -> None:  # name, id, classes, disabled
        super().__init__(**widget_args)
        self._run: Run | None = None
        self._shown: tuple[int, int, bool] | None = None  # (id(run), k, quiz) last shown
        self._count = 0  # frontier entries at the position
        self._added: range = range(0)
        self._kind = Frontier.FIFO
        self._iddfs = False
        self._coord_w = 5  # width of "(x,y)" for the largest cell of the map
        self._depth_w = 0  # width of "d=N" (iterative deepening only)
        self._cost_w = 0  # width of one cost figure (a priority queue only)
        self._hint_col = 0  # column where end hints start
        self._empty_text = ""
        self._count_text = ""  # the first line: "4 in the queue"
        self._short_count = False  # "11 entries" instead: the long one left no entry in sight
        self._discarded: Line | None = None  # after a discarded step: the entry it threw away
        self._hint_w = 0  # the widest end hint (or "stale")
        self._move_w = DIR_W  # the move's width (wider for START)
        self._squeeze = 0  # how close the figures are pressed in a narrow panel (costs_column)
        self._rows: EntryRows | None = None  # an entry too wide for one row: its rows
        self._top_key: object = None
        self._top_cache: list[Parts] = []
        self._by_cell: list[int] | None = None  # the quiz: the entries sorted by cell
        self._pick: State | None = None  # the quiz: the entry marked as picked (the cursor)
        self.border_title = "Frontier"

    # -- the contract with the app ----------------------------------------------------------
    @property
    def run(self) -> Run | None:
        return self._run

    #: The quiz lists at most this many entries (sorted by cell, each step).
    QUIZ_ENTRIES = 2000

    def show(self, run: Run, hide_order: bool = False, as_added: bool = False,
             direction: str = "", idle: bool = False) -> None:
        """Show ``run`` at its position: O(1), whatever the frontier's size.  ``hide_order``
        (the quiz) lists the entries by cell instead, without the next-out marks, so that the
        panel does not give the answer away; ``as_added`` (by hand) lists them in the order
        they were added, oldest first, without the marks: which to take is the student's
        lesson.  ``direction``: the half of a bidirectional search it is ("forward" or
        "backward", its title says so; "" for a one-way search); ``idle``: that half did not
        take the step, so nothing on it was just added.

        Keeps the count and the entry expanded next (the first two lines) in view when the run
        or the position changed; a repeated call at the same position leaves the scroll where
        the user put it.
        """
        hide_order = hide_order or as_added
        key = (id(run), run.k, hide_order)
        moved = key[:2] != (self._shown or (None, None))[:2]
        self._run, self._shown = run, key
        kind = self._kind = run.algo.frontier
        self._iddfs = run.algo.iterative and not run.algo.contours  # d=N: a depth limit's
        n = self._count = run.now.frontier_len()
        self._added = range(0) if idle else run.now.added_now()
        widths = column_widths(run)
        self._coord_w, self._depth_w, self._move_w, self._cost_w = widths
        self._hint_col = entry_width(run, widths) + HINT_GAP
        self._discarded = discarded_line(run, self._cost_w)
        self._by_cell = None
        if as_added:  # events are numbered in the order they were generated
            self._by_cell = sorted(run.now.frontier())[:self.QUIZ_ENTRIES]
        elif hide_order:
            events = run.now.frontier(0, self.QUIZ_ENTRIES)
            self._by_cell = sorted(events, key=lambda g: run.nodes.cell(g)[::-1])
        weighted = run.algo.priority == "g+h" and run.semantics.weight != 1.0
        self.show_titles(directed(titles(run.algo, hide_order, as_added,
                                         run.semantics.priority_words(run.algo) if weighted
                                         else ""), direction),
                         legends(kind, hide_order, as_added) if n else ())
        if n:
            self._empty_text = ""
            self._count_text = kind.count_text(group_digits(n))
            self._hint_w = max(len(end_hint(kind, 0, n)), len(end_hint(kind, n - 1, n)),
                               len("stale") if self._cost_w else 0)
        else:
            self._empty_text = describe_empty(run)
        self._fit(moved)

    def on_resize(self) -> None:
        if self._run is not None:
            self._fit(False)

    def _fit(self, moved: bool) -> None:
        """Size what the panel scrolls over to its lines at the panel's width (the hints
        shown only where they fit, the first lines wrapped), and repaint what changed."""
        n = self._count
        top = self._top_rows()
        width = max((length(row) for row in top), default=0)
        if n:
            count = len(figures(self._run, 0, self._cost_w)) if self._cost_w and self._run else 0
            self._squeeze, entry_w, self._rows = fit_entry(
                self.scrollable_content_region.width, self._hint_col - HINT_GAP, count,
                (self._coord_w, self._depth_w, self._move_w, self._cost_w))
            # too short a panel for the count's rows and an entry: the count's words go first
            region = self.scrollable_content_region
            lines, long = region.height, len(self._top_rows(False))
            wraps = len(wrap(plain([(self._count_text, "")], prose=True), region.width or 1000))
            short = wraps > 1 and bool(lines) and long + self._rows_per() > lines
            if short != self._short_count:
                self._short_count = short
                top = self._top_rows()
                width = max((length(row) for row in top), default=0)
            if self._rows is not None:
                width = max(width, self._rows.width)
            else:
                width = max(width,
                            self._hint_col + self._hint_w if self._hints_fit() else entry_w)
            more = self._by_cell is not None and n > len(self._by_cell)  # "… N more"
            listed = len(self._by_cell) if more and self._by_cell is not None else n
            height = len(top) + listed * self._rows_per() + more
        else:
            height = len(top)
        set_virtual_size(self, Size(width, height))
        if moved:
            self.scroll_to(0, 0, animate=False, immediate=True, force=True)
        self.refresh_changed()

    def rows_in_sight(self) -> int:
        """The rows that show the entries the step just added (and the count above them):
        a stack's are on top, a queue's (and a trace's, as added) at the back, a priority
        queue's anywhere: all of its rows."""
        if self._kind is Frontier.LIFO and self._by_cell is None:
            return self._top() + max(1, len(self._added)) * self._rows_per()
        return self.virtual_size.height

    def _rows_per(self) -> int:
        """The rows each entry takes (more than one in a panel too narrow for it)."""
        return 1 if self._rows is None else len(self._rows.rows)

    def _hints_fit(self) -> bool:
        """The end hints (and "stale") are shown only when they fit beside the entries:
        they go before any figure does."""
        room = self.scrollable_content_region.width
        return not room or self._hint_col + self._hint_w <= room

    def _top_rows(self, short: bool | None = None) -> list[Parts]:
        """The lines above the entries, wrapped to the panel's width: the count (or what an
        empty frontier means), then the entry a discarded step threw away.  ``short``: the
        count as "11 entries" (None: as the panel shows it)."""
        room = self.scrollable_content_region.width or 1000
        short = self._short_count if short is None else short
        key = (self._count_text, self._empty_text, self._discarded, room, short)
        if self._top_key != key:
            if self._count:
                n = group_digits(self._count)
                text = f"{n} {'entry' if self._count == 1 else 'entries'}" if short else (
                    self._count_text)
                rows = wrap(plain([(text, "frontier-panel--detail")], prose=True), room)
            else:
                cls = "frontier-panel--no-path" if "no path" in self._empty_text else (
                    "frontier-panel--empty")
                rows = wrap(plain([(self._empty_text, cls)], prose=True), room)
            if self._discarded is not None:
                rows += wrap(self._discarded, room)
            self._top_key, self._top_cache = key, rows
        return self._top_cache

    def set_pick(self, cell: State | None) -> None:
        """Mark the entry of ``cell`` as the quiz's pick (None: none), in view when listed."""
        if cell == self._pick:
            return
        self._pick = cell
        self.refresh()
        y = self.pick_line()
        if y is not None:
            top, height = round(self.scroll_y), self.scrollable_content_region.height
            if not top <= y < top + height:
                self.scroll_to(y=y if y < top else y - height + 1, animate=False,
                               immediate=True)

    def pick_line(self) -> int | None:
        """The line of the picked entry, or None when it is not listed."""
        index = self._pick_index()
        return None if index is None else self._top() + index * self._rows_per()

    def _pick_index(self) -> int | None:
        run, cells = self._run, self._by_cell
        if run is None or cells is None or self._pick is None:
            return None
        return next((i for i, g in enumerate(cells) if run.nodes.cell(g) == self._pick), None)

    def entry_cell(self, y: int) -> State | None:
        """The quiz: the cell of the entry on line ``y`` of the list, None for other lines."""
        run, cells = self._run, self._by_cell
        i = (y - self._top()) // self._rows_per() if y >= self._top() else -1
        if run is None or cells is None or not self._count or not 0 <= i < len(cells):
            return None
        return run.nodes.cell(cells[i])

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action == "pick":
            return bool(self._by_cell) and bool(self._count)
        return True

    def action_pick(self, delta: int) -> None:
        """The entry ``delta`` lines from the pick (the first when none is picked)."""
        cells = self._by_cell
        if not cells or self._run is None:
            return
        index = self._pick_index()
        index = 0 if index is None else max(0, min(len(cells) - 1, index + delta))
        self.post_message(self.EntryPicked(self, self._run.nodes.cell(cells[index])))

    def on_click(self, event: events.Click) -> None:
        offset = event.get_content_offset(self)
        if offset is None:
            return
        cell = self.entry_cell(offset.y + round(self.scroll_y))
        if cell is not None:
            self.post_message(self.EntryPicked(self, cell, answer=event.chain >= 2,
                                               clicked=True))

    def _top(self) -> int:
        """Lines above the entries: the count, and the entry a discarded step threw away."""
        return len(self._top_rows())

    # -- text, for tests and for render_line ------------------------------------------------
    def line_parts(self, y: int) -> list[tuple[str, str]]:
        """Line ``y`` as (text, component class) pieces: the count, the entry a discarded step
        threw away (if it did), then the entries;
        ``[]`` past the end."""
        run = self._run
        if run is None:
            return []
        n = self._count
        top = self._top_rows()
        if y < len(top):
            return top[y]
        if not n:
            return []
        y, row = divmod(y - self._top(), self._rows_per())
        if not 0 <= y < n:
            return []
        if self._by_cell is not None:  # the quiz: by cell, no next-out mark
            if y >= len(self._by_cell):
                if row:
                    return []
                return [(f"   … {n - len(self._by_cell):,} more", "frontier-panel--detail")]
            g = self._by_cell[y]
        else:
            (g,) = run.now.frontier(y, y + 1)
        first = y == 0 and self._by_cell is None and self._kind.next_known
        marks = (first, g in self._added)
        widths = (self._coord_w, self._depth_w, self._cost_w)
        if self._rows is not None:
            return entry_row(run, g, self._rows, row, marks, widths)
        hint = (self._hint_col, end_hint(self._kind, y, n) if self._by_cell is None else ""
                ) if self._hints_fit() else None
        parts = entry_line(run, g, marks, widths, self._squeeze, self._iddfs, hint)
        room, squeeze = self.scrollable_content_region.width, self._squeeze
        while room and squeeze < 2 and self._cost_w and length(parts) > room:
            # a figure longer than the map's diagonal (f 10.07 beside 7.07): this entry's
            # figures pressed closer, so that no number is cut
            squeeze += 1
            parts = entry_line(run, g, marks, widths, squeeze, self._iddfs, None)
        return parts

    def line_band(self, y: int) -> Style | None:
        """The entry expanded next is highlighted across the whole line (all its rows), like
        a cursor."""
        top = self._top()
        if top <= y < top + self._rows_per() and self._count and self._by_cell is None:
            return Style(bgcolor=self.cached_style("frontier-panel--next").bgcolor)
        if self._pick is not None and self.entry_cell(y) == self._pick:
            return Style(bgcolor=self.cached_style("frontier-panel--picked").bgcolor)
        return None

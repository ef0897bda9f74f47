"""The screen of panes: a pane a search, the status lines, the key bar, the legend, the readout,
the comparison table and the challenge, and how the session is pushed down to them
(:class:`~tui_search.tui.screens.main.MainScreen` adds the keys).  One search is one pane:
nothing here asks whether it is comparing.

Its parts: ``playback`` times playback and seeks
(:class:`~tui_search.tui.screens.playback_driver.PlaybackDriver`); the challenge panel's
verdict is checked by :mod:`~tui_search.tui.screens.exercise_check` once an exercise is shown.
"""

from __future__ import annotations

import time
from functools import cached_property
from typing import TYPE_CHECKING, cast

from textual import events
from textual.app import ComposeResult
from textual.await_remove import AwaitRemove
from textual.markup import escape
from textual.screen import Screen
from textual.widget import AwaitMount, Widget
from textual.widgets import Static

from tui_search.engine.maps.grid import Grid
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State
from tui_search.engine.util.filenames import describe_name
from tui_search.tui.model import playback
from tui_search.tui.model.boards import holds
from tui_search.tui.model.file_rules import FileAccess
from tui_search.tui.model.session import NEEDS_ENDPOINTS, Before, Session
from tui_search.tui.screens.keys import KEY_IMPORTANCE
from tui_search.tui.screens.playback_driver import PlaybackDriver
from tui_search.tui.view.layout import (
    GUTTER,
    PANE_STATS_HEIGHT,
    arrange,
    board_size,
    lesson_width,
)
from tui_search.tui.view.readout import describe_each
from tui_search.tui.view.status_lines import screen_rows, screen_status
from tui_search.tui.widgets.cell_readout import CellReadout
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar
from tui_search.tui.widgets.lazy_parts import Later, challenge_panel, compare_table, show_part
from tui_search.tui.widgets.legend import Legend
from tui_search.tui.widgets.pane_box import PaneBox
from tui_search.tui.widgets.run_pane import RunPane, own_rows
from tui_search.tui.widgets.stats import Stats

if TYPE_CHECKING:
    from textual.notifications import SeverityLevel

    from tui_search.tui.screens.file_commands import FileCommands
    from tui_search.tui.widgets.challenge import ChallengePanel
    from tui_search.tui.widgets.compare_table import CompareTable
    from tui_search.tui.widgets.graph_view import GraphView
    from tui_search.tui.widgets.lesson_panel import LessonPanel

MIN_WIDTH, MIN_HEIGHT = 60, 20
#: What ``v`` says when no pane has room for the Code panel (no lists under a map this big),
#: and a refit says when the panels it showed fold (the status lines took their rows).
NO_ROOM_FOR_CODE = ("No room for the Code panel here: a taller terminal, or fewer panes, "
                    "shows it (v hides it)")
#: The challenge panel's lines before it is first laid out (its border and a few of text).
CHALLENGE_LINES = 8


class PanesScreen(Screen[None]):
    """The session's panes and everything around them."""

    AUTO_FOCUS = "GridView, GraphView"
    #: How much each key's hint matters in the key bar (the by-hand screen has its own).
    IMPORTANCE = KEY_IMPORTANCE

    def __init__(self, session: Session, file_access: FileAccess) -> None:
        super().__init__()
        self.session = session
        self.file_access = file_access
        self.panes = self._new_panes()
        self.playback = PlaybackDriver(self)  # the timer and the seeks' slices
        # what a mouse drag paints: True wall, False free, "brush" the terrain brush's cost
        self._stroke: bool | str | None = None
        self._bindings_key: tuple[object, ...] = ()
        self._terrain = self._has_terrain()  # what the legend was drawn for
        self._fitted_lines = (-1, -1, -1)  # the status lines' heights last fitted to
        self._code_shown = False  # some pane showed the Code panel when last fitted
        self._last_note: tuple[str, float] | None = None  # the last note's kind, its end
        #: A by-hand exercise's last run: solved, and its verdict (None: no run yet).
        self.hand_result: tuple[bool, str] | None = None

    @cached_property
    def files(self) -> FileCommands:
        """Saving, opening, generating and quitting, made when first used: the first frame
        imports none of it (benchmarks/README.md, "startup")."""
        from tui_search.tui.screens.file_commands import FileCommands

        return FileCommands(self)

    # -- layout ----------------------------------------------------------------------------
    def compose(self) -> ComposeResult:
        yield KeyBar(self.IMPORTANCE, id="keys")
        self.stats = Stats(id="stats")
        yield self.stats
        # the comparison table, the challenge and the too-small note: mounted when first
        # shown (show_part); until then neither composed nor styled (the first two not made)
        self._table: Later[CompareTable] = Later(compare_table)
        self._challenge: Later[ChallengePanel] = Later(challenge_panel)
        self.small_note = Static(id="too-small")
        self.readout = CellReadout(id="readout")
        yield self.readout
        self.legend = Legend(self.panes[0].view, id="legend")
        self.legend.two_way = any(not isinstance(run, Run) for run in self.session.runs)
        yield self.legend
        if self.session.lesson is not None:
            from tui_search.tui.widgets.lesson_panel import LessonPanel  # only for a lesson

            yield LessonPanel(classes="lesson")
        yield from self.over_panes()
        self.pane_box = PaneBox(*self.panes, id="panes")
        yield self.pane_box

    def over_panes(self) -> list[Widget]:
        """What a screen of panes shows over them besides the challenge (by hand: its
        panel)."""
        return []

    def _show_part(self, part: Widget, shown: bool) -> None:
        """Mount the table, the challenge or the too-small note the first time it shows."""
        show_part(self, part, shown, [self.stats, self._table.made, self._challenge.made,
                                      self.readout, self.legend, self.pane_box, self.small_note])

    @property
    def table(self) -> CompareTable:
        return self._table.get()

    @property
    def challenge(self) -> ChallengePanel:
        return self._challenge.get()

    def _new_panes(self, labels: list[str] | None = None) -> list[RunPane]:
        """A pane for each of ``labels`` (default: every search shown)."""
        session = self.session
        return [RunPane(session.board, label, NEEDS_ENDPOINTS)
                for label in (session.labels if labels is None else labels)]

    @property
    def views(self) -> list[GridView | GraphView]:
        return [pane.view for pane in self.panes]

    @property
    def grid_views(self) -> list[GridView]:
        """The views of a grid's cells (none when a graph is shown)."""
        return [view for view in self.views if isinstance(view, GridView)]

    def _has_terrain(self) -> bool:
        board = self.session.board
        return isinstance(board, Grid) and board.costs is not None

    def on_mount(self) -> None:
        self.playback.start()
        self._check_size(self.size.width, self.size.height)
        for view in self.views:
            view.set_cursor(self.session.cursor)
        self._check_exercise()
        self.show_lesson()
        # reckoned: the first frame is laid out already.  The classes it sets are not restyled
        # here: the ScreenResume that follows the mount restyles the whole screen before the
        # first frame (restyling the pane here as well cost the start: benchmarks/README.md,
        # "startup")
        self.fit_panes(restyle=False)
        self.present()
        self.call_after_refresh(self.fit_panes)  # measured

    def on_resize(self, event: events.Resize) -> None:
        self._check_size(event.size.width, event.size.height)
        self.call_after_refresh(self.fit_panes)

    def on_stats_height_changed(self, message: Stats.HeightChanged) -> None:
        """A status line took a row more or less (its text wrapped anew, or a pane's lines
        were shown or mounted): fit the panes to the room that leaves."""
        self.call_after_refresh(self._refit)

    def on_pane_box_resized(self, message: PaneBox.Resized) -> None:
        """The lines around the panes took a row or gave one back (a second search's readout
        line, the counts said under the panes): fit the panes to the room that leaves."""
        self.call_after_refresh(self._refit)

    def _lines_measured(self) -> tuple[int, int, int]:
        """What the layout reads of the status lines: the panes' own lines' height (0: not
        laid out yet, reckoned), the rows the lines under the panes wrapped to, and the
        panes' room they leave."""
        return (max(pane.stats.outer_size.height for pane in self.panes), self.stats.wrapped,
                self.pane_box.size.height)

    def _refit(self) -> None:
        """Fit the panes again if the status lines' heights are not those they were last
        fitted to (a pane's lines first laid out: their rows were reckoned)."""
        if self._lines_measured() != self._fitted_lines:
            self.fit_panes()

    def fit_panes(self, restyle: bool = True) -> None:
        """Fit the panes to the room the other lines leave (:func:`layout.arrange`).  Before
        the first layout that room is reckoned from the screen's size, so the first frame is
        laid out as the next ones.  ``restyle=False``: the classes set are not restyled now
        (the screen is restyled whole next)."""
        table, box = self._table.made, self.pane_box
        measured = table.outer_size.height if table and table.display else 0
        table_height = max(measured, len(self.panes) + 5)  # a line a search, its head, two
        # more and its border; more when its sentence wraps (the layout says if it shows)
        # the lines under the panes where the panes have lines of their own, and where not:
        # the layout fits each choice to its own lines
        lines_width = self.stats.content_size.width or self.size.width - 2  # its padding
        (rows, least), (folded_rows, folded_least) = (
            screen_rows(self.session, self.size.width, lines_width, own) for own in (True, False))
        wrapped = rows - least
        if box.size.area:  # the room the lines under the panes leave where the panes have lines
            width, height = box.size.width, box.size.height + measured + (
                self.stats.outer_size.height - rows)
        else:  # the key bar, the status lines, the readout, the legend, the challenge
            wrapped = 0  # reckoned at a row a line
            width = self.size.width
            if self.session.lesson is not None:
                width -= lesson_width(width)
            legend = self.legend.get_content_height(self.size, self.size, max(1, width - 2))
            challenge = CHALLENGE_LINES if (self.session.exercise is not None
                                            or self.session.by_hand is not None) else 0
            height = self.size.height - 4 - legend - challenge
        self._fitted_lines = self._lines_measured()
        stats = self._fitted_lines[0] or PANE_STATS_HEIGHT
        arrangement = arrange(len(self.panes), width, height, board_size(self.session.board),
                              table_height=table_height,
                              fold_trees=self.session.fold_trees and not self.session.show_code,
                              stats_height=stats,
                              wrapped=wrapped, code=self.session.show_code,
                              folded=(folded_rows - rows, folded_rows - folded_least),
                              stats_rows=lambda w: own_rows(self.panes, w) or stats)
        box.styles.grid_size_columns = arrangement.columns
        box.styles.grid_size_rows = arrangement.rows
        if arrangement.table and (table is None or not table.display):
            # not kept up while hidden, nor filled before it first shows (a resize that makes
            # room for it showed an empty box, its rows' room a gap, until the next step)
            self.table.show(self.session.labels, self.session.runs)
        if arrangement.table or table is not None:
            self.table.display = arrangement.table
            self._show_part(self.table, arrangement.table)
        panes_lines = self.panes[0].stats.display
        # each pane's own lines take as many rows as the tallest's in the narrowest pane: the
        # maps start on one row (one whose lines wrapped more had its map a row lower)
        level = (width - GUTTER * (arrangement.columns - 1)) // arrangement.columns
        peers = [pane.stats for pane in self.panes]
        for pane in self.panes:
            pane.stats.peers = peers
            pane.lay_out(arrangement, code=self.session.show_code, restyle=restyle,
                         level_width=level)
        shown = any(p.code_shown for p in self.panes)
        if self._code_shown and not shown and self.session.show_code:
            self.warn(NO_ROOM_FOR_CODE, timeout=6)  # never folded without a word
        self._code_shown = shown
        if arrangement.pane_stats != panes_lines and self.is_mounted:
            self.present()  # the lines under the panes say the counts the panes' lines did

    def _check_size(self, width: int, height: int) -> None:
        for lesson in self.query(".lesson"):
            lesson.styles.width = lesson_width(width)
        small = width < MIN_WIDTH or height < MIN_HEIGHT
        if small != self.too_small:
            self.set_class(small, "-too-small")
            self.refresh_bindings()  # behind the message only q acts
        self._show_part(self.small_note, small)
        self.small_note.update(
            f"Terminal too small: need at least {MIN_WIDTH}×{MIN_HEIGHT}, have {width}×{height}")

    @property
    def too_small(self) -> bool:
        """True while the terminal is too small and the screen shows only a message."""
        return self.has_class("-too-small")

    # -- showing the session ---------------------------------------------------------------
    def new_runs_shown(self) -> None:
        """The session made new runs: as many panes as searches (the first ones kept, named
        anew), then show."""
        session = self.session
        labels = session.labels
        for pane, label in zip(self.panes, labels, strict=False):
            pane.label = label
        if len(self.panes) != len(labels):
            state = self.views[0].view_state()
            kept, gone = self.panes[:len(labels)], self.panes[len(labels):]
            added = self._new_panes(labels[len(kept):])
            self.panes = kept + added
            removing = [pane.remove() for pane in gone]
            mounting = self.pane_box.mount_all(added) if added else None
            for pane in added:
                pane.view.set_cursor(session.cursor)
                pane.view.set_view_state(state)  # zoom, labels, overview: as the others
            self.call_later(self._panes_changed, removing, mounting)
        self._check_exercise()
        terrain = self._has_terrain()
        two_way = any(not isinstance(run, Run) for run in session.runs)
        if (terrain, two_way) != (self._terrain, self.legend.two_way):
            # the legend shows the ramp, or no longer; a bidirectional search's kinds, or not
            self._terrain, self.legend.two_way = terrain, two_way
            self.legend.refresh(layout=True)
            self.fit_panes()
        self.present()

    async def _panes_changed(self, removing: list[AwaitRemove],
                             mounting: AwaitMount | None) -> None:
        """Once the panes are there: focus the first map, fit the panes, show every run."""
        for removed in removing:
            await removed
        if mounting is not None:
            await mounting
        if self.app.screen is self:
            self.views[0].focus()
        self.fit_panes()
        self.present()

    def _replace_panes(self) -> None:
        """New panes of the board's kind (a grid's views, or a graph's)."""
        gone, self.panes = self.panes, self._new_panes()
        removing = [pane.remove() for pane in gone]
        mounting = self.pane_box.mount_all(self.panes)
        self.legend.view = self.panes[0].view
        self.call_later(self._panes_changed, removing, mounting)

    def show_lesson(self) -> None:
        """The lesson's section shown (``--lesson``), and its keys."""
        play = self.session.lesson
        for panel in self.query(".lesson"):
            assert play is not None
            cast("LessonPanel", panel).show(play.where, play.section.text)
        self.refresh_bindings()

    def show_map(self) -> None:
        """The map was replaced or saved: every view on it, then show."""
        board = self.session.board
        if any(isinstance(view, GridView) != isinstance(board, Grid) for view in self.views):
            self._replace_panes()  # a grid after a graph, or a graph after a grid
        for view in self.views:
            if isinstance(view, GridView):
                if isinstance(board, Grid) and view.grid is not board:
                    view.set_grid(board)
            elif not isinstance(board, Grid) and view.graph is not board:
                view.set_graph(board)
            view.set_cursor(self.session.cursor)
        self.new_runs_shown()
        self.fit_panes()

    def present(self, changed: list[State] | None = None, follow: bool = True,
                per_run: list[list[State] | None] | None = None) -> None:
        """Push the runs at their positions to every widget; ``changed`` limits the map
        repaint (``per_run``: a list of changed cells for each run)."""
        session = self.session
        runs = session.runs
        marks = session.jumps.marks()
        by_hand = session.by_hand
        highlight = tuple(by_hand.highlight()) if by_hand is not None else ()
        for i, pane in enumerate(self.panes):
            if pane.is_mounted:  # else shown whole once mounted (_panes_changed)
                pane.show(runs[i] if runs else None,
                          per_run[i] if per_run is not None else changed, follow=follow,
                          hide_order=session.quiz.on and i == 0,
                          as_added=by_hand is not None,
                          title=escape(describe_name(session.title)),  # a file's name: not markup
                          mark=marks[i] if i < len(marks) else None, marks=highlight)
        if (table := self._table.made) is not None and table.display:
            table.show(session.labels, runs)
        self.show_pick()
        self.show_status()
        self.show_readout()

    def show_status(self) -> None:
        """The status lines (:func:`~tui_search.tui.view.status_lines.screen_status`) and the key
        bar: all a seek's progress changes."""
        session = self.session
        status = screen_status(session, self.size.width,
                               panes_lines=self.panes[0].stats.display)
        self.stats.show(status.lines, status.max_rows)
        runs = session.runs
        key = (not runs, session.at_start(), session.at_end(), session.speed_index,
               session.playing, session.seeking, len(self.panes),
               session.edits.history.can_undo(), session.edits.history.can_redo())
        if key != self._bindings_key:  # what greys out or hides keys changed
            self._bindings_key = key
            self.refresh_bindings()

    def show_readout(self) -> None:
        """What the runs know of the cell under the mouse, else of the cursor's."""
        session = self.session
        hover = next((v.hover for v in self.views if v.hover is not None), None)
        cell: State
        cell, label = (hover, "Mouse") if hover is not None else (session.cursor, "Cursor")
        if not holds(session.board, cell):
            cell, label = session.cursor, "Cursor"
        self.readout.show(label, describe_each(session.runs, session.names, session.board, cell))

    @property
    def quiz_panel(self) -> FrontierPanel:
        """The frontier the quiz asks about: the first pane's."""
        return self.panes[0].frontier

    def show_pick(self) -> None:
        """Mark the cursor's entry in the quiz's frontier panel (none outside the quiz)."""
        self.quiz_panel.set_pick(self.session.cursor if self.session.quiz.on else None)

    def moved(self, before: Before | None) -> None:
        """Show the runs after a move from ``before``: only the cells a one-step move
        changed."""
        if before is not None:
            runs = zip(self.session.runs, before, strict=True)
            self.present(per_run=[playback.step_changes(run, k, was_at_end)
                                  for run, (k, was_at_end) in runs])

    def warn(self, text: str | None, timeout: float = 3) -> None:
        """A warning; the same one again (a key pressed again) replaces it."""
        self.note(text, text or "", severity="warning", timeout=timeout)

    def note(self, text: str | None, kind: str, *, severity: SeverityLevel = "information",
             timeout: float = 3) -> None:
        """Notify ``text``, replacing a note of the same ``kind`` still on screen (``b`` four
        times, a refusal said again), not stacked over the map.  Textual clears notifications
        only all at once: only while the last one shown is this kind's."""
        if not text:
            return
        now = time.monotonic()
        if self._last_note is not None and self._last_note[0] == kind \
                and now < self._last_note[1]:
            self.app.clear_notifications()
        self._last_note = (kind, now + timeout)
        self.notify(text, severity=severity, timeout=timeout)

    # -- the exercise ----------------------------------------------------------------------
    def _check_exercise(self) -> None:
        """The challenge panel shown while an exercise is, with its verdict on the map as it is
        now (:func:`~tui_search.tui.screens.exercise_check.check_exercise`)."""
        exercise = self.session.exercise  # (a grid's on a grid, a graph's on a graph)
        shown = exercise is not None and (exercise.graph is None) == (self.session.graph is None)
        if self.has_class("-challenge") != shown:
            self.set_class(shown, "-challenge")
            self._show_part(self.challenge, shown)
            self.call_after_refresh(self.fit_panes)
        if shown:
            from tui_search.tui.screens.exercise_check import check_exercise  # once one is shown

            check_exercise(self, self.session, self.challenge)

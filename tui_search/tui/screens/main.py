"""The main screen's keys and the widgets' messages: each a call on the session, then the
screen shows what changed (:class:`~tui_search.tui.screens.panes.PanesScreen`)."""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar, cast

from textual.binding import BindingType

from tui_search.engine.search.state import State, as_cell
from tui_search.tui.model import playback
from tui_search.tui.model.boards import goal_of
from tui_search.tui.model.map_edits import brush_name
from tui_search.tui.model.searches import current_node
from tui_search.tui.screens.keys import KEYS
from tui_search.tui.screens.panes import NO_ROOM_FOR_CODE, PanesScreen
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView
from tui_search.tui.widgets.key_bar import KeyBar

if TYPE_CHECKING:  # the settings' module is imported when the dialog first opens
    from tui_search.tui.dialogs.settings_choice import SettingsChoice
    from tui_search.tui.widgets.graph_view import GraphView
    from tui_search.tui.widgets.lesson_panel import LessonPanel


class MainScreen(PanesScreen):
    """The panes, and every key of :mod:`~tui_search.tui.screens.keys`."""

    BINDINGS: ClassVar[list[BindingType]] = KEYS

    # -- moving through the runs -----------------------------------------------------------
    def action_next(self) -> None:
        self.playback.pause()
        self.moved(self.session.step(forward=True))

    def action_prev(self) -> None:
        self.playback.pause()
        self.moved(self.session.step(forward=False))

    def action_first(self) -> None:
        if self.session.runs:
            self.playback.seek(to_end=False)

    def action_last(self) -> None:
        """Go to the end: record each search, then move there, in slices with the event loop
        answering keys in between (esc, or any key that moves the position, stops it)."""
        if self.session.runs and not self.session.at_end():
            self.playback.seek(to_end=True)

    def action_stop_seek(self) -> None:
        """esc while computing the end: stop where the runs are (what was recorded is kept)."""
        if self.session.seeking:
            self.playback.stop()
            self.present(changed=[])

    def action_difference(self) -> None:
        """A replay: to the step where the trace first parts from its search, and back."""
        self.playback.pause()
        self.session.jumps.to_difference()
        self.present()

    def action_reset(self) -> None:
        self.session.new_runs()
        self.new_runs_shown()

    def action_play(self) -> None:
        """Play (at the last step: again from step 0); pause when playing."""
        if self.session.playing:
            self.action_pause()
        elif self.session.runs:
            self.playback.play()

    def action_pause(self) -> None:
        if self.session.playing:
            self.playback.stop()
            self.present()

    def action_faster(self) -> None:
        self.playback.set_speed(self.session.speed_index + 1)
        self.present(changed=[])

    def action_slower(self) -> None:
        self.playback.set_speed(self.session.speed_index - 1)
        self.present(changed=[])

    # -- the searches shown ----------------------------------------------------------------
    def action_algorithm(self, algorithm: str) -> None:
        """One pane: run ``algorithm``.  Several: add it to them, or take it out."""
        self.playback.pause()
        self.warn(self.session.choose_algorithm(algorithm), timeout=4)
        self.new_runs_shown()

    def action_compare(self) -> None:
        """Several panes (the searches last compared) or one again."""
        self.playback.pause()
        self.warn(self.session.toggle_compare(), timeout=5)
        self.new_runs_shown()

    def action_show_compare(self, spec: str) -> None:
        """Compare the searches of ``spec`` (the palette's comparisons)."""
        self.playback.pause()
        self.warn(self.session.show_searches(spec), timeout=5)
        self.new_runs_shown()

    def action_fold_trees(self) -> None:
        self.session.fold_trees = not self.session.fold_trees
        self.fit_panes()

    def action_code(self) -> None:
        """The Code panel (the search's pseudocode, the step's lines lit) in the search
        trees' place, or the trees again."""
        self.session.show_code = not self.session.show_code
        self.fit_panes()
        self.present(changed=[])
        if self.session.show_code and not any(p.code_shown for p in self.panes):
            self.warn(NO_ROOM_FOR_CODE, timeout=6)

    def action_lesson(self, by: int) -> None:
        """The lesson's next (1) or previous (-1) section: its text, and the session in the
        state it sets."""
        play = self.session.lesson
        if play is not None and play.move(self.session, by):
            self.playback.pause()
            self.show_map()
            self.show_lesson()

    def action_lesson_scroll(self, by: int) -> None:
        """Scroll the lesson's text half a panel down (1) or up (-1)."""
        for panel in self.query(".lesson"):
            cast("LessonPanel", panel).scroll_by_half(by)

    def action_settings(self) -> None:
        from tui_search.engine.search.registry import get_algorithm
        from tui_search.tui.dialogs.settings import SettingsScreen  # only when asked

        self.playback.stop()
        session = self.session
        shown = [get_algorithm(c.algorithm) for c in session.contenders]
        self.app.push_screen(SettingsScreen(session.semantics, shown[0], session.comparison,
                                            shown, graph=session.graph), self._settings_chosen)

    def _settings_chosen(self, chosen: SettingsChoice | None) -> None:
        if chosen is not None:
            before = (self.session.semantics, self.session.spec, self.session.runs)
            self.session.choose_settings(chosen.semantics, chosen.comparison)
            if (self.session.semantics, self.session.spec, self.session.runs) != before:
                self.new_runs_shown()

    # -- the exercise and the quiz ---------------------------------------------------------
    def action_exercise(self) -> None:
        """Cycle the challenge: the exercise file given at start, exercise 1, 2, none."""
        self._exercise_shown(self.session.cycle_exercise())

    def action_show_exercise(self, exercise: int) -> None:
        """Show exercise 1 or 2 as a live challenge on the map (0: none)."""
        self._exercise_shown(self.session.show_exercise(exercise or None))

    def _exercise_shown(self, rules: str) -> None:
        """The challenge checked; the panes' searches anew under the exercise's rules when
        they changed (``rules``: the note saying so)."""
        exercise = self.session.exercise
        if exercise is not None and (self.session.graph is None) != (exercise.graph is None):
            self.session.show_exercise(None)  # a grid's exercise on a graph, or the reverse
            kind = "grids" if exercise.graph is None else "graphs"
            self.warn(f"This exercise is on {kind}: open one for it")
            return
        if rules:
            self.playback.pause()
            self.session.new_runs(rules)
            self.new_runs_shown()
        else:
            self._check_exercise()

    def action_by_hand(self) -> None:
        """H: make the search's steps yourself, each checked at once (a screen of its own,
        :mod:`~tui_search.tui.screens.by_hand`)."""
        from tui_search.tui.screens.by_hand import open_by_hand  # only when asked

        self.playback.stop()
        open_by_hand(self)

    def action_quiz(self) -> None:
        self.session.toggle_quiz()
        self.present(changed=[])
        self.refresh_bindings()  # the frontier panel's pick keys come or go
        self.query_one(KeyBar).raise_hint("quiz", self.session.quiz.on)  # its key ends it

    def action_answer(self) -> None:
        """Take the step and mark the guess: the cell under the cursor."""
        self.playback.pause()
        before = self.session.answer()
        if before is None:
            self.present(changed=[])
        self.moved(before)

    def on_frontier_panel_entry_picked(self, message: FrontierPanel.EntryPicked) -> None:
        """A pick in the quiz's panel moves the cursor there; a double click also answers."""
        if not self.session.quiz.on or message.panel is not self.quiz_panel:
            return
        self.move_cursor(message.cell)
        if message.answer:
            self.action_answer()

    # -- the map ---------------------------------------------------------------------------
    def move_cursor(self, cell: State) -> None:
        if self.session.move_cursor(cell):
            for view in self.views:  # one cursor, on every pane's map
                view.set_cursor(cell)
            self.show_pick()
            self.show_readout()

    def action_move(self, dx: int, dy: int) -> None:
        """The cursor a cell that way; on a graph, to the nearest node that way."""
        view = self.views[0]
        if isinstance(view, GridView):
            x, y = as_cell(self.session.cursor)
            self.move_cursor((x + dx, y + dy))
        else:
            view.action_toward({(0, -1): "up", (0, 1): "down", (-1, 0): "left",
                                (1, 0): "right"}[(dx, dy)])

    def on_graph_view_cursor_moved(self, message: GraphView.CursorMoved) -> None:
        """A graph's cursor moved (arrows, Tab, the mouse): the session's and every pane's."""
        graph = self.session.graph
        if graph is not None and 0 <= message.node < len(graph):
            node = graph.names[message.node]
            if node != self.session.cursor:
                self.move_cursor(node)

    def _edited(self, refusal: str | None) -> None:
        if refusal is not None:
            self.warn(refusal)
        else:
            self.playback.pause()
            self.new_runs_shown()

    def action_place(self, what: str) -> None:
        session = self.session
        self._edited(session.edits.place(what, session.cursor))

    def action_toggle_wall(self) -> None:
        session = self.session
        self._edited(session.edits.toggle_wall(session.cursor))

    # -- the terrain brush -------------------------------------------------------------------
    def action_brush(self, cost: float | None = None) -> None:
        """The brush's next cost (``b``), or ``cost`` (the palette's; 0: off)."""
        edits = self.session.edits
        if self.session.graph is not None:
            from tui_search.tui.model.graph_edits import NO_TERRAIN

            self.warn(NO_TERRAIN)
            return
        if cost is None:
            edits.cycle_brush()
        else:
            edits.brush = cost or None
        self.show_brush()

    def show_brush(self) -> None:
        """The key bar says the brush (``m Paint cost 5``) while it is on, and a note says
        what changed."""
        cost = self.session.edits.brush
        bar = self.query_one(KeyBar)
        bar.relabel("paint", None if cost is None else f"Paint {brush_name(cost)}")
        bar.raise_hint("paint", cost is not None)
        self.refresh_bindings()
        self.note("Terrain brush off" if cost is None else
                  f"Terrain brush: {brush_name(cost)} (m or a mouse drag paints it)", "brush")

    def action_paint(self) -> None:
        session = self.session
        self._edited(session.edits.paint_cost(session.cursor))

    def action_undo(self) -> None:
        """Undo the last edit (a mouse stroke is one): the cursor on it, the searches anew."""
        self._undone(self.session.edits.undo())

    def action_redo(self) -> None:
        self._undone(self.session.edits.undo(redo=True))

    def _undone(self, refusal: str | None) -> None:
        if refusal is None:
            self.move_cursor(self.session.cursor)
        self._edited(refusal)

    def on_grid_view_cell_clicked(self, message: GridView.CellClicked) -> None:
        """A left-button stroke paints what its first cell became (an obstacle, or free);
        start and goal are never painted over; the right button only moves the cursor."""
        self.move_cursor(message.cell)
        self._stroke = None
        edits, cell = self.session.edits, message.cell
        grid = self.session.grid
        if message.button != 1 or self.views[0].overview:
            return
        if edits.brush is not None:  # the terrain brush: the stroke paints its cost
            self._stroke = "brush"
            edits.history.begin_stroke()
            self._stroked(edits.stroke_cost(cell))
        elif cell not in (grid.start, grid.goal):
            self._stroke = not grid.is_blocked(cell)
            edits.history.begin_stroke()  # the cells of this stroke: one edit
            self._edited(edits.toggle_wall(cell))

    def on_grid_view_cell_dragged(self, message: GridView.CellDragged) -> None:
        if self._stroke is not None:
            self.move_cursor(message.cell)
            edits = self.session.edits
            stroke = self._stroke
            self._stroked(edits.paint(message.cell, stroke) if isinstance(stroke, bool)
                          else edits.stroke_cost(message.cell))

    def _stroked(self, changed: bool) -> None:
        if changed:
            self.playback.pause()
            self.new_runs_shown()

    def on_grid_view_stroke_ended(self, message: GridView.StrokeEnded) -> None:
        self._stroke = None
        self.session.edits.history.end_stroke()

    def on_grid_view_cell_hovered(self, message: GridView.CellHovered) -> None:
        self.show_readout()

    def action_overview(self) -> None:
        on = not self.views[0].overview
        for view in self.views:
            view.set_overview(on)

    def action_zoom(self, steps: int) -> None:
        for view in self.views:
            view.zoom(steps)

    def action_labels(self) -> None:
        views = self.grid_views
        if not views:
            self.warn("A graph's nodes are labelled with their names: no cell labels")
            return
        for view in views:
            mode = view.cycle_labels()
        self.note(f"Cell labels: {mode}", "labels", timeout=2)

    def action_page(self, pages: int) -> None:
        """The cursor a screenful of cells up or down (at least one cell)."""
        view = self.views[0]
        if not isinstance(view, GridView):
            return  # a graph's nodes have no pages: the arrows and Tab go node to node
        rows = view.geometry.rows_in(view.scrollable_content_region.height)
        x, y = as_cell(self.session.cursor)
        y = max(0, min(self.session.grid.height - 1, y + pages * max(1, rows - 1)))
        self.move_cursor((x, y))

    def action_jump(self, where: str) -> None:
        """The cursor to the start, the goal or the node being expanded (when there is one)."""
        session = self.session
        run = session.run
        cell = {"start": session.board.start, "goal": goal_of(session.board),
                "current": current_node(run) if run is not None else None}[where]
        if cell is None:
            self.warn({"start": "No start on the map", "goal": "No goal on the map",
                       "current": "No node is being expanded (step 0)"}[where])
            return
        self.move_cursor(cell)

    # -- files and screens -----------------------------------------------------------------
    def action_save(self) -> None:
        self.files.save_own()

    def action_save_as(self) -> None:
        self.files.save_as()

    def action_open(self) -> None:
        self.files.open()

    def action_generate(self) -> None:
        self.files.generate()

    def action_quit(self) -> None:
        self.files.quit()

    def action_export(self) -> None:
        """The palette's Export: the run as a file (tui/screens/export_command.py)."""
        if self.session.graph is not None:
            self.warn("Exports (.svg, .cast, .gif, .md) are of a grid's search, not yet a graph's")
            return
        from tui_search.tui.screens.export_command import ask_export  # only when asked

        ask_export(self, self.session, self.file_access, getattr(self.app, "exporter", None))

    def action_help(self) -> None:
        from tui_search.tui.dialogs.help import HelpScreen  # only when asked: start-up time

        self.app.push_screen(HelpScreen(self.views[0]))

    # -- keys ------------------------------------------------------------------------------
    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """Grey out (None) the keys that cannot act now, hide (False) those that do not apply
        (Play while playing, Pause while not, esc but while computing the end, undo and
        redo before the first edit), and behind the "too small" message let only q act."""
        session = self.session
        runs = session.runs
        if self.too_small:
            return action in ("quit", "help_quit")
        play = session.lesson
        if action == "page":  # pgdn and pgup: a page of cells, or a lesson's sections
            return play is None
        if action == "lesson_scroll":
            return play is not None
        if action == "lesson":
            if play is None:
                return False
            return 0 <= play.index + int(str(parameters[0])) < len(play.lesson.sections) or None
        playing = session.playing
        state: dict[str, bool | None] = {
            "play": False if playing else (None if not runs else True),
            "pause": playing,
            "stop_seek": session.seeking,
            "next": None if not runs or (session.at_end() and not playing) else True,
            "prev": None if not runs or session.at_start() else True,
            "reset": None if not runs else True,
            "answer": session.quiz.on and bool(runs),
            "faster": None if session.speed_index == len(playback.SPEEDS) - 1 else True,
            "slower": None if session.speed_index == 0 else True,
        }
        history = session.edits.history
        edited = history.can_undo() or history.can_redo()
        state["undo"] = (history.can_undo() or None) if edited else False
        state["redo"] = (history.can_redo() or None) if edited else False
        state["last"], state["first"] = state["next"], state["prev"]
        state["paint"] = session.edits.brush is not None
        state["difference"] = session.jumps.difference_step is not None
        return state.get(action, True)

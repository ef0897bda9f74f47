"""The by-hand screen: one pane whose steps the student makes (:mod:`~tui_search.tui.model.
by_hand`), the panel over it that says what to do and names a mistake at once, and the keys
of :mod:`~tui_search.tui.screens.by_hand_keys`.

It is pushed over the main screen (``H``, the palette, ``--by-hand``) with a session of its own
on a copy of the map, so leaving it (``esc``) finds the searches as they were.  At the end the
summary; its replay puts the run, as a trace, beside the search on the main screen.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, ClassVar

from textual.binding import BindingType
from textual.widget import Widget

from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.state import as_cell
from tui_search.tui.model.by_hand import ByHand
from tui_search.tui.model.session import Session
from tui_search.tui.screens.by_hand_keys import ARROW_MOVES, BY_HAND_IMPORTANCE, KEYS
from tui_search.tui.screens.panes import PanesScreen
from tui_search.tui.widgets.by_hand_panel import ByHandPanel
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.grid_view import GridView

if TYPE_CHECKING:
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.search.compare import Contender
    from tui_search.engine.traces.hand import Told
    from tui_search.tui.model.file_rules import FileAccess

#: Said when there is nothing to step.
NO_ENDS = "By hand needs a start (s) and a goal (g) on the map"
NO_RECURSION = ("By hand steps a search with a frontier: turn recursion off in the settings "
                "(,) first")
NO_TWO_WAY = ("By hand steps a one-way search: pick BFS, DFS, UCS, greedy or A* (a "
              "bidirectional search's two frontiers are the app's to step)")


def hand_session(main: Session, exercise: Exercise | None = None) -> Session | str:
    """A session of its own for a run by hand: ``exercise``'s map and search (a by-hand
    exercise), else the main session's map as it is now and its first search; or why there
    can be none (one line)."""
    contender: Contender | None
    if exercise is not None:
        grid, (_, contender) = exercise.grid, exercise.searches[0]
        name = exercise.recipe.title if exercise.recipe is not None else main.map_name
    else:
        grid, name = main.grid, main.map_name
        contender = main.contenders[0] if main.contenders else None
    if contender is None:
        return NO_ENDS
    if grid.start is None or grid.goal is None:
        return NO_ENDS
    if contender.semantics.recursive:
        return NO_RECURSION
    if get_algorithm(contender.algorithm).bidirectional:
        return NO_TWO_WAY
    grid = grid.copy()
    session = Session(grid, None, contender.algorithm, contender.semantics,
                      main.max_steps, unsaved_name=name)
    by_hand = ByHand(grid, contender.algorithm, contender.semantics, exercise, name)
    session.by_hand = by_hand
    session.runs = [by_hand.run]  # the pane shows the steps the student has made
    session.records = main.records
    return session


def open_by_hand(screen: PanesScreen, exercise: Exercise | None = None) -> bool:
    """Push the by-hand screen over ``screen`` (the main screen): ``exercise``'s run, else the
    main session's by-hand exercise's, else its map and first search.  False, with a warning
    why, when there can be none.  The run is recorded when it ends or is left
    (``--records``); its replay, when asked for, is shown on ``screen``."""
    main = screen.session
    if main.graph is not None:
        screen.warn("By hand runs on a grid's map for now, not on a graph", timeout=5)
        return False
    if exercise is None and main.exercise is not None and main.exercise.by_hand:
        exercise = main.exercise
    session = hand_session(main, exercise)
    if isinstance(session, str):
        screen.warn(session, timeout=5)
        return False

    def ended(by_hand: ByHand, replay: bool) -> None:
        problem = by_hand.write(main.records)
        if problem:
            screen.warn(problem, timeout=8)
        if by_hand.exercise is not None:
            screen.hand_result = (by_hand.solved, by_hand.verdict())
        if replay and by_hand.hand.k:
            main.show_replay(by_hand.replay(), by_hand.run.grid, by_hand.map_name)
            screen.show_map()
        elif by_hand.exercise is not None:
            screen.new_runs_shown()  # the challenge says the run's verdict

    screen.app.push_screen(ByHandScreen(session, screen.file_access, ended))
    return True


class ByHandScreen(PanesScreen):
    """The run by hand.  ``ended`` is called with the run when the student leaves (to record
    it) and, with ``replay`` True, when they ask for its replay."""

    BINDINGS: ClassVar[list[BindingType]] = KEYS
    IMPORTANCE = BY_HAND_IMPORTANCE

    def __init__(self, session: Session, file_access: FileAccess,
                 ended: Callable[[ByHand, bool], Any] | None = None) -> None:
        super().__init__(session, file_access)
        self.panel = ByHandPanel(id="by-hand")
        self._ended = ended

    @property
    def by_hand(self) -> ByHand:
        assert self.session.by_hand is not None
        return self.session.by_hand

    def over_panes(self) -> list[Widget]:
        return [self.panel]

    def on_mount(self) -> None:
        super().on_mount()
        self.show_hand()

    def show_hand(self) -> None:
        """The panel, the map's marks and the keys, as the run is now."""
        self.panel.show(self.by_hand)
        self.present()
        self.refresh_bindings()

    def present(self, changed: list[Any] | None = None, follow: bool = True,
                per_run: list[list[Any] | None] | None = None) -> None:
        super().present(None, follow, None)  # the marks move with every move: all of it
        self.quiz_panel.set_pick(self.session.cursor)

    def show_pick(self) -> None:
        self.quiz_panel.set_pick(self.session.cursor)

    # -- the moves --------------------------------------------------------------------------
    def _told(self, told: Told | None) -> None:
        if told is None:
            return
        self.show_hand()
        if told.ok and self.by_hand.finished and self.by_hand.ended is not None:
            problem = self.by_hand.write(self.session.records)  # at once: a kill loses nothing
            if problem:
                self.warn(problem, timeout=8)
            self.call_after_refresh(self.action_summary)

    def action_move(self, dx: int, dy: int) -> None:
        """Taking an entry off: the cursor; adding successors: the cell that way."""
        if self.by_hand.hand.picked is not None:
            self._told(self.by_hand.add_move(ARROW_MOVES[(dx, dy)]))
            return
        x, y = as_cell(self.session.cursor)  # (by hand runs on a grid)
        self.move_cursor((x + dx, y + dy))

    def action_add(self, move: str) -> None:
        self._told(self.by_hand.add_move(move))

    def action_take(self) -> None:
        self._told(self.by_hand.enter(as_cell(self.session.cursor)))

    def action_end_step(self) -> None:
        self._told(self.by_hand.enter(as_cell(self.session.cursor)))

    def action_take_back(self) -> None:
        self._told(self.by_hand.take_back())

    def action_undo(self) -> None:
        self._told(self.by_hand.undo())

    def action_hint(self) -> None:
        self.by_hand.hint()
        hinted = self.by_hand.hand.hint_cell()
        if hinted is not None and self.by_hand.hand.picked is None:
            self.move_cursor(as_cell(hinted))  # the entry to take: the cursor on it, its entry lit
        self.show_hand()

    def action_again(self) -> None:
        """The run again from step 0 (the run so far is recorded, unfinished)."""
        self._end(replay=False)
        old = self.by_hand
        grid = old.hand.run.grid
        self.session.by_hand = fresh = ByHand(grid, old.run.algorithm, old.run.semantics,
                                              old.exercise, old.map_name)
        self.session.runs = [fresh.run]
        self.move_cursor(grid.start or (0, 0))
        self.show_hand()

    def action_summary(self) -> None:
        from tui_search.tui.dialogs.by_hand_summary import AGAIN, REPLAY, ByHandSummaryScreen

        if not self.by_hand.finished or self.app.screen is not self:
            return

        def chosen(choice: str | None) -> None:
            if choice == REPLAY:
                self._end(replay=True)
                self.dismiss()
            elif choice == AGAIN:
                self.action_again()

        self.app.push_screen(ByHandSummaryScreen(self.by_hand), chosen)

    def action_leave(self) -> None:
        self._end(replay=False)
        self.dismiss()

    def action_quit(self) -> None:
        self._end(replay=False)
        self.app.exit()

    def _end(self, replay: bool) -> None:
        if self._ended is not None:
            self._ended(self.by_hand, replay)

    # -- the mouse ----------------------------------------------------------------------------
    def move_cursor(self, cell: tuple[int, int]) -> None:
        if self.session.move_cursor(cell):
            for view in self.views:
                view.set_cursor(cell)
            self.show_pick()
            self.show_readout()

    def on_grid_view_cell_clicked(self, message: GridView.CellClicked) -> None:
        """A click takes the entry there, or adds the cell (the right button only moves
        the cursor)."""
        self.move_cursor(message.cell)
        if message.button == 1 and self.by_hand.hand.phase != "done":
            self._told(self.by_hand.click(message.cell))

    def on_grid_view_cell_hovered(self, message: GridView.CellHovered) -> None:
        self.show_readout()

    def on_frontier_panel_entry_picked(self, message: FrontierPanel.EntryPicked) -> None:
        """An entry picked in the frontier panel: the cursor on it; clicked, taken off."""
        self.move_cursor(as_cell(message.cell))
        if message.clicked and self.by_hand.hand.picked is None:
            self._told(self.by_hand.take(as_cell(message.cell)))

    def action_help(self) -> None:
        from tui_search.tui.dialogs.help import HelpScreen

        self.app.push_screen(HelpScreen(self.views[0]))

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """Enter's three meanings, one shown at a time; the keys that add a successor only
        while adding them."""
        if self.too_small:
            return action in ("quit", "leave")
        phase = self.by_hand.hand.phase
        state: dict[str, bool | None] = {
            "take": phase == "pick", "end_step": phase == "mark", "summary": phase == "done",
            "add": phase == "mark" or None,
            "take_back": bool(self.by_hand.hand.marks) or None,
            "undo": (phase == "mark" or bool(self.by_hand.hand.steps)) or None,
            "hint": phase != "done" or None,
        }
        return state.get(action, True)


__all__ = ["NO_ENDS", "NO_RECURSION", "ByHandScreen", "hand_session"]

"""Predict the next node: a quiz mode of the app (a mixin of
:class:`~tui_search.tui.app.SearchApp`).

While it is on, the frontier panel lists its entries by cell, without the next-out mark, so it
does not give the answer away; the student moves the cursor to the cell that will come off the
frontier next -- or picks its entry in the frontier panel: a click on its line, or ``up`` /
``down`` there after ``tab`` (the pick *is* the cursor: the app moves it to that cell) -- and
presses ``enter`` (a double click on the entry picks and answers); the app takes the step, says right or wrong, and keeps a
score.  Under BFS the answer is the queue's front, under DFS the stack's top, under A* the
lowest f -- the whole lesson in one habit.
"""

from __future__ import annotations

from tui_search.engine.grid import Cell
from tui_search.tui.mixin import AppMixinBase
from tui_search.tui.widgets.frontier_panel import FrontierPanel
from tui_search.tui.widgets.key_bar import KeyBar


def cell_text(cell: Cell) -> str:
    return f"({cell[0]},{cell[1]})"


class QuizActions(AppMixinBase):
    """``i`` toggles the quiz; ``enter`` answers with the cell under the cursor, which a pick
    in the frontier panel moves."""

    quiz = False
    quiz_right = 0
    quiz_asked = 0

    def _quiz_question(self) -> str:
        run = self.search_run
        if run is None:
            return "Quiz: place a start and a goal first"
        frontier = run.algo.frontier
        where = f"the {frontier.noun}'s {frontier.next_end}"
        if run.algo.weighted:
            where += f" (the lowest {run.algo.priority_name})"
        # the score first: on a narrow screen the line's end is cut, and the hint can go
        return (f"Quiz ({self._quiz_score()}): which node comes off the {frontier.noun} next? "
                f"Cursor on it or click its entry, then enter (it is {where})")

    def _quiz_score(self) -> str:
        return f"{self.quiz_right} of {self.quiz_asked}"

    def action_quiz(self) -> None:
        self.quiz = not self.quiz
        self.quiz_right = self.quiz_asked = 0
        self.note = self._quiz_question() if self.quiz else ""
        self._show(changed=[])
        self.refresh_bindings()  # the frontier panel's pick keys come or go
        self.query_one(KeyBar).raise_hint("quiz", self.quiz)  # its key ends it: in sight

    @property
    def quiz_panel(self) -> FrontierPanel:
        """The frontier the quiz asks about: the single view's, or the left pane's."""
        panes = self.panes
        return panes[0].frontier if panes else self.frontier_panel

    def _show_pick(self) -> None:
        """Mark the cursor's entry in the quiz's frontier panel (none outside the quiz)."""
        self.quiz_panel.set_pick(self.cursor_cell if self.quiz else None)

    def on_frontier_panel_entry_picked(self, message: FrontierPanel.EntryPicked) -> None:
        """A pick in the quiz's panel moves the cursor there; a double click also answers."""
        if not self.quiz or message.panel is not self.quiz_panel:
            return
        self._move_cursor(message.cell)
        if message.answer:
            self.action_answer()

    def action_answer(self) -> None:
        """Take the step and mark the guess: the cell under the cursor."""
        run = self.search_run
        if not self.quiz or run is None:
            return
        if run.at_end:
            self.note = f"Quiz over: the search is done · {self._quiz_score()} (r restarts)"
            self._show(changed=[])
            return
        self._stop()
        guess = self.cursor_cell
        before = self._advance(forward=True)  # in compare mode every pane steps
        if before is None:
            return
        node = run.current_node()
        if node is None or run.k == before[0][0]:  # the left pane did not move
            self._moved(before)
            return
        self.quiz_asked += 1
        frontier = run.algo.frontier
        where = f"the {frontier.noun}'s {frontier.next_end}"
        if node == guess:
            self.quiz_right += 1
            verdict = f"Right: {cell_text(node)} was {where}"
        else:
            verdict = f"Not quite: {cell_text(node)} came off {where}, not {cell_text(guess)}"
        self.note = f"{verdict} · {self._quiz_score()} · next: cursor or pick, enter"
        self._moved(before)


__all__ = ["QuizActions"]

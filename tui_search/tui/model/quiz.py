"""Predict the next node: the quiz's questions, verdicts and score (no Textual).

While it is on, the frontier panel lists its entries by cell, without the next-out mark, so it
does not give the answer away; the student moves the cursor to the cell that will come off the
frontier next -- or picks its entry in the frontier panel (the pick *is* the cursor) -- and
presses ``enter``; the app takes the step, says right or wrong, and keeps a score.  Under BFS
the answer is the queue's front, under DFS the stack's top, under A* the lowest f -- the whole
lesson in one habit.
"""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import TYPE_CHECKING, NamedTuple

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State
from tui_search.tui.model.cell_edits import cell_text

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun


def _where(run: "Run | BiRun") -> str:
    frontier = run.algo.frontier
    if not isinstance(run, Run):  # whose turn it is
        turn = run.next_direction() or "forward"
        return f"the {turn} search's {frontier.noun}'s {frontier.next_end}"
    return f"the {frontier.noun}'s {frontier.next_end}"


#: The question while there is no run.
NO_RUN = "Quiz: place a start and a goal first"


class Quiz(NamedTuple):
    """The quiz's state: on or off, and the score (``right`` of ``asked``)."""

    on: bool = False
    right: int = 0
    asked: int = 0

    @property
    def score(self) -> str:
        return f"{self.right:,} of {self.asked:,}"

    def question(self, run: "Run | BiRun") -> str:
        where = _where(run)
        if run.algo.queued:
            where += f" (the lowest {run.algo.priority_name})"
        noun = run.algo.frontier.noun
        # the score first: on a narrow screen the question wraps, the score on its first row
        return (f"Quiz ({self.score}): which node comes off the {noun} next? "
                f"Cursor on it or click its entry, then enter (it is {where})")

    def over(self) -> str:
        return f"Quiz over: the search is done · {self.score} (r restarts)"


def toggled(quiz: Quiz, run: "Run | BiRun | None") -> tuple[Quiz, str]:
    """The quiz turned on (its first question, or why there is none yet) or off (no word)."""
    if quiz.on:
        return Quiz(), ""
    on = Quiz(on=True)
    return on, on.question(run) if run is not None else NO_RUN


def verdict(quiz: Quiz, run: "Run | BiRun", node: State, guess: State) -> tuple[Quiz, str]:
    """The new score and what to say, when the step took ``node`` off and the student
    guessed ``guess``."""
    right = node == guess
    quiz = Quiz(quiz.on, quiz.right + right, quiz.asked + 1)
    where = _where(run)
    said = (f"Right: {cell_text(node)} was {where}" if right
            else f"Not quite: {cell_text(node)} came off {where}, not {cell_text(guess)}")
    return quiz, f"{said} · {quiz.score} · next: cursor or pick, enter"


__all__ = ["NO_RUN", "Quiz", "toggled", "verdict"]

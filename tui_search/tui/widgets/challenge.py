"""The challenge panel: an exercise (the tutorial's or a teacher's file), checked live on the map
being edited.

It quotes the exercise under its title, names its rules where they are not the tutorial's
(its searches, and the panes, run under them), shows its searches' figures on the map as it is
now, and says **Solved** the moment an edit satisfies the exercise -- or that an edit unsolved
it.  What the
figures are and whether they solve it comes from :mod:`tui_search.engine.course.grading`; the app
pushes each new verdict with :meth:`ChallengePanel.show`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

from rich.text import Text
from textual.widgets import Static

if TYPE_CHECKING:  # the exercise modules: imported once one is shown (tui/session.py)
    from tui_search.engine.course.exercise_file import Exercise
    from tui_search.engine.course.grading import Verdict


class ChallengePanel(Static):
    """The exercise, the figures, and solved / not solved."""

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "challenge--quote", "challenge--solved", "challenge--unsolved", "challenge--hint",
    }

    DEFAULT_CSS = """
    ChallengePanel {
        height: auto;
        max-height: 12;
        padding: 0 1;
        border: round $accent;
        border-title-align: left;
        border-title-color: $text-accent;
        & > .challenge--quote { color: $text-muted; text-style: italic; }
        & > .challenge--solved { color: $text-success; text-style: bold; }
        & > .challenge--unsolved { color: $text-warning; text-style: bold; }
        & > .challenge--hint { color: $text-muted; }
    }
    """

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.verdict: Verdict | None = None
        self.was_solved = False  # the verdict before the last edit
        self.text = ""  # what it says, as plain text (for tests)

    def show(self, exercise: Exercise, verdict: Verdict | None, note: str = "") -> None:
        """The exercise's verdict on the map as it is now (None, with ``note`` saying why,
        when it cannot be checked)."""
        before = self.verdict.solved if self.verdict is not None else None
        self.was_solved = bool(before)
        self.verdict = verdict
        self.border_title = exercise.title
        style = self.get_component_rich_style
        out = Text()
        out.append(exercise.text + "\n", style("challenge--quote"))
        if exercise.rules:  # the searches' rules, where they are not the tutorial's
            out.append(f"Rules: {exercise.rules}\n", style("challenge--hint"))
        if verdict is None:
            out.append(note, style("challenge--hint"))
        else:
            if verdict.solved:
                out.append("Solved ✓ ", style("challenge--solved"))
            elif not verdict.graded:
                out.append("Not graded: ", style("challenge--unsolved"))
            elif before:
                out.append("Not solved any more: ", style("challenge--unsolved"))
            else:
                out.append("Not solved yet: ", style("challenge--unsolved"))
            out.append(verdict.said)
            if verdict.hints:
                out.append(f"\nHint: {verdict.hints}", style("challenge--hint"))
        self.text = out.plain
        self.update(out)

    def show_by_hand(self, exercise: Exercise, result: tuple[bool, str] | None) -> None:
        """A by-hand exercise: what it asks, and its last run's verdict (``result``: solved,
        and in words; None: no run yet)."""
        self.verdict = None
        self.border_title = exercise.title
        style = self.get_component_rich_style
        out = Text()
        out.append(exercise.text + "\n", style("challenge--quote"))
        name = exercise.searches[0][1].label
        allowed = f"{exercise.mistakes} mistake{'s' if exercise.mistakes != 1 else ''}"
        out.append(f"By hand: H steps {name} yourself; solved when you finish it with at "
                   f"most {allowed}\n", style("challenge--hint"))
        if result is None:
            out.append("Not done yet", style("challenge--unsolved"))
        else:
            solved, said = result
            out.append(f"Your last run: {said}",
                       style("challenge--solved" if solved else "challenge--unsolved"))
        self.was_solved = bool(result and result[0])
        self.text = out.plain
        self.update(out)


__all__ = ["ChallengePanel"]

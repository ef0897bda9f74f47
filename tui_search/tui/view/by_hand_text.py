"""What the by-hand panel says, as text (no Textual): the title, what to do now, what the last
move came to (a mistake named, a hint), the counts so far, and the end's summary.  The panel
(:mod:`~tui_search.tui.widgets.by_hand_panel`) and the summary dialog draw it.
"""

from __future__ import annotations

from tui_search.tui.model.by_hand import ByHand, Summary

#: A piece of text and its style's name (the widget's component class, without its prefix):
#: ``prompt``, ``mistake``, ``said``, ``counts``, ``solved``, ``unsolved``.
Piece = tuple[str, str]


def clock_text(seconds: float) -> str:
    """``1:05`` (minutes and seconds), ``1:02:05`` past an hour."""
    whole = int(seconds)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02}:{secs:02}" if hours else f"{minutes}:{secs:02}"


def title(by_hand: ByHand) -> str:
    """"By hand: BFS · Exercise title"."""
    ex = by_hand.exercise
    return f"By hand: {by_hand.name}" + (f" · {ex.title}" if ex is not None else "")


def panel_lines(by_hand: ByHand) -> list[list[Piece]]:
    """The panel's lines: the last thing said (a mistake, a hint, or the step made and what
    to do next), then the counts and the exercise's verdict."""
    hand = by_hand.hand
    said = by_hand.said
    lines: list[list[Piece]] = []
    if by_hand.wrong:
        lines.append([("✗ ", "mistake"), (said, "mistake")])
        lines.append([(f"Try again · {by_hand.prompt()}", "prompt")])
    elif said.startswith("Hint:"):
        lines.append([(said, "said")])
        lines.append([(by_hand.prompt(), "prompt")])
    else:
        lines.append([(said, "prompt")])
    n = len(hand.mistakes)
    counts = f"Mistakes {n} · hints {by_hand.hints} · h a hint · u undo"
    row: list[Piece] = [(counts, "counts")]
    verdict = by_hand.verdict()
    if verdict:
        row.append((f" · {verdict}", "solved" if by_hand.solved else "unsolved"))
    lines.append(row)
    return lines


def summary_lines(summary: Summary, name: str) -> list[str]:
    """The end of a run, a line a fact: the steps and the time, the mistakes by cause, the
    hints and undos, the path, the exercise's verdict."""
    s = summary
    lines = [f"{s.steps:,} step{'s' if s.steps != 1 else ''} in {clock_text(s.seconds)}, "
             f"{s.mistakes:,} mistake{'s' if s.mistakes != 1 else ''}"
             + ("" if s.mistakes else ": every step right the first time")]
    lines += [f"  {n} × {words}" for words, n in s.by_cause]
    lines.append(f"Hints: {s.hints:,} · steps undone: {s.undone:,}")
    lines.append(f"{name} found a path of {s.path_moves:,} moves" if s.path_moves is not None
                 else f"{name} found no path: the frontier ran out")
    if s.verdict:
        lines.append(f"Exercise: {s.verdict}")
    return lines


__all__ = ["clock_text", "panel_lines", "summary_lines", "title"]

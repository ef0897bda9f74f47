"""A bidirectional search in plain sentences (plain mode and the handout), and what either
kind of run says after a key (:func:`report`, :func:`result`): each step as its
narration says it, with whose turn it was; both frontiers; the tree the step grew; both
trees; and at the end the path through the meeting cell and why the search stopped."""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.run.recorded import Run
from tui_search.plain.telling import (
    frontier_sentence,
    result_sentence,
    step_report,
    tree_lines,
    tree_sentence,
)
from tui_search.tui.view.narration import cell_text
from tui_search.tui.view.two_way.words import NAMES, two_way_narration

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun


def _sentence(text: str) -> str:
    return text if text.endswith((".", "!", "?")) else text + "."


def two_way_step(run: BiRun, name: str = "") -> str:
    """"Step 3: ← Backward: expanded (9,3) …"."""
    head = f"{name} step" if name else "Step"
    return f"{head} {run.k}: {_sentence(two_way_narration(run))}"


def two_way_frontiers(run: BiRun, hide_order: bool = False) -> str:
    """Both frontiers, each as the one-way search's sentence says it, named by its half."""
    return " ".join(f"{NAMES[d]}: {frontier_sentence(half, hide_order)}"
                    for d, half in zip(NAMES, run.halves, strict=True))


def two_way_new_edges(run: BiRun) -> str:
    """The new edges of the tree of the half that took the step ("" at step 0)."""
    if not run.k:
        return ""
    direction = run.direction(run.k)
    said = tree_sentence(run.halves[direction != "forward"])
    return f"{NAMES[direction]}: {said}" if said else ""


def two_way_result(run: BiRun) -> str:
    """At the end: the path through the meeting, its moves and cost, or no path."""
    if not run.at_end:
        return ""
    outcome = run.outcome_so_far(run.k)
    counts = (f"Expanded {outcome.expanded}, generated {outcome.generated}, the largest "
              f"frontiers together {outcome.max_frontier}.")
    if not run.found:
        return f"No path. {counts}"
    moves, cost = run.moves() or [], run.path_cost()
    said = ", ".join(moves) if moves else "none: the start is the goal"
    return (f"Path: {len(moves)} moves, cost {cost:.2f}, through the meeting "
            f"{cell_text(run.meeting())}: {said}. {counts}")


def two_way_report(run: BiRun, name: str = "", hide_order: bool = False) -> list[str]:
    """What plain mode prints after a key: the step, the tree's new edges, both frontiers,
    and at the end the path."""
    lines = [two_way_step(run, name), two_way_new_edges(run), two_way_frontiers(run, hide_order),
             two_way_result(run)]
    return [line for line in lines if line]


def two_way_trees(run: BiRun) -> list[str]:
    """Both search trees, the forward's first."""
    out: list[str] = []
    moved = run.direction(run.k) if run.k else ""
    for direction, half in zip(NAMES, run.halves, strict=True):
        head, *lines = tree_lines(half)
        if direction == "backward" and lines and lines[0].startswith("START"):
            lines[0] = "GOAL" + lines[0][len("START"):]  # the backward search's root
        if direction != moved:  # only the half that took the step is expanding a node
            lines = [line.replace(", being expanded", ", expanded") for line in lines]
        out += [f"{NAMES[direction]} {head[0].lower()}{head[1:]}", *lines]
    return out


def report(run: Run | BiRun, name: str = "", hide_order: bool = False) -> list[str]:
    """What plain mode prints of either kind of run after a key (:func:`~tui_search.plain.
    telling.step_report` for a one-way search)."""
    if isinstance(run, Run):
        return step_report(run, name, hide_order)
    return two_way_report(run, name, hide_order)


def result(run: Run | BiRun) -> str:
    """Either kind of run's answer at its end ("" before)."""
    return result_sentence(run) if isinstance(run, Run) else two_way_result(run)


__all__ = ["report", "result", "two_way_frontiers", "two_way_new_edges", "two_way_report",
           "two_way_result", "two_way_step", "two_way_trees"]

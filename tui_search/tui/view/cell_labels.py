"""What a big cell of the map says (no Textual: the grid view draws these strings): its
glyph, the arrow of the move that reached it and, where there is room, its depth or, for the
cost-ordered searches, its g and f -- as Red Blob Games' pages draw a search, with all eight
directions.

A cell ``width`` x ``height`` characters (4x2 or more) is laid out as::

    ●◀ 17      glyph top left (under the cursor, its mark beside it and a bar along the
               last line), the first number right-aligned on the first line
      ↗        the arrow in the middle line
    5  31      the second number (f), right-aligned on the last line when there is one free;
               the cell's terrain cost (when not 1) on the last line: right, else left
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.maps.grid import DIRECTIONS, Cell
from tui_search.engine.run.recorded import Run
from tui_search.tui.view.cell_codes import CURSOR_BAR, CURSOR_MARK

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun

#: What a cell's label shows, in the order the label key cycles them.
LABEL_MODES = ("arrows", "depth/cost", "none")
#: The arrow of each move, by direction name.
ARROWS = dict(zip(DIRECTIONS, "↑↗→↘↓↙←↖", strict=True))


def number_text(value: float, room: int) -> str | None:
    """``value`` in at most ``room`` characters: an integer as it is, a cost with one decimal
    or none; None when even that does not fit."""
    if float(value).is_integer():
        options = [f"{int(value)}"]
    else:
        options = [f"{value:.1f}", f"{value:.0f}"]
    for text in options:
        if len(text) <= room:
            return text
    return None


def label(run: Run | BiRun, cell: Cell, mode: str) -> tuple[str, list[float]]:
    """The arrow (or ``""``) and the numbers ``cell``'s label shows in ``mode``, from the
    latest event that reached the cell at the run's position (nothing when none did; a
    bidirectional search's: in the half that reached it, the forward first)."""
    if not isinstance(run, Run):
        from tui_search.tui.view.two_way.cells import half_at

        half = half_at(run, cell)
        if half is None:
            return "", []
        run = half
    g = run.now.last_event(cell)
    if g is None or mode == "none":
        return "", []
    arrow = ARROWS.get(run.nodes.move(g), "") if mode == "arrows" else ""
    costs = run.nodes.costs(g)
    if costs is None:
        numbers = [float(run.nodes.depth(g))]
    else:
        cost, h, priority = costs
        numbers = [cost, priority] if priority != cost else [cost]
        if not run.algo.informed:
            numbers = [cost]
        elif priority == h:  # greedy: f is h
            numbers = [cost, h]
    return arrow, numbers


def cell_line(run: Run | BiRun | None, cell: Cell, width: int, height: int, sub: int, mode: str,
              glyph: str, wall: bool, cost: str | None = None, cursor: bool = False) -> str:
    """Line ``sub`` (0 .. height-1) of ``cell`` drawn ``width`` characters wide; ``cost``
    (the cell's terrain cost, when it is not 1) on the last line, right-aligned when no
    number is there, else at its left; ``cursor``: the cursor's mark beside the glyph (the
    second character of the first line, which a number never takes) and a bar along the
    last line."""
    if wall:
        return "█" + CURSOR_MARK + "█" * (width - 2) if cursor and sub == 0 else "█" * width
    if cursor and sub == height - 1 and height > 1:  # a bar under the cell, what it says kept
        return cell_line(run, cell, width, height, sub, mode, glyph, wall, cost).replace(
            " ", CURSOR_BAR)
    arrow, numbers = label(run, cell, mode) if run is not None else ("", [])
    middle = height // 2 if height > 1 else 0
    text = [" "] * width
    if sub == 0:
        text[0] = glyph
    if arrow and sub == middle:
        text[(width - 1) // 2] = arrow
    slots = [0] + ([height - 1] if height > 1 and (height - 1 != middle or not arrow) else [])
    right_free = True  # nothing right-aligned on this line yet
    for line, value in zip(slots, numbers, strict=False):
        if line != sub:
            continue
        shown = number_text(value, width - 2)
        if shown is not None:
            text[width - len(shown):] = shown
            right_free = False
    if cost is not None and height > 1 and sub == height - 1:
        at = width - len(cost) if right_free else 0
        text[at:at + len(cost)] = cost
    if cursor and sub == 0:
        text[1] = CURSOR_MARK
    return "".join(text)


__all__ = ["ARROWS", "LABEL_MODES", "cell_line", "label", "number_text"]

"""How a frontier entry wider than its panel takes more rows (no Textual): the cell on the
first row, and the figures -- iterative deepening's ``d=3``, a priority queue's ``f6.41``,
``g2.41``, ``h4.00`` -- the depth after it while it fits, the figures on rows of their own,
indented under the cell, together while they fit.  The least important parts go first, never a figure: the move (``NE``) goes when it
would open a row, then the marker column (``▶+``) when the cell does not fit beside it (the
entry expanded next is highlighted anyway).

Every entry of a panel takes the same rows (their columns have the same widths), so the
entry on a line is found by a division, whatever the frontier's size."""

# No `from __future__ import annotations`: typing compiles a NamedTuple's string
# annotations one by one at import (~5 M instructions of every start in all: session 14).
from typing import TYPE_CHECKING, NamedTuple

from tui_search.tui.pieces import Parts
from tui_search.tui.widgets.frontier_text import figures

if TYPE_CHECKING:
    from tui_search.engine.run import Run

#: Width of the marker column: "▶+ ".
MARKER_W = 3
#: Width of the move column: a direction's name (START, longer, is only ever on its own: the
#: frontier holds just the root then).
DIR_W = 2


class EntryRows(NamedTuple):
    """An entry's layout on more than one row: ``rows`` holds each row's indent and the
    slots on it ("depth", "move", and "0", "1", "2": the figures), the first row's after the
    cell; ``marker``: the marker column is shown.  (A NamedTuple: a frozen dataclass costs
    ~1 ms of every start: benchmarks/README.md, session 14.)"""

    marker: bool
    rows: tuple[tuple[int, tuple[str, ...]], ...]
    width: int  # the widest row


def plan_rows(room: int, coord_w: int, depth_w: int, move_w: int,
              figure_ws: list[int]) -> EntryRows:
    """The rows of an entry in ``room`` cells whose cell is ``coord_w`` wide, its depth
    ``depth_w`` (0: none), its move ``move_w`` and its figures ``figure_ws``."""
    marker = MARKER_W + coord_w <= room
    indent = MARKER_W if marker else 0
    used = (MARKER_W if marker else 0) + coord_w
    rows: list[tuple[int, list[str]]] = [(0, [])]
    width = used
    slots = ([("depth", depth_w)] if depth_w else []) + [("move", move_w)] + [
        (str(i), w) for i, w in enumerate(figure_ws)]
    for name, w in slots:
        if used + 1 + w <= room and (name != "0" or len(rows) > 1):  # the figures on
            # rows of their own, together while they fit
            rows[-1][1].append(name)
            used += 1 + w
        elif name == "move":  # the least important part: it goes rather than take a row
            continue
        else:
            at = indent if indent + w <= room else 0
            rows.append((at, [name]))
            used = at + w
        width = max(width, used)
    return EntryRows(marker, tuple((at, tuple(names)) for at, names in rows), width)


def entry_row(run: "Run", g: int, plan: EntryRows, row: int, marks: tuple[bool, bool],
              widths: tuple[int, int, int]) -> Parts:
    """Row ``row`` of the entry of event ``g`` laid out by ``plan``; ``marks``: it is the
    entry expanded next, it was just added; ``widths``: the cell's, the depth's (0: none)
    and one cost's (0: none)."""
    first, added = marks
    coord_w, depth_w, cost_w = widths
    main = "frontier-panel--next" if first else "frontier-panel--entry"
    indent, slots = plan.rows[row]
    parts: Parts = [(" " * indent, main)] if indent else []
    if not row:
        if plan.marker:
            parts += [("▶" if first else " ", main),
                      ("+" if added else " ", "frontier-panel--added" if added else main),
                      (" " * (MARKER_W - 2), main)]
        x, y = run.nodes.cell(g)
        parts.append((f"({x},{y})".ljust(coord_w), main))
    shown = figures(run, g, cost_w) if cost_w else []
    stale = "frontier-panel--stale" if shown and run.now.is_stale(g) else main
    for slot in slots:
        piece: tuple[str, str]
        if slot == "depth":
            piece = (f"d={run.nodes.depth(g)}".ljust(depth_w), "frontier-panel--detail")
        elif slot == "move":
            piece = (run.nodes.move(g).ljust(DIR_W), main)
        else:  # a figure, pressed close: "f6.41"
            piece = (shown[int(slot)].replace(" ", "", 1), stale)
        if parts and (row == 0 or parts[-1][0].strip()):
            parts.append((" ", main))
        parts.append(piece)
    return parts

"""How a frontier entry is laid out (no Textual): its columns' widths, its one row
(:func:`entry_line`), and, wider than its panel, its rows.  Those: the cell on the
first row, and the figures -- iterative deepening's ``d=3``, a priority queue's ``f6.41``,
``g2.41``, ``h4.00`` -- the depth after it while it fits, the figures on rows of their own,
indented under the cell, together while they fit.  The least important parts go first, never a
figure: the move (``NE``) goes when it would open a row, then the marker column (``▶+``) when the
cell does not fit beside it (the entry expanded next is highlighted anyway).

Every entry of a panel takes the same rows (their columns have the same widths), so the
entry on a line is found by a division, whatever the frontier's size."""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import TYPE_CHECKING, NamedTuple

from tui_search.engine.search.heuristics import octile
from tui_search.engine.search.state import state_text, state_width
from tui_search.engine.util.numbers import group_digits
from tui_search.tui.view.frontier_text import DIR_W, costs_column, figures
from tui_search.tui.view.pieces import Parts

if TYPE_CHECKING:
    from tui_search.engine.run.recorded import Run

#: Width of the marker column: "▶+ ".
MARKER_W = 3
#: Cells between an entry and its end hint (at least).
HINT_GAP = 2


class EntryRows(NamedTuple):
    """An entry's layout on more than one row: ``rows`` holds each row's indent and the
    slots on it ("depth", "move", and "0", "1", "2": the figures), the first row's after the
    cell; ``marker``: the marker column is shown.  (A NamedTuple: a frozen dataclass would
    cost every start more: benchmarks/README.md, "startup".)"""

    marker: bool
    rows: tuple[tuple[int, tuple[str, ...]], ...]
    width: int  # the widest row


def move_text(run: "Run", g: int) -> str:
    """The entry's move: a grid's direction, START; nothing on a graph, whose move is the
    node it reaches (the entry's own name)."""
    if run.graph is not None and run.nodes.parent(g) >= 0:
        return ""
    return run.nodes.move(g)


def cost_bound(run: "Run") -> float:
    """A cost no path costs more than, for a cost column's width: the straight-line cost
    across the map, or every road of the graph."""
    graph = run.graph
    if graph is not None:
        return sum(graph.data.road_cost)
    return octile(run.grid.width - 1, run.grid.height - 1)


def column_widths(run: "Run") -> tuple[int, int, int, int]:
    """The widths of the entries' columns at the run's position (every entry's the same): the
    cell's, for the map's largest cell; iterative deepening's ``d=N`` (0: none); the move's
    (START, longer, is only ever on its own: just the root is on the frontier then); one
    cost's (0: not a priority queue), the longest straight-line cost across the map's --
    most figures fit, a longer one pushes the rest of its line along."""
    coord_w = state_width(run.board)
    limit = run.steps.depth_limit() if run.algo.iterative else None
    depth_w = len(f"d={group_digits(limit)}") if limit is not None else 0
    cost_w = len(f"{cost_bound(run):.2f}") if run.algo.weighted else 0
    move_w = max(DIR_W, len(run.nodes.move(run.now.frontier(0, 1)[0]))
                 if run.now.frontier_len() == 1 else 0)
    return coord_w, depth_w, move_w, cost_w


def entry_width(run: "Run", widths: tuple[int, int, int, int]) -> int:
    """An entry's width on one row: marker + cell + " " [+ d=N + " "] + move [+ costs]: the
    move after the depth, so that every column stands one space from the next whatever its
    label (START d=0 / S d=1 alike)."""
    coord_w, depth_w, move_w, cost_w = widths
    return (MARKER_W + coord_w + 1 + (depth_w + 1 if depth_w else 0) + move_w
            + (len(costs_column(run, 0, cost_w)) if cost_w else 0))


def fit_entry(room: int, entry_w: int, count: int, widths: tuple[int, int, int, int]
              ) -> tuple[int, int, "EntryRows | None"]:
    """How an entry ``entry_w`` wide with ``count`` figures fits ``room`` cells (0: not laid
    out yet): too narrow for it, its figures pressed closer together (``squeeze`` 1), then
    each name on its number (2), then on more rows.  ``widths``: the cell's, the depth's (0:
    none), the move's and one cost's.  Returns the squeeze, the entry's width pressed, and
    its rows (None: one)."""
    coord_w, depth_w, move_w, cost_w = widths
    squeeze = 0 if not room or entry_w <= room else (1 if entry_w - 1 <= room else 2)
    entry_w -= (0, 1, 1 + count)[squeeze] if count else 0
    # (a figure's name, its number, and a digit to spare: a path's cost may pass the map's
    # diagonal)
    rows = None if not room or entry_w <= room else plan_rows(
        room, coord_w, depth_w, move_w, [cost_w + 2] * count)
    return squeeze, entry_w, rows


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
        parts.append((state_text(run.nodes.cell(g)).ljust(coord_w), main))
    shown = figures(run, g, cost_w) if cost_w else []
    stale = "frontier-panel--stale" if shown and run.now.is_stale(g) else main
    for slot in slots:
        piece: tuple[str, str]
        if slot == "depth":
            piece = (f"d={group_digits(run.nodes.depth(g))}".ljust(depth_w),
                     "frontier-panel--detail")
        elif slot == "move":
            piece = (move_text(run, g).ljust(DIR_W), main)
        else:  # a figure, pressed close: "f6.41"
            piece = (shown[int(slot)].replace(" ", "", 1), stale)
        if parts and (row == 0 or parts[-1][0].strip()):
            parts.append((" ", main))
        parts.append(piece)
    return parts


def entry_line(run: "Run", g: int, marks: tuple[bool, bool], widths: tuple[int, int, int],
               squeeze: int, iddfs: bool, hint: "tuple[int, str] | None") -> Parts:
    """The entry of event ``g`` on one row: the marker column, the cell, iteration's depth
    (``iddfs``), the move, a priority queue's figures (pressed by ``squeeze``:
    :func:`~tui_search.tui.view.frontier_text.costs_column`).  ``marks`` and ``widths`` as
    for :func:`entry_row`; ``hint``: the column the end hints start at and this entry's hint,
    None when the hints (and "stale") do not fit beside the entries."""
    first, added = marks
    coord_w, depth_w, cost_w = widths
    main = "frontier-panel--next" if first else "frontier-panel--entry"
    parts = [
        ("▶" if first else " ", main),
        ("+" if added else " ", "frontier-panel--added" if added else main),
        (" " + state_text(run.nodes.cell(g)).ljust(coord_w) + " ", main),
    ]
    used = MARKER_W + coord_w + 1
    if iddfs:
        depth = f"d={group_digits(run.nodes.depth(g))}".ljust(depth_w)
        parts.append((depth, "frontier-panel--detail"))
        parts.append((" ", main))
        used += len(depth) + 1
    move = move_text(run, g).ljust(DIR_W)
    parts.append((move, main))
    used += len(move)
    if cost_w:
        costs = costs_column(run, g, cost_w, squeeze)
        stale = run.now.is_stale(g)
        parts.append((costs, "frontier-panel--stale" if stale else main))
        used += len(costs)
        if stale and hint is not None:  # in the hint column (a priority queue has no
            # end hints)
            parts.append((" " * max(HINT_GAP, hint[0] - used), main))
            parts.append(("stale", "frontier-panel--stale"))
    if hint is not None and hint[1]:
        parts.append((" " * max(HINT_GAP, hint[0] - used), "frontier-panel--entry"))
        parts.append((hint[1], "frontier-panel--hint"))
    return parts

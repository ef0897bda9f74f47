"""Where the panes go, from the room there is (no Textual): one rule for one pane or four.

The panes share the space the status lines, the key bar, the legend, the readout and the
challenge panel leave.  In that room the map comes first: it is shown whole whenever it fits
at its smallest cells.  What else a pane shows gives way in this order when there is not room
for all of it: the comparison table, the search trees, the panes' own status lines (the line
under them then says each search's step and nodes expanded), the frontier lists (a queue
beside a stack is what a replay or a comparison is there to show; what a pane's narration
says of a step, the "+" entries of its frontier show too).  A pane
much wider than tall keeps its lists beside the map, as a column; else under it.

When the status lines under the panes wrap to more rows, the map stays where it was (placed in
the room they left at their least) while the rows under it that they take were blank.
"""

# No future import: CONTRIBUTING.md, "Start-up".
import math
from collections.abc import Callable
from typing import TYPE_CHECKING, NamedTuple

from tui_search.engine.maps.grid import Grid
from tui_search.tui.view.geometry import Geometry

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph

#: Panes stand side by side while each is at least this wide (else in a grid of fewer
#: columns), and are fitted to at least this many lines when a grid is chosen.
PANE_MIN_WIDTH, PANE_MIN_HEIGHT = 50, 16
#: The lists (frontier and tree) need this many lines under a map, and a column beside one
#: this wide (at most LISTS_MAX_WIDTH, else 40 % of the pane).
LISTS_MIN_HEIGHT, LISTS_MIN_WIDTH, LISTS_MAX_WIDTH = 6, 38, 56
#: The trees show under a map when the lists get at least this many lines; beside it, when
#: the column has this many (the frontier takes a third of it: its border, its count line and
#: an entry at least).
TREES_MIN_HEIGHT, TREES_BESIDE_MIN_HEIGHT = 9, 12
#: The Code panel (in the trees' place) needs fewer: its border and a few lines, the lit one
#: and its neighbours, where the lists get at least this many lines.
CODE_MIN_HEIGHT = 5
#: Beside the lists, a map that cannot fit whole gets at least this many columns.
MAP_MIN_WIDTH = 20
#: With the Code panel, the lists' column beside the map takes the columns the map's cells
#: leave blank, up to this many: the default pseudocode's widest line unwrapped (72), with
#: the panel's border, padding and scrollbar.
CODE_COLUMN_WIDTH = 80
#: A pane's own status lines share the map's column beside the lists: at least this wide.
STATS_MIN_WIDTH = 40
#: A pane's own status lines (its search's figures and narration).
PANE_STATS_HEIGHT = 2
#: The columns between two panes side by side (app.tcss: ``#panes``' grid-gutter).
GUTTER = 1
#: Where no arrangement shows the whole map, one whose map box has at least this many lines
#: (its border and three rows; the whole map if shorter) is taken before any other: a pane
#: with no room for its map is no choice while the map could show in part.
MAP_MIN_LINES = 5


def own_lines(n: int) -> bool:
    """Whether each of ``n`` panes may have status lines of its own, and the screen the
    comparison table and the lockstep's lines under them: the layout's one rule over the
    number of panes.  One pane's lines are the screen's own, and one search has nothing to
    be compared with."""
    return n > 1  # rule over N: what one pane shows under the map, several in each pane


class Arrangement(NamedTuple):
    """How ``n`` panes are laid out: a ``columns`` x ``rows`` grid of panes; each pane's map
    box gets ``map_height`` lines (0: all that is left), its lists ``lists_height`` (0: none),
    or a column ``lists_width`` wide beside the map (``beside``)."""

    columns: int
    rows: int
    table: bool  # the comparison table under the panes
    pane_stats: bool
    beside: bool
    lists_width: int
    lists_height: int
    trees: bool
    map_height: int
    fits: bool  # the whole map is in view at the smallest cells
    pane_width: int = 0
    map_max_height: int = 0  # the map's box is taller than the pane by rows under the map
    # kept blank: the map is at most this tall, so it stays in view (0: as tall as its box)
    code: bool = False  # room for the Code panel in the trees' place: CODE_MIN_HEIGHT lines

    @property
    def lists(self) -> bool:
        return self.beside or self.lists_height > 0


def pane_grid(n: int, width: int, height: int) -> tuple[int, int]:
    """Columns and rows for ``n`` panes in ``width`` x ``height``: side by side while each
    gets PANE_MIN_WIDTH columns; else the grid whose panes come closest to that width and to
    PANE_MIN_HEIGHT lines (two by two, or one above the other in a narrow terminal, beside
    each other again in a short one)."""
    if width // n >= PANE_MIN_WIDTH:
        return n, 1

    def fit(columns: int) -> float:
        rows = -(-n // columns)
        return min(width / columns / PANE_MIN_WIDTH, height / rows / PANE_MIN_HEIGHT)

    columns = max(range(1, n + 1), key=lambda c: (fit(c), -abs(c - -(-n // c))))
    return columns, -(-n // columns)


def lists_width(pane_width: int) -> int:
    return max(LISTS_MIN_WIDTH, min(LISTS_MAX_WIDTH, pane_width * 2 // 5))


def arrange(n: int, width: int, height: int, map_size: tuple[int, int], *,
            table_height: int = 0, fold_trees: bool = False,
            stats_height: int = PANE_STATS_HEIGHT, wrapped: int = 0,
            code: bool = False, folded: tuple[int, int] | None = None,
            stats_rows: Callable[[int], int] | None = None) -> Arrangement:
    """Lay ``n`` panes out in ``width`` x ``height`` (the room under and beside the fixed
    lines, the table's ``table_height`` lines included when there is one) for a map of
    ``map_size`` cells, whose smallest cells are 2 characters by 1 line, in a border; a
    pane's own status lines take ``stats_height`` lines.  The status lines under the panes
    take ``wrapped`` rows more than their least: the map is placed as in the room they would
    leave (:func:`_steady`).  With ``code`` (the Code panel in the trees' place) the lists
    under a map need only CODE_MIN_HEIGHT lines.

    ``height`` and ``wrapped`` are for the status lines under the panes as they are where the
    panes have lines of their own; ``folded`` (rows more, rows beyond their least) is what
    those lines take where the panes' own lines fold (they then say each search's counts, a
    line more).  Each choice is fitted to the rows its own lines take, so the choice made is
    the one made again once its lines are laid out (a layout that took the room the shorter
    lines leave, then lost it to the longer ones, flipped back and forth).  For the same
    reason ``stats_rows``, when given, says the lines the panes' own status lines take in a
    column that many characters wide (beside the lists they have the map's column only, and
    wrap to more rows); else they take ``stats_height`` whatever the width."""
    lists_min = CODE_MIN_HEIGHT if code else LISTS_MIN_HEIGHT
    candidates = []
    own = own_lines(n)
    for table in ((True, False) if table_height and own else (False,)):
        room = height - (table_height if table else 0)
        preferred = pane_grid(n, width, room)[0]
        # each pane's own status lines (where it has them) give way last
        for stats in ((stats_height, 0) if own else (0,)):
            more, wrap = folded if own and not stats and folded else (0, wrapped)
            for columns in range(1, n + 1):
                rows = -(-n // columns)
                pane_w = width // columns
                # the lines the pane's status lines take over the whole pane and beside the
                # lists, in the narrowest pane (the gutters take their columns)
                narrow = (width - GUTTER * (columns - 1)) // columns
                under_h, beside_h = ((stats_rows(narrow), stats_rows(narrow - lists_width(pane_w)))
                                     if stats and stats_rows else (stats, stats))
                pane_h = max(0, (room - more) // rows - under_h)
                pane = _pane(columns, rows, table, stats > 0, pane_w, pane_h, map_size,
                             fold_trees, lists_min, pane_h - beside_h + under_h, under_h, code)
                if wrap:
                    steady_h = max(0, (room - more + wrap) // rows - under_h)
                    steady = _pane(columns, rows, table, stats > 0, pane_w, steady_h,
                                   map_size, fold_trees, lists_min,
                                   steady_h - beside_h + under_h, under_h, code)
                    pane = _steady(steady, pane, steady_h, pane_h, map_size, fold_trees,
                                   lists_min, beside_h - under_h)
                shows = (pane.map_height or pane_h) >= min(map_size[1] + 2, MAP_MIN_LINES)
                candidates.append(((pane.fits, shows, pane.lists, pane.pane_stats or not own,
                                    pane.trees or fold_trees, columns == preferred, table),
                                   pane))
    # What gives way first: the table, then the grid's best proportions, then the trees,
    # then the panes' own status lines, then the lists; the map never (where it cannot show
    # whole, it keeps MAP_MIN_LINES before the rest keep theirs).
    return max(candidates, key=lambda ranked: ranked[0])[1]


def _steady(steady: Arrangement, pane: Arrangement, steady_h: int, pane_h: int,
            map_size: tuple[int, int], fold_trees: bool, lists_min: int,
            beside_more: int) -> Arrangement:
    """``steady``, laid out in a pane ``steady_h`` lines tall, in the ``pane_h`` lines
    ``pane`` is laid out in, when the whole map still shows there at the same cells and
    place: the lists under the map give up the lines, or the map's box (the pane's height)
    overflows the pane by lines that were blank under the map; else ``pane``.  Beside the
    lists the pane's own status lines take ``beside_more`` lines more of the map's column."""
    if (pane.beside, pane.lists_height > 0) != (steady.beside, steady.lists_height > 0) \
            or not steady.fits:
        return pane
    more = steady_h - pane_h
    if steady.lists_height:  # the map's box keeps its height, the lists are shorter
        lists_h = steady.lists_height - more
        if lists_h < lists_min:
            return pane
        return Arrangement(*steady[:6], lists_h, lists_h >= TREES_MIN_HEIGHT and not fold_trees,
                           *steady[8:])
    # the map, centred in a box as tall as the steady pane: at most this tall, it ends above
    # the pane's end (a map zoomed in scrolls in that height)
    box_w = steady.pane_width - (steady.lists_width if steady.beside else 0)
    box_h = steady_h - (beside_more if steady.beside else 0)
    most = box_h - 2 * more
    if Geometry.fit(*map_size, box_w - 2, box_h - 2).size[1] + 2 > most:
        return pane
    return Arrangement(*steady[:8], box_h, *steady[9:11], most, pane.code)


def _pane(columns: int, rows: int, table: bool, pane_stats: bool, pane_w: int, pane_h: int,
          map_size: tuple[int, int], fold_trees: bool, lists_min: int,
          beside_h: int, own_h: int, code: bool = False) -> Arrangement:
    """One pane's inside: its lists beside the map when the pane is much wider than tall and
    the whole map fits beside them (or would not fit whole under them either); else under
    the map when there is room for both.  ``pane_h``: the lines under the pane's own status
    lines when they span the pane; ``beside_h``: beside the lists (they wrap to more rows
    in the map's column alone), the lines the map's column has under them; ``own_h``: the
    lines they take spanning the pane (the lists' column beside the map spans them too);
    ``code``: the Code panel in the trees' place (its lines are long: they wrap)."""
    map_w, map_h = map_size
    need_w, need_h = 2 * map_w + 2, map_h + 2  # the smallest cells, in a border
    side = lists_width(pane_w)
    beside_w = max(min(need_w, MAP_MIN_WIDTH), STATS_MIN_WIDTH if pane_stats else 0)
    if pane_w >= 3 * pane_h and pane_w - side >= beside_w:
        beside = Arrangement(columns, rows, table, pane_stats, True, side, 0,
                             not fold_trees and pane_h + own_h >= TREES_BESIDE_MIN_HEIGHT,
                             0, need_h <= beside_h and need_w <= pane_w - side, pane_w,
                             # the Code panel in the trees' place: 2fr of the column, the
                             # frontier's third keeping an entry in sight, as the trees'
                             code=pane_h + own_h >= TREES_BESIDE_MIN_HEIGHT)
        if beside.fits:
            if code:  # the columns the map's cells leave blank: the code's, up to its lines
                drawn = Geometry.fit(map_w, map_h, pane_w - side - 2, beside_h - 2).size[0] + 2
                wide = min(CODE_COLUMN_WIDTH, pane_w - max(drawn, beside_w))
                return Arrangement(columns, rows, table, pane_stats, True, max(side, wide), 0,
                                   beside.trees, 0, True, pane_w, code=beside.code)
            return beside
        under = _under(columns, rows, table, pane_stats, pane_w, pane_h, map_size, fold_trees,
                       lists_min, own_h, code)
        return under if under.fits else beside  # under the map when it shows whole there
    return _under(columns, rows, table, pane_stats, pane_w, pane_h, map_size, fold_trees,
                  lists_min, own_h, code)


def _under(columns: int, rows: int, table: bool, pane_stats: bool, pane_w: int, pane_h: int,
           map_size: tuple[int, int], fold_trees: bool, lists_min: int,
           own_h: int = 0, code: bool = False) -> Arrangement:
    """One pane's inside with its lists under the map (or none, or the map scrolling): at
    least ``lists_min`` lines; ``own_h``, the lines the pane's own status lines take above
    them; ``code``: the Code panel in the lists, whose long lines wrap: the map's box then
    has half the pane, not three fifths."""
    map_w, map_h = map_size
    need_w, need_h = 2 * map_w + 2, map_h + 2  # the smallest cells, in a border
    if need_h + lists_min <= pane_h:
        # The map's box: as tall as the map at the biggest cells that fit the pane's width
        # and three fifths of its height (half beside the Code panel's long lines, which
        # wrap) with its own status lines at their least (rows
        # more in them, wrapped, take from the lists, not from the map's cells); the lists
        # get the rest.
        share = (pane_h + own_h - min(own_h, PANE_STATS_HEIGHT)) * (5 if code else 6) // 10
        fitted = Geometry.fit(map_w, map_h, pane_w - 2, max(1, share - 2)).size[1]
        box_h = min(pane_h - lists_min, max(need_h, fitted + 2))
        lists_h = pane_h - box_h
        return Arrangement(columns, rows, table, pane_stats, False, 0, lists_h,
                           lists_h >= TREES_MIN_HEIGHT and not fold_trees, box_h,
                           need_w <= pane_w, pane_w, code=lists_h >= CODE_MIN_HEIGHT)
    if need_h <= pane_h:  # the whole map, without the lists
        return Arrangement(columns, rows, table, pane_stats, False, 0, 0, False, pane_h,
                           need_w <= pane_w, pane_w)
    # Too big to fit: the map scrolls (z: the overview); the lists keep their share.
    lists_h = pane_h * 2 // 5 if pane_h * 2 // 5 >= lists_min else 0
    return Arrangement(columns, rows, table, pane_stats, False, 0, lists_h,
                       lists_h >= TREES_MIN_HEIGHT and not fold_trees, pane_h - lists_h, False,
                       pane_w, code=lists_h >= CODE_MIN_HEIGHT)




#: Beside the map, what is under the frontier (the tree, the Code panel) keeps at least this
#: many lines of the column: its border and three.
UNDER_FRONTIER_MIN = 5


def frontier_lines(column: int, need: int) -> int | None:
    """The frontier's lines in the lists' column beside the map, ``column`` lines tall, above
    the tree or the Code panel: what its count and the entries down to the newest ``need``
    (its border included), so that those are in sight before the panel under it gets lines,
    while that one keeps UNDER_FRONTIER_MIN; None (a third, as app.tcss has it) when a third
    is enough, or when even those lines would not show them (the panel shows its front)."""
    if need <= column // 3 or need > column - UNDER_FRONTIER_MIN:
        return None
    return need


def board_size(board: "Grid | Graph") -> tuple[int, int]:
    """The map's size the layout plans for, in cells of 2 characters by 1 line: a grid's;
    for a graph (drawn to fill the room it is given) a size that grows with its nodes, from
    room for a few marks and names to a box that leaves the lists their share."""
    if isinstance(board, Grid):
        return board.width, board.height
    side = math.isqrt(max(0, len(board) - 1)) + 1
    return min(40, max(16, 6 * side)), min(20, max(12, 4 * side))


def lesson_width(screen_width: int) -> int:
    """The lesson's column beside the panes (``--lesson``): two fifths of the screen, 28
    columns at least and 56 at most."""
    return max(28, min(56, screen_width * 2 // 5))


__all__ = ["CODE_MIN_HEIGHT", "MAP_MIN_LINES", "Arrangement", "arrange", "frontier_lines",
           "lesson_width", "own_lines", "pane_grid"]

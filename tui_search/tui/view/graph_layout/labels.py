"""The names beside the marks and the costs beside the roads: where each goes so that none
covers another, a mark, or (where it can be helped) a road.

A name goes right of its mark (a blank between: ``● Arad``), else left, else above or below;
of the places free, the one that covers the fewest roads and sits nearest no other mark wins.
When some name finds no place, every name is cut to a shorter prefix -- never shorter than
it takes to tell it from every other name (``Ara`` for Arad, ``Bu`` if only Bucharest starts
with B) -- and the longest cut that places them all is kept; then each name is given back as
much of itself as fits where it is.  A name keeps a blank on either side, so two never run
together, and the blank after a name right of its mark is where the cursor's mark (``◀``)
goes.

A cost goes on its road, centred on a cell near the road's middle, where it covers no mark,
name or other cost (a blank kept on either side) and as few other roads as can be.

Positions are cells of the whole drawing: (column, row).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence

from rich.cells import cell_len

Cell = tuple[int, int]
#: Where a name may go, in order of preference: right of the mark, left, then above and below
#: it (centred, starting at the mark, ending at it) -- as the first cell's offset from the mark
#: for a name of ``n`` cells, and the blank that joins a name beside its mark to it.
PLACES: tuple[tuple[Callable[[int], Cell], str], ...] = (
    (lambda n: (1, 0), "right"), (lambda n: (-n - 1, 0), "left"),
    (lambda n: (-((n - 1) // 2), -1), ""), (lambda n: (-((n - 1) // 2), 1), ""),
    (lambda n: (0, -1), ""), (lambda n: (0, 1), ""), (lambda n: (1 - n, -1), ""),
    (lambda n: (1 - n, 1), ""),
)
#: What a step down the order of preference weighs, against a road cell covered.
RANK_WEIGHT = 0.25
#: What another node's mark right above or below a name weighs (the name might seem its).
NEAR_MARK_WEIGHT = 0.75
#: How many cells near a road's middle a cost is tried at.
COST_TRIES = 9


def shown(name: str) -> str:
    """``name`` as it can be drawn: a character that is not one printable cell wide (a
    control character, a wide one) becomes ``?``."""
    if name.isprintable() and cell_len(name) == len(name):
        return name
    return "".join(ch if ch.isprintable() and cell_len(ch) == 1 else "?" for ch in name)


def unique_lengths(names: Sequence[str]) -> list[int]:
    """For each name, the shortest prefix that no other name starts with (the whole name
    when another name starts with it)."""
    order = sorted(range(len(names)), key=names.__getitem__)
    need = [1] * len(names)
    for a, b in zip(order, order[1:], strict=False):
        x, y = names[a], names[b]
        common = 0
        for cx, cy in zip(x, y, strict=False):
            if cx != cy:
                break
            common += 1
        need[a] = max(need[a], min(len(x), common + 1))
        need[b] = max(need[b], min(len(y), common + 1))
    return need


class Board:
    """What is where on the part of the drawing being laid out: the marks and the names and
    costs placed so far (``taken``: cell -> node, or ``-1 - road`` for a cost), the cells a road
    crosses (``roads``), and the bounds ``[x0, x1) x [y0, y1)``."""

    def __init__(self, marks: dict[Cell, int], roads: dict[Cell, list[int]],
                 bounds: tuple[int, int, int, int],
                 ends: tuple[Sequence[int], Sequence[int]] = ((), ())) -> None:
        self.marks = marks
        self.taken: dict[Cell, int] = dict(marks)
        self.roads = roads
        self.bounds = bounds
        self.ends = ends  # each road's two ends: its numbers' ``a`` and ``b``

    def inside(self, c: int, r: int) -> bool:
        x0, y0, x1, y1 = self.bounds
        return x0 <= c < x1 and y0 <= r < y1

    def free(self, col: int, row: int, length: int, owner: int) -> bool:
        """Can ``owner``'s text of ``length`` cells start at ``(col, row)``: inside, and with a
        blank either side, on no one else's mark, name or cost -- and no other mark two
        cells from either end (it would seem the text's own)?"""
        if not (self.inside(col, row) and self.inside(col + length - 1, row)):
            return False
        taken = self.taken
        for c in range(col - 1, col + length + 1):
            who = taken.get((c, row))
            if who is not None and who != owner:
                return False
        marks = self.marks
        return marks.get((col - 2, row), owner) == owner == marks.get((col + length + 1, row),
                                                                       owner)

    def put(self, col: int, row: int, text: str, owner: int) -> None:
        for i in range(len(text)):
            self.taken[(col + i, row)] = owner

    def lift(self, col: int, row: int, length: int) -> None:
        for i in range(length):
            del self.taken[(col + i, row)]

    def covered(self, col: int, row: int, length: int, node: int = -1, road: int = -1) -> int:
        """How many of the cells a text would cover have a road other than ``road`` and the
        roads of ``node`` (a name over its own node's road just seems to end it)."""
        roads, (a, b) = self.roads, self.ends
        return sum(1 for c in range(col, col + length)
                   if any(e != road and (node < 0 or node != a[e] and node != b[e])
                          for e in roads.get((c, row), ())))

    def near_marks(self, col: int, row: int, length: int, owner: int) -> int:
        """Other nodes' marks just above or below a text."""
        marks = self.marks
        return sum(1 for r in (row - 1, row + 1) for c in range(col, col + length)
                   if marks.get((c, r), owner) != owner)


def best_place(board: Board, node: int, mark: Cell, name: str) -> tuple[int, int, str] | None:
    """Where ``node``'s name goes beside its mark, as ``(column, row, text)`` (the text with
    the blank that joins it to the mark, beside it), or None when nowhere is free."""
    best: tuple[float, int, int, str] | None = None
    for rank, (offset, side) in enumerate(PLACES):
        text = " " + name if side == "right" else name + " " if side == "left" else name
        n = len(text)
        dc, dr = offset(len(name))
        col, row = mark[0] + dc, mark[1] + dr
        if not board.free(col, row, n, node):
            continue
        score = (board.covered(col, row, n, node=node) + rank * RANK_WEIGHT
                 + board.near_marks(col, row, n, node) * NEAR_MARK_WEIGHT)
        if best is None or score < best[0]:
            best = (score, col, row, text)
    return None if best is None else best[1:]


def place_names(board: Board, order: Sequence[int], marks: dict[int, Cell],
                names: Sequence[str], need: Sequence[int]) -> dict[int, tuple[int, int, str]]:
    """Each node's name (of ``order``, placed in that order) as ``(column, row, text)``; the
    longest cut of the names that places all of them (or the most), then each name as long
    as fits where it is.  ``need``: each name's shortest unique prefix."""
    longest = max((len(names[v]) for v in order), default=0)
    best: dict[int, tuple[int, int, str]] = {}
    cuts = sorted({min(len(names[v]), max(cut, need[v])) for v in order
                   for cut in range(1, longest + 1)}, reverse=True)
    tried: set[tuple[int, ...]] = set()
    for cut in cuts:
        lengths = tuple(min(len(names[v]), max(cut, need[v])) for v in order)
        if lengths in tried:
            continue
        tried.add(lengths)
        placed = _place_all(board, order, marks, names, lengths)
        if len(placed) > len(best):
            best = placed
        for col, row, text in placed.values():
            board.lift(col, row, len(text))
        if len(best) == len(order):
            break
    for v, (col, row, text) in best.items():
        board.put(col, row, text, v)
    for v in order:  # each name as long as it can be, where it is or elsewhere
        if v not in best or len(best[v][2].strip()) == len(names[v]):
            continue
        col, row, text = best[v]
        board.lift(col, row, len(text))
        for length in range(len(names[v]), len(text.strip()), -1):
            at = best_place(board, v, marks[v], names[v][:length])
            if at is not None:
                col, row, text = at
                break
        best[v] = (col, row, text)
        board.put(col, row, text, v)
    return best


def _place_all(board: Board, order: Sequence[int], marks: dict[int, Cell],
               names: Sequence[str], lengths: Sequence[int]) -> dict[int, tuple[int, int, str]]:
    """Names cut to ``lengths`` placed greedily in ``order`` (those that find room)."""
    placed = {}
    for v, length in zip(order, lengths, strict=True):
        at = best_place(board, v, marks[v], names[v][:length])
        if at is not None:
            placed[v] = at
            board.put(*at, v)
    return placed


def place_cost(board: Board, road: int, text: str, along: Sequence[Cell]) -> Cell | None:
    """Where road ``road``'s cost ``text`` goes: centred on one of the cells ``along`` (the
    road's cells, nearest its middle first), or None when none is free."""
    n = len(text)
    owner = -1 - road
    best: tuple[int, int, int, int] | None = None
    for i, (c, r) in enumerate(along[:COST_TRIES]):
        col = c - (n - 1) // 2
        if not board.free(col, r, n, owner):
            continue
        score = board.covered(col, r, n, road=road)
        if best is None or (score, i) < best[:2]:
            best = (score, i, col, r)
    if best is None:
        return None
    board.put(best[2], best[3], text, owner)
    return best[2], best[3]


def middle_first(cells: Iterable[Cell]) -> list[Cell]:
    """A road's cells from its middle outwards (the middle's left neighbour first)."""
    cells = list(cells)
    mid = (len(cells) - 1) / 2
    order = sorted(range(len(cells)), key=lambda i: abs(i - mid))
    return [cells[i] for i in order]


__all__ = ["Board", "best_place", "middle_first", "place_cost", "place_names", "shown",
           "unique_lengths"]

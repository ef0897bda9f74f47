"""Teaching text that wraps instead of being cut, as (text, component class) pieces: the
status lines, the readout and the comparison table are built of them without Textual
(:mod:`tui_search.tui.view.status_lines` builds the status lines) and drawn by
:class:`~tui_search.tui.widgets.wrapped_lines.PartsLines`.

A line is made of :class:`Piece` s: each is kept on one row when it fits (a count is never
split from its label), and goes to the next row whole when it does not; only a piece wider
than a row flows word by word, and only a word wider than a row is ever cut.  Prose (the
narration) flows word by word from piece to piece.  The separator between two pieces is
dropped at a row break.

At most ``max_rows`` rows (:func:`lay_out`): past that the pieces ranked least important go
first (the highest :attr:`Piece.rank`; rank 0 -- what the lesson is about -- never goes, and
takes more rows rather than be cut).

Redrawn on every step, so wrapping is O(pieces) (a line that fits is not split into words) and
is done once per text and width.
"""

# No future import: CONTRIBUTING.md, "Start-up".
import re
from typing import NamedTuple

from rich.cells import cell_len  # the widths Textual draws with (a pure function)

#: A line as (text, component class) pieces.
Parts = list[tuple[str, str]]

#: Words that only separate others: never the first word of a row (dropped at a break).
SEPARATORS = frozenset({"·", "│", "—"})
_TOKEN = re.compile(r" +|[^ ]+")


class Piece(NamedTuple):
    """Text kept on one row when it fits.  ``rank``: 0 never goes; else, when the rows run
    out, the highest rank goes first (or gives way to its ``short`` form, when it has one).
    ``lead`` goes before it when it follows another piece on the same row (a separator,
    dropped at a row break)."""

    parts: Parts
    rank: int = 0
    lead: tuple[str, str] | None = None
    short: Parts | None = None
    short_rank: int = 0  # the short form goes too, at this rank (0: it never goes)


class Line(NamedTuple):
    """A line of pieces, wrapped to as many rows as it needs; ``prose``: its words flow from
    piece to piece (a sentence), rather than each piece starting a row when it does not fit."""

    pieces: list[Piece]
    prose: bool = False


def plain(parts: Parts, prose: bool = False) -> Line:
    """A line of one piece."""
    return Line([Piece(parts)], prose)


def length(parts: Parts) -> int:
    """How many cells ``parts`` take."""
    return sum(cell_len(text) for text, _ in parts)


def _words(parts: Parts) -> list[tuple[Parts, Parts]]:
    """``parts`` as (spaces before, word) pairs, each keeping its pieces' classes."""
    words: list[tuple[Parts, Parts]] = []
    space: Parts = []
    word: Parts = []
    for text, cls in parts:
        for token in _TOKEN.findall(text):
            if token[0] == " ":
                if word:
                    words.append((space, word))
                    space, word = [], []
                space.append((token, cls))
            else:
                word.append((token, cls))
    if word:
        words.append((space, word))
    return words


def _split_word(word: Parts, width: int) -> list[Parts]:
    """A word wider than a row, cut into rows (the one text that is ever cut)."""
    rows: list[Parts] = [[]]
    used = 0
    for text, cls in word:
        for char in text:
            n = cell_len(char)
            if used + n > width and used:
                rows.append([])
                used = 0
            rows[-1].append((char, cls))
            used += n
    return rows


def wrap(line: Line, width: int, dropped: frozenset[int] = frozenset(),
         gone: frozenset[int] = frozenset()) -> list[Parts]:
    """The rows ``line`` takes in ``width`` cells, its pieces numbered in ``dropped`` left
    out (or in their short form), those in ``gone`` left out even so; an empty line is one
    empty row."""
    rows: list[Parts] = []
    row: Parts = []
    used = 0

    def flow(parts: Parts) -> None:
        nonlocal row, used
        for space, word in _words(parts):
            wlen, slen = length(word), length(space)
            separator = len(word) == 1 and word[0][0] in SEPARATORS
            if row and used + slen + wlen <= width:
                row += space + word
                used += slen + wlen
                continue
            if separator:  # not at the start of a row, nor past its end
                continue
            if row:
                rows.append(row)
            if wlen > width:
                *whole, row = _split_word(word, width)
                rows.extend(whole)
                used = length(row)
            else:
                row, used = list(word), wlen

    for i, piece in enumerate(line.pieces):
        parts = piece.parts
        if i in gone:
            continue
        if i in dropped:
            if piece.short is None:
                continue
            parts = piece.short
        plen = length(parts)
        lead = [piece.lead] if row and piece.lead else []
        llen = length(lead)
        if used + llen + plen <= width:
            row += lead + parts
            used += llen + plen
        elif line.prose:
            flow(lead + parts)
        else:
            if row:
                rows.append(row)
                row, used = [], 0
            if plen <= width:
                row, used = list(parts), plen
            else:
                flow(parts)
    rows.append(row)
    return rows


def lay_out(lines: list[Line], width: int, max_rows: int | None = None) -> list[Parts]:
    """The rows of ``lines`` in ``width`` cells, at most ``max_rows`` of them when dropping
    (or shortening) the pieces of rank above 0 (the highest first, the last of a rank first)
    gets there; a short form goes in its turn too, at its ``short_rank``."""
    width = max(1, width)
    wrapped = [wrap(line, width) for line in lines]
    total = sum(map(len, wrapped))
    if max_rows is not None and total > max_rows:
        # (rank, line, piece, 1: dropped or shortened, 0: its short form gone)
        droppable = sorted([(rank, i, j, stage) for i, line in enumerate(lines)
                            for j, piece in enumerate(line.pieces)
                            for rank, stage in ((piece.rank, 1), (piece.short_rank, 0))
                            if rank and (stage or piece.short)], reverse=True)
        dropped: list[set[int]] = [set() for _ in lines]
        gone: list[set[int]] = [set() for _ in lines]  # shortened, then gone whole
        best = (total, list(wrapped))
        for _, i, j, stage in droppable:
            (dropped if stage else gone)[i].add(j)
            wrapped[i] = wrap(lines[i], width, frozenset(dropped[i]), frozenset(gone[i]))
            total = sum(map(len, wrapped))
            if total < best[0]:  # a piece goes only when that saves a row
                best = (total, list(wrapped))
            if total <= max_rows:
                break
        wrapped = best[1]
    return [row for rows in wrapped for row in rows]


def text_of(parts: Parts) -> str:
    return "".join(text for text, _ in parts)


def line_text(pieces: list[Piece]) -> str:
    """The pieces as one unwrapped line of text."""
    return "".join(text_of(piece.parts if i == 0 or piece.lead is None
                           else [piece.lead, *piece.parts]) for i, piece in enumerate(pieces))

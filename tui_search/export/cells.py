"""The app's screen as rows of styled cells, read back from its own SVG screenshot.

Textual's public way to see what an app has drawn is :meth:`textual.app.App.export_screenshot`:
Rich's SVG of the screen, a ``<rect>`` for each run of cells with a background and a ``<text>``
for each run of characters, each at ``x = column * 12.2`` and ``y = row * 24.4`` (Rich's
``export_svg`` at its default font size) and with a CSS class for its colour and weight.  Read
back, it is the screen cell by cell -- every export (:mod:`~tui_search.export.svg`,
:mod:`~tui_search.export.cast`, :mod:`~tui_search.export.gif`) draws from the same cells, so
each is drawn like the app.  (Rich is pinned exactly in ``pyproject.toml``; the tests read the
screen back and compare it with the app's own text.)
"""

from __future__ import annotations

import re
from html import unescape
from typing import NamedTuple

from rich.cells import cell_len

#: Rich's SVG geometry at its default font size (``Console.export_svg``).
CHAR_WIDTH = 20 * 0.61
LINE_HEIGHT = 20 * 1.22
TEXT_BASELINE = 20  # a text's y, from its line's top
RECT_TOP = 1.5  # a background's y, from its line's top


class Look(NamedTuple):
    """How a cell is drawn: its colours as ``#rrggbb`` (reverse and dim already applied, as
    the screenshot resolves them) and its text styles."""

    fg: str
    bg: str
    bold: bool = False
    italic: bool = False
    underline: bool = False
    strike: bool = False


#: A cell: its character ("" for the right half of a wide one) and look.
Cell = tuple[str, Look]
Row = tuple[Cell, ...]
Screen = tuple[Row, ...]

_STYLE = re.compile(r"\.(terminal-[\w-]+?-r\d+) \{ ([^}]*) \}")
_RECT = re.compile(r'<rect fill="(#[0-9a-fA-F]{6})" x="([\d.]+)" y="([\d.]+)" '
                   r'width="([\d.]+)" height="[\d.]+" shape-rendering="crispEdges"/>')
_TEXT = re.compile(r'<text class="(terminal-[\w-]+?-r\d+)" x="([\d.]+)" y="([\d.]+)" '
                   r'textLength="[\d.]+" clip-path="[^"]*">(.*?)</text>', re.DOTALL)
_FILL = re.compile(r"fill: (#[0-9a-fA-F]{6})")
_TERMINAL_FILL = re.compile(r'<rect fill="(#[0-9a-fA-F]{6})" stroke=')


class ScreenshotError(ValueError):
    """The screenshot is not the SVG this module reads (a Rich that draws otherwise)."""


def read_screenshot(svg: str, width: int, height: int) -> Screen:
    """The ``width`` x ``height`` screen the screenshot ``svg`` shows, cell by cell."""
    styles = {name: rules for name, rules in _STYLE.findall(svg)}
    chrome = _TERMINAL_FILL.search(svg)
    if not styles or chrome is None:
        raise ScreenshotError("not a Rich SVG screenshot")
    default_bg = chrome.group(1).lower()
    bg = [[default_bg] * width for _ in range(height)]
    for fill, x, y, w in _RECT.findall(svg):
        row = round((float(y) - RECT_TOP) / LINE_HEIGHT)
        first = round(float(x) / CHAR_WIDTH)
        for col in range(first, min(width, first + round(float(w) / CHAR_WIDTH))):
            if 0 <= row < height:
                bg[row][col] = fill.lower()
    fg_default = "#c5c8c6"
    chars: list[list[str]] = [[" "] * width for _ in range(height)]
    looks: list[list[tuple[str, str] | None]] = [[None] * width for _ in range(height)]
    for name, x, y, text in _TEXT.findall(svg):
        row = round((float(y) - TEXT_BASELINE) / LINE_HEIGHT)
        col = round(float(x) / CHAR_WIDTH)
        if not 0 <= row < height or name not in styles:
            raise ScreenshotError(f"a text at row {row} with no style")
        for ch in unescape(text).replace("\xa0", " "):
            wide = cell_len(ch)
            if 0 <= col < width:
                chars[row][col] = ch
                looks[row][col] = (name, ch)
                if wide == 2 and col + 1 < width:
                    chars[row][col + 1] = ""
                    looks[row][col + 1] = (name, "")
            col += max(1, wide)
    cache: dict[tuple[str, str], Look] = {}

    def look(name: str | None, background: str) -> Look:
        key = (name or "", background)
        if key not in cache:
            rules = styles.get(name or "", "")
            fill = _FILL.search(rules)
            cache[key] = Look(fill.group(1).lower() if fill else fg_default, background,
                              "font-weight: bold" in rules, "font-style: italic" in rules,
                              "underline" in rules, "line-through" in rules)
        return cache[key]

    def at(r: int, c: int) -> Cell:
        styled = looks[r][c]
        return chars[r][c], look(styled[0] if styled is not None else None, bg[r][c])

    return tuple(tuple(at(r, c) for c in range(width)) for r in range(height))


def row_text(row: Row) -> str:
    """A row's characters, as a terminal shows them."""
    return "".join(ch for ch, _ in row)


def crop(screen: Screen, x: int, y: int, width: int, height: int) -> Screen:
    """The ``width`` x ``height`` part of ``screen`` at column ``x``, row ``y`` (a wide
    character cut in half shows as a space)."""
    rows = []
    for row in screen[y:y + height]:
        part = list(row[x:x + width])
        if part and part[0][0] == "":
            part[0] = (" ", part[0][1])
        if part and cell_len(part[-1][0]) == 2:
            part[-1] = (" ", part[-1][1])
        rows.append(tuple(part))
    return tuple(rows)


def runs(row: Row) -> list[tuple[int, int, str, Look]]:
    """A row as runs of one look: (first column, columns, text, look)."""
    out: list[tuple[int, int, str, Look]] = []
    for col, (ch, look) in enumerate(row):
        if out and out[-1][3] == look:
            first, n, text, _ = out[-1]
            out[-1] = (first, n + 1, text + ch, look)
        else:
            out.append((col, 1, ch, look))
    return out

"""A character of the app's screen drawn in a :data:`CELL` pixel box, for the GIF: Latin-1 in
Pillow's built-in bitmap font, the app's other characters as shapes -- box-drawing lines,
block elements, the map's and the panels' markers (``● ○ ◉ ◆ ▶ ◀ ★ ✗``), arrows -- and any
other one as the Latin-1 letters it decomposes to, or a small hollow box.

No shape is smoothed: a pixel is the character's colour or the background's.
"""

from __future__ import annotations

import unicodedata

from PIL import ImageDraw, ImageFont

#: A cell's pixels (Pillow's bitmap font is 6 x 11, set 1 in and 2 down).
CELL = (8, 16)
_W, _H = CELL
_MID_X, _MID_Y = _W // 2 - 1, _H // 2 - 1

#: Box-drawing lines: the arms from the middle (left, right, up, down), 1 light, 2 heavy.
_BOX = {
    "─": (1, 1, 0, 0), "━": (2, 2, 0, 0), "│": (0, 0, 1, 1), "┃": (0, 0, 2, 2),
    "┌": (0, 1, 0, 1), "┐": (1, 0, 0, 1), "└": (0, 1, 1, 0), "┘": (1, 0, 1, 0),
    "╭": (0, 1, 0, 1), "╮": (1, 0, 0, 1), "╰": (0, 1, 1, 0), "╯": (1, 0, 1, 0),
    "├": (0, 1, 1, 1), "┤": (1, 0, 1, 1), "┬": (1, 1, 0, 1), "┴": (1, 1, 1, 0),
    "┼": (1, 1, 1, 1), "╴": (1, 0, 0, 0), "╶": (0, 1, 0, 0), "╵": (0, 0, 1, 0),
    "╷": (0, 0, 0, 1), "┏": (0, 2, 0, 2), "┓": (2, 0, 0, 2), "┗": (0, 2, 2, 0),
    "┛": (2, 0, 2, 0), "═": (2, 2, 0, 0), "║": (0, 0, 2, 2),
}
#: Block elements as the box they fill, in eighths of the cell: (left, top, right, bottom).
_BLOCKS = {"█": (0, 0, 8, 8), "▀": (0, 0, 8, 4), "▄": (0, 4, 8, 8), "▌": (0, 0, 4, 8),
           "▐": (4, 0, 8, 8), "▔": (0, 0, 8, 1), "▕": (7, 0, 8, 8)}
_BLOCKS.update({chr(0x2581 + i): (0, 7 - i, 8, 8) for i in range(7)})  # ▁ ... ▇
_BLOCKS.update({chr(0x2589 + i): (0, 0, 7 - i, 8) for i in range(7)})  # ▉ ... ▏
#: Arrows as (dx, dy) from the middle.
_ARROWS = {"←": (-1, 0), "→": (1, 0), "↑": (0, -1), "↓": (0, 1), "↖": (-1, -1), "↗": (1, -1),
           "↘": (1, 1), "↙": (-1, 1)}


def draw_glyph(draw: ImageDraw.ImageDraw, font: ImageFont.ImageFont, ch: str, x: int,
               fill: int, bold: bool = False) -> None:
    """Draw ``ch`` in the cell at pixel column ``x`` (row 0 of ``draw``'s image)."""
    if ch == " ":
        return
    if ch in _BOX:
        _box(draw, x, _BOX[ch], fill)
    elif ch in _BLOCKS:
        left, top, right, bottom = _BLOCKS[ch]
        draw.rectangle((x + left * _W // 8, top * _H // 8, x + right * _W // 8 - 1,
                        bottom * _H // 8 - 1), fill=fill)
    elif ch in _ARROWS:
        _arrow(draw, x, _ARROWS[ch], fill)
    elif not _shape(draw, x, ch, fill):
        text = ch if _latin1(ch) else _decomposed(ch)
        if text is None:
            draw.rectangle((x + 2, 4, x + _W - 3, _H - 5), outline=fill)
            return
        for dx in (0, 1) if bold else (0,):
            draw.text((x + 1 + dx, 2), text[:1], fill=fill, font=font)


def _latin1(ch: str) -> bool:
    return ord(ch) < 256 and ch.isprintable()


def _decomposed(ch: str) -> str | None:
    """``ch`` as the Latin-1 it decomposes to (``⁸`` is ``8``), or None."""
    text = unicodedata.normalize("NFKD", ch)
    return text if text and all(_latin1(c) for c in text) else None


def _box(draw: ImageDraw.ImageDraw, x: int, arms: tuple[int, int, int, int], fill: int
         ) -> None:
    left, right, up, down = arms
    cx, cy = x + _MID_X, _MID_Y
    for weight, box in ((left, (x, cy, cx, cy)), (right, (cx, cy, x + _W - 1, cy)),
                        (up, (cx, 0, cx, cy)), (down, (cx, cy, cx, _H - 1))):
        if weight:
            x0, y0, x1, y1 = box
            grow = weight - 1  # heavy: one pixel more across
            draw.rectangle((x0, y0, x1 + (grow if x0 == x1 else 0),
                            y1 + (grow if y0 == y1 else 0)), fill=fill)


def _arrow(draw: ImageDraw.ImageDraw, x: int, way: tuple[int, int], fill: int) -> None:
    dx, dy = way
    cx, cy = x + _MID_X, _MID_Y
    reach = 3
    tip = (cx + dx * reach, cy + dy * reach)
    draw.line((cx - dx * reach, cy - dy * reach, *tip), fill=fill)
    # the head: two short strokes back from the tip, each turned 45 degrees
    for hx, hy in ((dx - dy, dy + dx), (dx + dy, dy - dx)):
        sx, sy = (hx > 0) - (hx < 0), (hy > 0) - (hy < 0)  # their signs
        draw.line((tip[0], tip[1], tip[0] - 2 * sx, tip[1] - 2 * sy), fill=fill)


def _shape(draw: ImageDraw.ImageDraw, x: int, ch: str, fill: int) -> bool:
    """The markers and dots drawn as shapes; False for a character that is none of them."""
    cx, cy = x + _MID_X, _MID_Y
    if ch in "●•◉○◯":
        r = 1 if ch == "•" else 3
        if ch in "○◯◉":
            draw.ellipse((cx - r, cy - r, cx + r + 1, cy + r + 1), outline=fill)
            if ch == "◉":
                draw.rectangle((cx, cy, cx + 1, cy + 1), fill=fill)
        else:
            draw.ellipse((cx - r, cy - r, cx + r + 1, cy + r + 1), fill=fill)
    elif ch in "◆◇":
        points = [(cx, cy - 4), (cx + 4, cy), (cx, cy + 4), (cx - 4, cy)]
        draw.polygon(points, fill=fill if ch == "◆" else None, outline=fill)
    elif ch in "■□▪":
        r = 2 if ch == "▪" else 3
        box = (cx - r, cy - r, cx + r, cy + r)
        draw.rectangle(box, fill=None if ch == "□" else fill, outline=fill)
    elif ch in "▶►▷▸":
        draw.polygon([(cx - 3, cy - 4), (cx + 3, cy), (cx - 3, cy + 4)], fill=fill)
    elif ch in "◀◄◁◂":
        draw.polygon([(cx + 3, cy - 4), (cx - 3, cy), (cx + 3, cy + 4)], fill=fill)
    elif ch in "▲△":
        draw.polygon([(cx - 4, cy + 3), (cx, cy - 3), (cx + 4, cy + 3)], fill=fill)
    elif ch in "▼▽":
        draw.polygon([(cx - 4, cy - 3), (cx, cy + 3), (cx + 4, cy - 3)], fill=fill)
    elif ch in "★☆":
        draw.polygon([(cx, cy - 5), (cx + 1, cy - 1), (cx + 4, cy - 1), (cx + 2, cy + 1),
                      (cx + 3, cy + 5), (cx, cy + 2), (cx - 3, cy + 5), (cx - 2, cy + 1),
                      (cx - 4, cy - 1), (cx - 1, cy - 1)], fill=fill)
    elif ch in "✗✘✕×✂":
        draw.line((cx - 3, cy - 3, cx + 3, cy + 3), fill=fill)
        draw.line((cx - 3, cy + 3, cx + 3, cy - 3), fill=fill)
    elif ch in "✓✔":
        draw.line((cx - 3, cy, cx - 1, cy + 3), fill=fill)
        draw.line((cx - 1, cy + 3, cx + 3, cy - 3), fill=fill)
    elif ch in "⋮…":
        for i in (-3, 0, 3):
            dot = (cx, cy + i) if ch == "⋮" else (cx + i, cy + 3)
            draw.point(dot, fill=fill)
    else:
        return False
    return True

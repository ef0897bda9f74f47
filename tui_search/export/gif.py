"""An animated GIF of a run, with Pillow (the ``gif`` extra: ``pip install -e '.[gif]'``).

Each cell of the app's screen (:mod:`~tui_search.export.cells`) is a :data:`CELL` pixel box in
its background colour with its character on it: Latin-1 in Pillow's own bitmap font (built
into Pillow, so every machine draws the same pixels), the app's other characters -- box
lines, blocks, dots, arrows, markers -- drawn as shapes (:mod:`~tui_search.export.glyphs`).
Nothing is smoothed, so the picture holds only the screen's own colours, each an entry of
one palette: the same run gives the same bytes.
"""

from __future__ import annotations

from collections import Counter
from io import BytesIO

from PIL import Image, ImageDraw, ImageFont

from tui_search.export.cells import Row, runs
from tui_search.export.frames import Film
from tui_search.export.glyphs import CELL, draw_glyph

#: Colours a GIF's palette holds.
PALETTE_SIZE = 256


def _palette(film: Film) -> dict[str, int]:
    """Every colour of the film, the most used first, to its palette index (past 256: the
    nearest of the first 256)."""
    counts: Counter[str] = Counter()
    for screen in film.frames:
        for row in screen:
            for _ch, look in row:
                counts[look.bg] += 1
                counts[look.fg] += 1
    ranked = [colour for colour, _ in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))]
    kept = ranked[:PALETTE_SIZE]
    index = {colour: i for i, colour in enumerate(kept)}
    for colour in ranked[PALETTE_SIZE:]:
        index[colour] = min(range(len(kept)), key=lambda i: _distance(colour, kept[i]))
    return index


def _rgb(colour: str) -> tuple[int, int, int]:
    return int(colour[1:3], 16), int(colour[3:5], 16), int(colour[5:7], 16)


def _distance(a: str, b: str) -> int:
    return sum((x - y) ** 2 for x, y in zip(_rgb(a), _rgb(b), strict=True))


def _row_image(row: Row, index: dict[str, int], flat: list[int],
               font: ImageFont.ImageFont) -> Image.Image:
    """One row of cells, drawn."""
    w, h = CELL
    image = Image.new("P", (len(row) * w, h), 0)
    image.putpalette(flat)
    draw = ImageDraw.Draw(image)
    for first, n, text, look in runs(row):
        draw.rectangle((first * w, 0, (first + n) * w - 1, h - 1), fill=index[look.bg])
        fg = index[look.fg]
        col = first
        for ch in text:
            if ch == "":
                continue
            draw_glyph(draw, font, ch, col * w, fg, look.bold)
            col += 1
        if look.underline:
            draw.line((first * w, h - 2, (first + n) * w - 1, h - 2), fill=fg)
        if look.strike:
            draw.line((first * w, h // 2, (first + n) * w - 1, h // 2), fill=fg)
    return image


def gif_of(film: Film, fps: float, hold: float) -> bytes:
    """``film`` as an animated GIF, ``fps`` frames a second (to GIF's hundredths), the last
    held ``hold`` seconds more, looping."""
    index = _palette(film)
    colours = sorted(index, key=lambda c: index[c])[:PALETTE_SIZE]
    flat = [v for colour in colours for v in _rgb(colour)]
    flat += [0] * (3 * PALETTE_SIZE - len(flat))
    font = ImageFont.load_default_imagefont()
    w, h = CELL
    drawn: dict[Row, Image.Image] = {}
    images = []
    for screen in film.frames:
        image = Image.new("P", (film.width * w, film.height * h), 0)
        image.putpalette(flat)
        for y, row in enumerate(screen):
            if row not in drawn:
                drawn[row] = _row_image(row, index, flat, font)
            image.paste(drawn[row], (0, y * h))
        images.append(image)
    step = max(20, round(100 / fps) * 10)  # GIF counts hundredths of a second
    durations = [step] * len(images)
    durations[-1] += round(hold * 100) * 10
    out = BytesIO()
    images[0].save(out, format="GIF", save_all=True, append_images=images[1:],
                   duration=durations, loop=0, optimize=False)
    return out.getvalue()

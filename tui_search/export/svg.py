"""An animated SVG of a run: the app's screen a step at a time, in one file that plays in any
browser with no script -- each frame shown in turn by SVG's own animation (SMIL ``<animate>``
of ``visibility``, discrete), looping, the last frame held a little longer.

Drawn as Rich draws the app's screenshots (the same font, cell size and window), from the
screens of :mod:`~tui_search.export.frames`.  What repeats is written once: each distinct
row is a ``<g>`` in ``<defs>``; frame 0 is drawn whole and each later frame only lays the rows
that differ from it over it (a row paints its whole width, so it hides the one under it).  A
viewer with no animation (a still renderer such as ``rsvg-convert``) shows frame 0.
"""

from __future__ import annotations

from html import escape

from rich.cells import cell_len

from tui_search.export.cells import CHAR_WIDTH, LINE_HEIGHT, Look, Row, Screen, runs
from tui_search.export.frames import Film

#: The window around the screen, as Rich draws it (``Console.export_svg``).
PAD_LEFT, PAD_TOP, PAD_RIGHT, PAD_BOTTOM = 9, 41, 9, 9
CHROME = "#292929"
TITLE_FILL = "#c5c8c6"
BASELINE = 18.5  # a row's text, from the row's top (Rich's 20, less its rows' 1.5)
#: A row's backgrounds overlap the next row's a little, as Rich's do: no seam between them.
ROW_HEIGHT = "24.65"
_CDN = "https://cdnjs.cloudflare.com/ajax/libs/firacode/6.2.0/woff2/FiraCode"
FONT = f"""
    @font-face {{
        font-family: "Fira Code";
        src: local("FiraCode-Regular"), url("{_CDN}-Regular.woff2") format("woff2");
        font-style: normal;
        font-weight: 400;
    }}
    @font-face {{
        font-family: "Fira Code";
        src: local("FiraCode-Bold"), url("{_CDN}-Bold.woff2") format("woff2");
        font-style: bold;
        font-weight: 700;
    }}
    .m {{ font-family: Fira Code, monospace; font-size: 20px;
          font-variant-east-asian: full-width; }}
    .t {{ font-size: 18px; font-weight: bold; font-family: arial; }}
    rect {{ shape-rendering: crispEdges; }}"""


def _number(value: float) -> str:
    """A coordinate, the same bytes every time: at most two decimals, no trailing zeros."""
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return text if text != "-0" else "0"


class _Styles:
    """The CSS classes of the text looks and of the backgrounds, numbered in the order first
    met."""

    def __init__(self) -> None:
        self.names: dict[tuple[str, bool, bool, bool, bool], str] = {}
        self.fills: dict[str, str] = {}

    def fill(self, colour: str) -> str:
        if colour not in self.fills:
            self.fills[colour] = f"b{len(self.fills)}"
        return self.fills[colour]

    def of(self, look: Look) -> str:
        key = (look.fg, look.bold, look.italic, look.underline, look.strike)
        if key not in self.names:
            self.names[key] = f"s{len(self.names)}"
        return self.names[key]

    def css(self) -> str:
        rules = []
        for (fg, bold, italic, underline, strike), name in self.names.items():
            rule = [f"fill:{fg}"]
            if bold:
                rule.append("font-weight:bold")
            if italic:
                rule.append("font-style:italic")
            lines = [d for d, on in (("underline", underline), ("line-through", strike)) if on]
            if lines:
                rule.append(f"text-decoration:{' '.join(lines)}")
            rules.append(f".{name}{{{';'.join(rule)}}}")
        rules += [f".{name}{{fill:{colour}}}" for colour, name in self.fills.items()]
        return "\n".join(rules)


def _row_body(row: Row, styles: _Styles) -> str:
    """A row drawn at y 0: its backgrounds (every cell, so it hides a row under it), then its
    text, a run of one look an element."""
    parts = []
    for first, n, _text, bg in _bg_runs(row):
        parts.append(f'<rect class="{styles.fill(bg)}" x="{_number(first * CHAR_WIDTH)}" '
                     f'width="{_number(n * CHAR_WIDTH)}" height="{ROW_HEIGHT}"/>')
    for first, _n, text, look in runs(row):
        # Each character at its cell, as a terminal draws it (a font a little wider or
        # narrower than the cell never shifts the next); a text never starts or ends with a
        # space (a renderer may drop it): the spaces are the background's.
        stripped = text.lstrip(" ")
        first += len(text) - len(stripped)
        text = stripped.rstrip(" ")
        if not text:
            continue
        xs, col = [], first
        for ch in text:
            xs.append(_number(col * CHAR_WIDTH))
            col += cell_len(ch)
        parts.append(f'<text class="{styles.of(look)}" x="{" ".join(xs)}" y="{BASELINE}">'
                     f'{escape(text).replace(" ", "&#160;")}</text>')
    return "".join(parts)


#: Columns a piece of a row, at least: each distinct piece is drawn once, and a frame lays
#: over the first only the pieces that differ from it.
PIECE = 20


def _pieces(row: Row) -> list[tuple[int, Row]]:
    """``row`` in pieces of about :data:`PIECE` columns, each (its first column, its cells),
    cut where a word is not: before a space or where the look changes (a renderer that does
    not place each character at its cell lets a text drift a little, which must not show as a
    gap inside a word), else :data:`PIECE` columns further on."""
    pieces, start, width = [], 0, len(row)
    while start < width:
        end = start + PIECE
        while end < min(width, start + 2 * PIECE) and not _cut(row, end):
            end += 1
        pieces.append((start, row[start:end]))
        start = end
    return pieces


def _cut(row: Row, col: int) -> bool:
    """May a piece end before column ``col``?"""
    (before, look_before), (here, look) = row[col - 1], row[col]
    return here != "" and (here == " " or before == " " or look != look_before)


def _bg_runs(row: Row) -> list[tuple[int, int, str, str]]:
    out: list[tuple[int, int, str, str]] = []
    for col, (_ch, look) in enumerate(row):
        if out and out[-1][3] == look.bg:
            first, n, _, bg = out[-1]
            out[-1] = (first, n + 1, "", bg)
        else:
            out.append((col, 1, "", look.bg))
    return out


def _visibility(i: int, frames: int, fps: float, hold: float) -> str:
    """Frame ``i``'s (``i`` > 0) animation: visible in its slot of the loop, hidden else."""
    total = frames / fps + hold
    begin = i / fps / total
    values, times = ["hidden", "visible"], ["0", f"{begin:.6f}"]
    if i < frames - 1:
        values.append("hidden")
        times.append(f"{(i + 1) / fps / total:.6f}")
    return (f'<animate attributeName="visibility" calcMode="discrete" dur="{total:.3f}s" '
            f'repeatCount="indefinite" values="{";".join(values)}" '
            f'keyTimes="{";".join(times)}"/>')


def svg_of(film: Film, fps: float, hold: float, frames: list[Screen] | None = None,
           description: str = "") -> str:
    """``film`` as one SVG (``frames``: these of its frames instead; one frame is a still
    picture), ``fps`` frames a second, the last held ``hold`` seconds more; ``description``
    is its ``<desc>`` (what a screen reader says of it)."""
    shown = film.frames if frames is None else frames
    styles = _Styles()
    defs: dict[Row, str] = {}

    def use(piece: Row, x: int, y: int) -> str:
        if piece not in defs:
            defs[piece] = f"r{len(defs)}"
        at = f' x="{_number(x * CHAR_WIDTH)}"' if x else ""
        return f'<use xlink:href="#{defs[piece]}"{at} y="{_number(y * LINE_HEIGHT)}"/>'

    base = [_pieces(row) for row in shown[0]]
    body = ['<g id="step-0">' + "".join(use(piece, x, y) for y, row in enumerate(base)
                                        for x, piece in row) + "</g>"]
    base_sets = [set(row) for row in base]
    for i, screen in enumerate(shown[1:], start=1):
        changed = "".join(use(piece, x, y) for y, row in enumerate(screen)
                          if row != shown[0][y]
                          for x, piece in _pieces(row) if (x, piece) not in base_sets[y])
        body.append(f'<g id="step-{i}" visibility="hidden">'
                    f"{_visibility(i, len(shown), fps, hold)}{changed}</g>")
    rows = "\n".join(f'<g id="{name}">{_row_body(row, styles)}</g>'
                     for row, name in defs.items())
    width = film.width * CHAR_WIDTH + PAD_LEFT + PAD_RIGHT
    height = film.height * LINE_HEIGHT + PAD_TOP + PAD_BOTTOM
    title = escape(film.title)
    frames_said = "one frame" if len(shown) == 1 else f"{len(shown)} frames"
    return "\n".join([
        f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
        f'viewBox="0 0 {_number(width)} {_number(height)}" role="img">',
        f"<title>{title} ({frames_said}, tui-search)</title>",
        f"<desc>{escape(description)}</desc>" if description else "",
        f"<style>{FONT}\n{styles.css()}\n</style>",
        f"<defs>\n{rows}\n</defs>",
        f'<rect fill="{CHROME}" stroke="rgba(255,255,255,0.35)" stroke-width="1" x="1" y="1" '
        f'width="{_number(width - 2)}" height="{_number(height - 2)}" rx="8"/>',
        f'<text class="t" fill="{TITLE_FILL}" text-anchor="middle" x="{_number(width / 2)}" '
        f'y="27">{title}</text>',
        '<g transform="translate(26,22)"><circle cx="0" cy="0" r="7" fill="#ff5f57"/>'
        '<circle cx="22" cy="0" r="7" fill="#febc2e"/>'
        '<circle cx="44" cy="0" r="7" fill="#28c840"/></g>',
        f'<g class="m" transform="translate({PAD_LEFT},{PAD_TOP})">',
        *body,
        "</g>",
        "</svg>",
        "",
    ])

"""An asciicast v2 recording of a run (asciinema's format: ``asciinema play``, the asciinema
web player): a JSON header line, then one ``[time, "o", data]`` event a frame -- the terminal
output that draws the app's screen at that step.

The first frame clears the screen and draws every row; each later one moves the cursor to
the rows that changed since the frame before and redraws only them, as a terminal app
does.  Colours are 24-bit SGR sequences.  Times come from ``--fps`` alone (frame ``k`` at
``k / fps`` seconds) and the header has no timestamp: the same run gives the same bytes.
"""

from __future__ import annotations

import json

from tui_search.export.cells import Look, Row, runs
from tui_search.export.frames import Film

#: Hide the cursor, clear the screen, home; and at the end: attributes off, cursor shown.
START, END = "\x1b[?25l\x1b[2J\x1b[H", "\x1b[0m\x1b[?25h"


def _rgb(colour: str) -> str:
    return ";".join(str(int(colour[i:i + 2], 16)) for i in (1, 3, 5))


def sgr(look: Look) -> str:
    """The SGR sequence that sets ``look`` from scratch."""
    codes = ["0"]
    codes += [code for code, on in (("1", look.bold), ("3", look.italic), ("4", look.underline),
                                    ("9", look.strike)) if on]
    codes += [f"38;2;{_rgb(look.fg)}", f"48;2;{_rgb(look.bg)}"]
    return f"\x1b[{';'.join(codes)}m"


def row_output(row: Row, y: int) -> str:
    """What draws ``row`` as line ``y`` (0-based): the cursor to its start, then its runs."""
    text = "".join(sgr(look) + chars for _first, _n, chars, look in runs(row))
    return f"\x1b[{y + 1};1H{text}\x1b[0m"


def cast_of(film: Film, fps: float, hold: float) -> str:
    """``film`` as an asciicast v2 file, ``fps`` frames a second, the last held ``hold``
    seconds more."""
    header = {"version": 2, "width": film.width, "height": film.height, "title": film.title,
              "env": {"TERM": "xterm-256color"}}
    lines = [json.dumps(header)]
    before: tuple[Row, ...] | None = None
    for k, screen in enumerate(film.frames):
        changed = [row_output(row, y) for y, row in enumerate(screen)
                   if before is None or row != before[y]]
        data = (START if before is None else "") + "".join(changed)
        lines.append(json.dumps([round(k / fps, 6), "o", data]))
        before = screen
    end = round((len(film.frames) - 1) / fps + hold, 6)
    lines.append(json.dumps([end, "o", END]))
    return "\n".join(lines) + "\n"

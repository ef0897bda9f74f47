"""The map's drawing codes: what a cell is drawn as (a search state, or what the grid says),
its glyph, its name and its rank in a block of the overview.  The map, the legend and the help
screen draw from the same table (no Textual or Rich here: plain data)."""

from __future__ import annotations

# Drawing codes: the search states of a free cell (CellState's values), then what the grid says,
# then a bidirectional search's own (its backward half's states, a cell both halves reached,
# the best meeting so far).
FREE, FRONTIER, EXPANDED, CURRENT, PATH, WALL, START, GOAL = range(8)
BACK_FRONTIER, BACK_EXPANDED, BACK_CURRENT, BOTH, MEETING = range(8, 13)
COMPONENTS = ("free", "frontier", "expanded", "current", "path", "wall", "start", "goal",
              "back-frontier", "back-expanded", "back-current", "both", "meeting")
#: Two columns per cell; a distinct glyph per kind so the map reads in monochrome (the
#: backward half's squares beside the forward's circles).
GLYPHS = ("· ", "○ ", "● ", "◉ ", "◆ ", "██", "S ", "G ", "□ ", "■ ", "▣ ", "◐ ", "✦ ")
NAMES = ("free", "frontier (generated)", "expanded", "being expanded", "path", "obstacle",
         "start", "goal", "frontier backward", "expanded backward",
         "being expanded backward", "reached both ways", "best meeting")
#: The kinds a one-way search draws (the legend's and the help's; the others are a
#: bidirectional search's).
ONE_WAY = 8
UPPER_HALF = "▀"
#: The cursor: drawn beside the glyph of the cell under it, pointing at it, so the cell keeps
#: its own colours (the start stays green under the cursor at step 0).
CURSOR_MARK = "◀"
#: A big cell under the cursor: a bar along its last line (in the blanks: what it says kept).
CURSOR_BAR = "▂"
#: What draws a block of the overview: the code of highest rank in it.  Start and goal first
#: (one cell each, they would vanish in a block otherwise), then the best meeting, path >
#: node being expanded > frontier > expanded > obstacle > free (the backward half's just
#: under the forward's, a cell reached both ways above either).
RANK = {START: 12, GOAL: 11, MEETING: 10, PATH: 9, CURRENT: 8, BACK_CURRENT: 7, BOTH: 6,
        FRONTIER: 5, BACK_FRONTIER: 4, EXPANDED: 3, BACK_EXPANDED: 2, WALL: 1, FREE: 0}
BY_RANK = sorted(RANK, key=RANK.__getitem__)

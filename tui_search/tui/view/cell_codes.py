"""The map's drawing codes: what a cell is drawn as (a search state, or what the grid says),
its glyph, its name and its rank in a block of the overview.  The map, the legend and the help
screen draw from the same table (no Textual or Rich here: plain data)."""

from __future__ import annotations

# Drawing codes: the search states of a free cell (CellState's values), then what the grid says.
FREE, FRONTIER, EXPANDED, CURRENT, PATH, WALL, START, GOAL = range(8)
COMPONENTS = ("free", "frontier", "expanded", "current", "path", "wall", "start", "goal")
#: Two columns per cell; a distinct glyph per kind so the map reads in monochrome.
GLYPHS = ("· ", "○ ", "● ", "◉ ", "◆ ", "██", "S ", "G ")
NAMES = ("free", "frontier (generated)", "expanded", "being expanded", "path", "obstacle",
         "start", "goal")
UPPER_HALF = "▀"
#: The cursor: drawn beside the glyph of the cell under it, pointing at it, so the cell keeps
#: its own colours (the start stays green under the cursor at step 0).
CURSOR_MARK = "◀"
#: A big cell under the cursor: a bar along its last line (in the blanks: what it says kept).
CURSOR_BAR = "▂"
#: What draws a block of the overview: the code of highest rank in it.  Start and goal first
#: (one cell each, they would vanish in a block otherwise), then path > node being expanded >
#: frontier > expanded > obstacle > free.
RANK = {START: 7, GOAL: 6, PATH: 5, CURRENT: 4, FRONTIER: 3, EXPANDED: 2, WALL: 1, FREE: 0}
BY_RANK = sorted(RANK, key=RANK.__getitem__)

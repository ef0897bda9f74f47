"""The by-hand screen's key table: every key it has, its hint and what it does (the key bar
and the help read it).

Taking an entry off, the arrows move the cursor and ``enter`` takes its entry; adding the
successors, the arrows add the cell one move that way from the entry taken off, and the
diagonals are the number pad's corners (``7 9 1 3``, or ``home pgup end pgdn`` as the pad
has them) -- ``8 6 2 4`` the straight moves -- so that every move has a key as on a
roguelike's keypad.  ``h`` is the hint here: the main screen's ``h`` (the cursor left, as
vim's) has no job on this screen, where the cursor waits while the successors are added.
"""

from __future__ import annotations

from textual.binding import Binding, BindingType

#: The moves of the keys that add a successor: a key's move.
MOVE_KEYS = {"8": "N", "9": "NE", "6": "E", "3": "SE", "2": "S", "1": "SW", "4": "W",
             "7": "NW", "home": "NW", "pageup": "NE", "end": "SW", "pagedown": "SE"}
#: The arrows' moves while adding successors.
ARROW_MOVES = {(0, -1): "N", (1, 0): "E", (0, 1): "S", (-1, 0): "W"}

#: What the key bar keeps when it is too narrow (see the main screen's table).
BY_HAND_IMPORTANCE = {"help": 10, "leave": 10, "take": 9, "hint": 8, "take_back": 7,
                      "undo": 7, "again": 4, "summary": 9}

KEYS: list[BindingType] = [
    Binding("up", "move(0,-1)", "Cursor up", show=False),
    Binding("down", "move(0,1)", "Cursor down", show=False),
    Binding("left", "move(-1,0)", "Cursor left", show=False),
    Binding("right", "move(1,0)", "Cursor right", show=False),
    *(Binding(key, f"add({move!r})", f"Add {move}", show=False,
              tooltip=f"Add the cell {move} of the entry taken off")
      for key, move in MOVE_KEYS.items()),
    # enter: "Take" while taking an entry off, "End step" while adding its successors,
    # "Summary" at the end (check_action shows the one that acts now).
    Binding("enter", "take", "Take", tooltip="Take the entry under the cursor off the frontier"),
    Binding("enter", "end_step", "End step",
            tooltip="The successors added are all of them: the step is made"),
    Binding("enter", "summary", "Summary", tooltip="The run's summary, and its replay"),
    Binding("backspace", "take_back", "Take back", tooltip="Take back the last successor added"),
    Binding("h", "hint", "Hint", tooltip="A hint: the entry or the cell, then why (h again)"),
    Binding("u", "undo", "Undo", tooltip="Put the entry taken off back, else undo the last step"),
    Binding("r", "again", "Again", show=False, tooltip="Start the run again from step 0"),
    Binding("t", "app.next_theme", "Theme", show=False, tooltip="Next colour theme"),
    Binding("question_mark", "help", "Help", key_display="?", tooltip="Help"),
    Binding("escape", "leave", "Leave", key_display="esc",
            tooltip="Leave by hand: back to the searches"),
    Binding("q", "quit", "Quit", show=False, tooltip="Quit"),
]

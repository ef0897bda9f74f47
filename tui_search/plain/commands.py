"""Plain mode's commands: what may be typed on a line, what each does (``help`` lists them),
and how a line is read -- the app's keys where a key is a letter (``n``, ``p``, ``1`` ... ``6``,
``c``, ``i``, ``x``, ``s``, ``g``, ``o``, ``h j k l``, ``q``), and words for the rest
(``end``, ``answer 2,1``, ``set order N,W,S,E``, ``describe row 3``, ``save as FILE``).
"""

from __future__ import annotations

from typing import NamedTuple

from tui_search.engine.search.registry import ALGORITHMS


class Command(NamedTuple):
    """A command: the words that call it (a letter is a key, matched as typed; a longer word
    in any case), how it is written, what it does, and the mode's method that does it."""

    words: tuple[str, ...]
    usage: str
    says: str
    action: str


_KEYS = ", ".join(f"{a.app_key} {a.short}" for a in ALGORITHMS.values())

COMMANDS: tuple[Command, ...] = (
    Command(("n", "next"), "n [COUNT]", "the next step (COUNT steps)", "next"),
    Command(("p", "prev", "previous", "back"), "p [COUNT]", "the step before", "prev"),
    Command(("home", "first"), "home", "step 0", "first"),
    Command(("end", "last"), "end", "the last step: the answer", "last"),
    Command(("play",), "play", "every step to the end, each said", "play"),
    Command(("r", "reset"), "r", "the searches again from step 0", "reset"),
    Command(tuple(a.app_key for a in ALGORITHMS.values()) + tuple(ALGORITHMS),
            "1 to 6, or a search's name", f"the search to run ({_KEYS}); comparing: add it "
            "or take it out", "algorithm"),
    Command(("c", "compare"), "c, or compare A,B",
            "the searches side by side in lockstep, or one again; compare bfs,ucs names them",
            "compare"),
    Command(("status", "where"), "status", "the step, the counts and the narration again",
            "status"),
    Command(("frontier", "queue", "stack"), "frontier", "the whole frontier, in order",
            "frontier"),
    Command(("tree",), "tree", "the search tree, a node a line", "tree"),
    Command(("v", "code"), "v", "the search's pseudocode, the lines the step ran marked",
            "code"),
    Command(("i", "quiz"), "i", "the quiz on or off: predict which node comes off next",
            "quiz"),
    Command(("answer", "enter"), "answer X,Y",
            "the quiz's answer: cell X,Y comes off next (no cell: the cursor's)", "answer"),
    Command(("x", "exercise"), "x, or exercise 1, 2 or off",
            "the exercises as live challenges, checked after every edit", "exercise"),
    Command((",", "settings"), ",", "the search settings in force", "settings"),
    Command(("set",), "set NAME VALUE",
            "change a setting: order, corners, visit, goal-test, tree-search, heuristic, "
            "compare", "set"),
    Command(("describe",), "describe map, row Y, column X, cell X,Y or around",
            "the map in words (also typed alone: map, row 3, column 2, cell 2,1, around)",
            "describe"),
    Command(("map",), "map", "every row of the map", "map"),
    Command(("row",), "row Y", "row Y, from the left", "row"),
    Command(("column", "col"), "column X", "column X, from the top", "column"),
    Command(("cell",), "cell [X,Y]", "what the searches know of a cell (the cursor's)",
            "cell"),
    Command(("around",), "around", "the cursor's cell and its eight neighbours", "around"),
    Command(("left", "h"), "left or h", "the cursor a cell left", "left"),
    Command(("right", "l"), "right or l", "the cursor a cell right", "right"),
    Command(("up", "k"), "up or k", "the cursor a cell up", "up"),
    Command(("down", "j"), "down or j", "the cursor a cell down", "down"),
    Command(("go", "cursor"), "go X,Y", "the cursor to cell X,Y", "go"),
    Command(("S",), "S", "the cursor to the start", "to_start"),
    Command(("G",), "G", "the cursor to the goal", "to_goal"),
    Command(("e",), "e", "the cursor to the node being expanded", "to_node"),
    Command(("s",), "s", "the start at the cursor", "place_start"),
    Command(("g",), "g", "the goal at the cursor", "place_goal"),
    Command(("o", "obstacle"), "o", "an obstacle at the cursor, or none", "obstacle"),
    Command(("b", "brush"), "b [COST or off]", "the terrain brush: its next cost, or COST",
            "brush"),
    Command(("m", "paint"), "m", "paint the brush's cost at the cursor", "paint"),
    Command(("u", "undo"), "undo", "undo the last edit of the map", "undo"),
    Command(("redo",), "redo", "redo the edit undone", "redo"),
    Command(("save",), "save, or save as FILE",
            "save the map to its file (only the cells edited change), or to a new FILE",
            "save"),
    Command(("open",), "open FILE", "open another map (with unsaved edits: asks first)",
            "open"),
    Command(("generate",), "generate KIND [WxH] [SEED]",
            "make a map: maze, prim, kruskal, division, rooms or random:P (asks first too)",
            "generate"),
    Command(("help", "?"), "help", "this list", "help"),
    Command(("q", "quit", "exit"), "q", "quit (with unsaved edits: asks first)", "quit"),
)

#: The app's keys that draw, not search: what plain mode says of them.
APP_ONLY = {
    "t": "Themes are colours: plain mode has none.",
    "z": "The map's zoom is the app's: here, map, row Y and column X say it all.",
    "[": "The map's zoom is the app's: here, map, row Y and column X say it all.",
    "]": "The map's zoom is the app's: here, map, row Y and column X say it all.",
    "a": "Cell labels are the app's: here, cell X,Y says what a cell is.",
    "f": "The search tree is never hidden here: tree lists it.",
    "space": "Plain mode does not play by the clock: play says every step to the end.",
}


def find(word: str) -> Command | None:
    """The command ``word`` calls (a letter as typed, a longer word in any case)."""
    for command in COMMANDS:
        if word in command.words:
            return command
    if len(word) > 1:
        lower = word.lower()
        for command in COMMANDS:
            if lower in command.words:
                return command
    return None


def help_lines() -> list[str]:
    """Every command, a line each."""
    return ["Commands, one a line (then press enter):",
            *(f"{c.usage}: {c.says}." for c in COMMANDS)]

"""The key table: every key of the main screen, its hint and what it does.

The key bar, the help screen and the command palette all read this table, so a key is
documented where it is bound.  ``check_action`` on the main screen greys out or hides the keys
that cannot act now.
"""

from __future__ import annotations

from textual.binding import Binding, BindingType

from tui_search.engine.search.registry import ALGORITHMS
from tui_search.tui.view.themes import THEMES

#: What the key bar keeps when it is too narrow for every hint: the highest; help and quit
#: always (the bar drops the lowest first).  Undo shows only once the map has an edit, and
#: then matters more than a reset (an edit resets anyway).
KEY_IMPORTANCE = {
    "help": 10, "quit": 10, "stop_seek": 9, "next": 8, "play": 7, "pause": 7, "algorithm": 6,
    "compare": 6, "undo": 5, "settings": 5, "reset": 4, "save": 3, "quiz": 2, "overview": 2,
    "zoom": 1, "paint": 5, "lesson": 9, "difference": 8,
    "pick": 7,  # the frontier panel's, while it has the focus in the quiz
    "by_hand": 2,
}
STEP = Binding.Group("Step", compact=True)
ZOOM = Binding.Group("Zoom", compact=True)
UNDO = Binding.Group("Undo/Redo", compact=True)
LESSON = Binding.Group("Lesson", compact=True)
ALGO = Binding.Group("/".join(a.tag for a in ALGORITHMS.values() if a.key_bar), compact=True)

KEYS: list[BindingType] = [
    Binding("up,k", "move(0,-1)", "Cursor up", show=False),
    Binding("down,j", "move(0,1)", "Cursor down", show=False),
    Binding("left,h", "move(-1,0)", "Cursor left", show=False),
    Binding("right,l", "move(1,0)", "Cursor right", show=False),
    Binding("n", "next", "Next", group=STEP, tooltip="Next step (one expansion)"),
    Binding("p", "prev", "Prev", group=STEP, tooltip="Previous step"),
    # One key, two hints: "Play" while paused, "Pause" while playing (check_action hides
    # the other, and a key runs the first of its bindings that is enabled).
    Binding("space", "play", "Play", tooltip="Play (at the last step: again from step 0)"),
    Binding("space", "pause", "Pause", tooltip="Pause"),
    Binding("plus", "faster", "Faster", show=False, key_display="+", tooltip="Faster"),
    Binding("minus", "slower", "Slower", show=False, key_display="-", tooltip="Slower"),
    Binding("home", "first", "First", show=False, tooltip="First step"),
    Binding("end", "last", "Last", show=False, tooltip="Last step: the answer"),
    Binding("escape", "stop_seek", "Stop", key_display="esc",
            tooltip="Stop computing the last step"),
    *(Binding(a.app_key, f"algorithm({a.key!r})", a.short, group=ALGO, tooltip=a.name,
              show=a.key_bar) for a in ALGORITHMS.values()),
    Binding("s", "place('start')", "Start", show=False, tooltip="Start at the cursor"),
    Binding("g", "place('goal')", "Goal", show=False, tooltip="Goal at the cursor"),
    Binding("o", "toggle_wall", "Wall", show=False, tooltip="Obstacle on/off at the cursor"),
    Binding("b", "brush", "Brush", show=False,
            tooltip="Terrain brush: the next cost (2, 3, 5, 9, 1 plain floor, off); a mouse "
            "drag paints it"),
    # Shown only while the brush is on, as "Paint cost 5" (the key bar says the brush).
    Binding("m", "paint", "Paint", tooltip="Paint the terrain brush's cost at the cursor"),
    # Shown once the map has an edit to undo or redo (the title says "modified" then too).
    Binding("ctrl+z", "undo", "Undo", group=UNDO,
            tooltip="Undo the last edit of the map (a mouse stroke is one edit)"),
    Binding("ctrl+y", "redo", "Redo", group=UNDO, tooltip="Redo the edit undone last"),
    Binding("c", "compare", "Compare",
            tooltip="Compare searches side by side in lockstep (again: one search)"),
    Binding("f", "fold_trees", "Trees", show=False,
            tooltip="Fold the search trees away (again: show them)"),
    Binding("v", "code", "Code", show=False,
            tooltip="Code panel: the search's pseudocode, the step's lines lit ▶ (again: "
            "the search tree)"),
    Binding("r", "reset", "Reset", tooltip="Restart the search at step 0"),
    Binding("comma", "settings", "Settings", key_display=",",
            tooltip="Search settings: moves, corners, visited, goal test, tree search"),
    Binding("z", "overview", "Whole map",
            tooltip="Overview: the whole map at once, a character a block of cells"),
    Binding("right_square_bracket", "zoom(1)", "Zoom in", group=ZOOM, key_display="]",
            tooltip="Bigger cells (the cursor's cell stays in view)"),
    Binding("left_square_bracket", "zoom(-1)", "Zoom out", group=ZOOM, key_display="[",
            tooltip="Smaller cells (out of the smallest: the whole map)"),
    Binding("a", "labels", "Labels", show=False,
            tooltip="Cell labels: arrows and depth/cost, depth/cost only, none"),
    # With a lesson open (--lesson), pgdn and pgup move between its sections instead (or
    # shift+right and shift+left, on a keyboard without them); shift+up and shift+down
    # scroll its text (the lesson never takes the focus: every other key is the app's).
    Binding("pagedown,shift+right", "lesson(1)", "Next section", group=LESSON,
            key_display="pgdn", tooltip="Lesson: the next section (or shift+right)"),
    Binding("pageup,shift+left", "lesson(-1)", "Section back", group=LESSON,
            key_display="pgup", tooltip="Lesson: the section before (or shift+left)"),
    Binding("shift+down", "lesson_scroll(1)", "Scroll lesson", show=False, key_display="⇧↓",
            tooltip="Lesson: scroll its text down"),
    Binding("shift+up", "lesson_scroll(-1)", "Scroll lesson back", show=False,
            key_display="⇧↑", tooltip="Lesson: scroll its text up"),
    Binding("pageup", "page(-1)", "Page up", show=False, key_display="pgup",
            tooltip="Cursor a page up"),
    Binding("pagedown", "page(1)", "Page down", show=False, key_display="pgdn",
            tooltip="Cursor a page down"),
    Binding("S", "jump('start')", "To start", show=False, tooltip="Cursor to the start"),
    Binding("G", "jump('goal')", "To goal", show=False, tooltip="Cursor to the goal"),
    Binding("e", "jump('current')", "To node", show=False,
            tooltip="Cursor to the node being expanded"),
    # Shown only in a replay (--replay) whose trace parts from its search.
    Binding("d", "difference", "Difference",
            tooltip="Replay: every pane to the step where your trace first differs from the "
            "search (again: back to where you were)"),
    Binding("i", "quiz", "Quiz", tooltip="Predict the next node: a quiz (again to stop)"),
    # H, not h: h is the cursor's left, as vim's (docs/01-keys.md, "By hand").
    Binding("H", "by_hand", "By hand", tooltip="By hand: you make each step of the search "
            "(take an entry off, add its successors), each checked at once"),
    Binding("enter", "answer", "Answer", show=False,
            tooltip="Quiz: the node under the cursor (or the frontier entry picked) "
            "comes off next"),
    Binding("x", "exercise", "Exercise", show=False,
            tooltip="The exercises as live challenges: --exercise FILE's, 1, 2, off"),
    Binding("t", "app.next_theme", "Theme", show=False,
            tooltip="Next colour theme: " + ", ".join(t.title.lower() for t in THEMES.values())),
    Binding("ctrl+s", "save", "Save", tooltip="Save the map"),
    Binding("w", "save_as", "Save as", show=False, tooltip="Save the map as a new file"),
    Binding("ctrl+o", "open", "Open", show=False, tooltip="Open a map…"),
    Binding("ctrl+n", "generate", "Generate", show=False,
            tooltip="Generate a map: maze (DFS carving its own maze), prim, kruskal, division, "
            "rooms or random:P, from a seed (asks first when there are unsaved edits)"),
    Binding("question_mark", "help", "Help", key_display="?", tooltip="Help"),
    Binding("q", "quit", "Quit", tooltip="Quit (asks first when there are unsaved edits)"),
]

"""The help screen (``?``): the keys, the colours and glyphs, and how BFS and DFS work in the
tutorial's words."""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Static

from tui_search.engine.search.registry import ALGORITHMS, BIDIRECTIONAL
from tui_search.tui.view.themes import THEMES
from tui_search.tui.widgets.grid_view import GridView

if TYPE_CHECKING:
    from tui_search.tui.widgets.graph_view import GraphView
from tui_search.tui.widgets.legend import Legend

#: The keys, grouped as a learner uses them (a test checks every binding is listed here).
_FIRST, *_, _LAST = ALGORITHMS.values()  # the keys that pick a search: 1 to 7
KEYS = (
    ("arrows  h j k l", "move the cursor"),
    ("s  g", "put the start / the goal at the cursor"),
    ("o", "obstacle on / off at the cursor"),
    ("b  m", "terrain brush: next cost (2 3 5 9 1 off) / paint it"),
    ("click, drag", "draw or erase obstacles (first cell decides), or the brush"),
    ("right-click", "move the cursor only"),
    ("ctrl+z  ctrl+y", "undo / redo an edit of the map (a mouse stroke is one edit)"),
    ("n  p", "next / previous step (one expansion)"),
    ("space", "play / pause (at the last step: again from step 0)"),
    ("+  -", "faster / slower"),
    ("home  end", "first / last step (the answer)"),
    ("esc", "stop computing the last step (on a big map)"),
    (" ".join(a.app_key for a in ALGORITHMS.values()),
     " / ".join(a.short for a in ALGORITHMS.values()) + " (a new search, same map)"),
    ("ctrl+p  ,", " / ".join(a.short for a in BIDIRECTIONAL.values())
     + ", bidirectional: no key; pick one in the palette, or tick it in the settings for c"),
    ("c", "compare searches side by side, in lockstep; "
          f"{_FIRST.app_key}-{_LAST.app_key} add / remove"),
    ("f", "fold the search trees away / show them"),
    ("v", "Code panel: the search's pseudocode, the step's lines lit ▶"),
    ("r", "restart the search at step 0"),
    (",", "settings: moves, corners, visit, goal test, tree, heuristic"),
    ("z", "the whole map at once: a character a block of cells"),
    ("]  [", "zoom in / out: bigger / smaller cells"),
    ("a", "cell labels: arrows and depth or cost, depth or cost, none"),
    ("pgup  pgdn", "cursor a page up / down; in a lesson: section back / next"),
    ("⇧←  ⇧→", "lesson: section back / next, as pgup / pgdn (⇧ is shift)"),
    ("⇧↑  ⇧↓", "lesson: scroll its text up / down"),
    ("S  G  e", "cursor to the start / the goal / the node being expanded"),
    ("mouse over", "the line under the map says what the run knows of that cell"),
    ("i  enter", "quiz: predict the node that comes off next (cursor, enter)"),
    ("click, tab ↑↓", "quiz: pick the frontier entry instead (double click: answer)"),
    ("x", "the exercises as live challenges: --exercise FILE's, 1, 2, off"),
    ("d", "--replay: to the step where your trace first differs / back"),
    ("t", "next colour theme: " + ", ".join(t.title.lower() for t in THEMES.values())),
    ("ctrl+s", "save the map (to its file, in its format)"),
    ("w", "save the map as … (asks before replacing a file)"),
    ("ctrl+o", "open a map … (asks first when there are unsaved edits)"),
    ("ctrl+n", "generate a maze (DFS carves it) or a random map, from a seed"),
    ("ctrl+p", "command palette: every command by name (algorithms, themes, …)"),
    ("", ("its Screenshot: a picture of the screen (SVG) in the current folder, which a "
     "note names")),
    ("?", "this help"),
    ("q", "quit (asks first when there are unsaved edits)"),
    ("H", "by hand: you make each step; click or enter takes an entry off"),
    ("8 9 6 3 2 1 4 7", "by hand: add that move; ⌫ h u r: take back, hint, undo, again"),
)

HOW = """\
[b]Breadth-first search[/b] (BFS) begins at the START node and expands all of its \
successors: every direction the robot can move in without crashing into an obstacle, \
leaving the map, or going back to a node already seen. The fringe is a [b]FIFO queue[/b]: \
the node that has been waiting longest is expanded next. BFS is complete, and optimal when \
every move costs the same: it finds a path with the fewest moves.

[b]Depth-first search[/b] (DFS) uses a [b]LIFO stack[/b] instead: it always expands the last \
successor added, going down one branch until it can find no more successors, then back to \
the newest node that has not been expanded. It usually needs much less memory, but it is not \
optimal: the path it returns is the one it happened to go down.

[b]Iterative deepening[/b] (IDDFS) runs a depth-limited DFS with limits 0, 1, 2, ... so it \
finds a path with the fewest moves while keeping DFS's small stack.

The fewest moves is not the cheapest path when a diagonal costs √2. [b]Uniform-cost search[/b] \
(UCS) takes from a [b]priority queue[/b] the node whose path so far is cheapest (its cost \
[b]g[/b]): it finds the cheapest path. [b]A*[/b] adds [b]h[/b], an estimate of the cost still to \
go, and takes the lowest [b]f = g + h[/b]: the same cheapest path, expanding far fewer nodes, as \
long as h never overestimates (manhattan does, with diagonal moves). [b]Greedy best-first[/b] \
takes the lowest h alone: fast, and often wrong. A cell reached again more cheaply is pushed \
again; its older entry is [i]stale[/i] and is discarded when it comes off. On [b]terrain[/b] \
(shaded cells, their cost beside the glyph) a move costs its length times the cost of the cell it \
enters: BFS still counts moves and wades through the mud, UCS and A* walk round it.

[b]IDA*[/b] (key 7) joins the two: iterative deepening on f instead of depth. Each iteration \
is a DFS from START that cuts off any node whose f is over the limit (the status line's \
[b]f-limit[/b]); the next limit is the smallest f cut off ([b]next[/b]). A*'s cheapest path, on \
a small stack, paid for by repeating each iteration.

A [b]bidirectional[/b] search (BiBFS, BiUCS, BiA*: no key, in the palette or the \
settings) runs the same search from START and, the moves reversed, from the GOAL, a step \
each in turn (or the smaller frontier's first): two frontiers on one map, two panels, two \
trees. Where they meet is a path, but stopping at the [b]first meeting[/b] is a famous trap: \
it is not always the cheapest. The settings' [b]proven[/b] stop keeps the best meeting and \
goes on until no path through the frontiers can be cheaper.

Each expanded node turns blue and its successors are generated (dark). When the goal is \
generated, the path is traced back up the tree from the goal to START (green). (These are the \
dark theme's colours: the legend above shows the colours of the theme in use, t changes it.)"""


#: The app without its screen: plain mode, the terminal's cursor, the exports.
ELSEWHERE = """\
With a screen reader, a braille display or over SSH: tui-search --plain MAP runs the same \
searches as plain lines. Type a command a line (n, p, end, 1 to 6, c, i, x, describe row 3, \
cell 2,1, around, set order N,W,S,E, help) and it says what changed: the step in the \
tutorial's words, the frontier in order, the tree's new edges. In this app the terminal's own \
cursor stays on the map's cursor cell, for a braille display to follow.

For a slide, a web page or a bug report: ctrl+p, Export the run, writes it as an animated SVG \
(.svg), a terminal recording (.cast), a GIF (.gif), a handout (.md) or a Posthoc search \
trace (.trace.json, .trace.yaml); without the app, tui-search MAP --headless --export FILE \
(docs/12-exports-and-plain.md)."""


def keys_table() -> Table:
    """The keys and what each does, in two columns: a description wraps in its own column
    (under its first word, never under the keys)."""
    table = Table.grid(padding=(0, 2))
    table.add_column(style="bold", no_wrap=True)
    table.add_column(ratio=1)
    for key, description in KEYS:
        table.add_row(Text(key), Text(description))  # as written: no markup, no emoji
    return table


def about_text() -> str:
    """The version and the search core that runs, as ``tui-search --version`` says them (a
    user without a C compiler learns here that the Python core runs, and why)."""
    from tui_search import __version__
    from tui_search.engine.search.loops.compiled import core_name

    return f"tui-search {__version__} ({core_name()})"


class HelpScreen(ModalScreen[None]):
    """Keys, colours and a few lines on the searches; any of escape, ? or q closes it."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("escape,question_mark,q", "dismiss", "Close"),
    ]
    AUTO_FOCUS = "VerticalScroll"

    DEFAULT_CSS = """
    HelpScreen {
        align: center middle;
        & > VerticalScroll {
            width: 90%;
            max-width: 86;
            height: 90%;
            border: round $primary;
            border-title-align: center;
            background: $surface;
            padding: 0 1;
        }
        & .help-heading { text-style: bold; color: $text-accent; margin-top: 1; }
        & .help-note { color: $text-muted; padding: 0 1; }
    }
    """

    def __init__(self, view: GridView | GraphView) -> None:
        super().__init__()
        self._view = view

    def compose(self) -> ComposeResult:
        with VerticalScroll() as scroll:
            scroll.border_title = "Help · escape to close"
            yield Static("Keys", classes="help-heading")
            yield Static(keys_table(), id="help-keys")
            yield Static("Colours and glyphs", classes="help-heading")
            yield Legend(self._view)
            yield Static("A bidirectional search's, besides: the backward search's cells "
                         "(←), those both reached, the best meeting", classes="help-note")
            yield Legend(self._view, only_two_way=True)
            yield Static("How the searches work", classes="help-heading")
            yield Static(HOW)
            yield Static("Without the screen", classes="help-heading")
            yield Static(Text(ELSEWHERE), id="help-elsewhere")
            yield Static("About", classes="help-heading")
            yield Static(about_text(), id="help-about")

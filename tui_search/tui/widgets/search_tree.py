"""The search tree panel: every generated node under START, edges labelled by moves.

::

    ● START (0,0)
    └─ ● S (0,1)
       ├─ ○ S (0,2)
       └─ ● SE (1,2)  ◀ expanding
          ├─ ○ E (2,2)
          └─ ○ NE (2,1)

What it lists, in which view (the whole tree, or focused on the path to the node being
expanded), is :mod:`tui_search.tui.view.tree_listing`'s; this widget gives each of the model's roles
its component class (so a theme colours them), keeps the node being expanded in view and
repaints only the lines that changed.
"""


from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from textual.geometry import Size

from tui_search.engine.util.numbers import group_digits
from tui_search.tui.view.pieces import Parts
from tui_search.tui.view.tree_listing import GLYPH_EXPANDED, GLYPH_FRONTIER, GLYPH_GOAL, TreeModel
from tui_search.tui.view.tree_listing import Parts as TreeParts
from tui_search.tui.view.tree_window import label_span, tree_window
from tui_search.tui.view.two_way.words import directed
from tui_search.tui.widgets.line_panel import LinePanel
from tui_search.tui.widgets.scrollbars import set_virtual_size

if TYPE_CHECKING:
    from tui_search.engine.run.recorded import Run

#: The model's roles are these component classes without the prefix.
PREFIX = "search-tree--"


class SearchTreePanel(LinePanel):
    """The search tree of a :class:`Run` at its position.

    Call :meth:`show` after every change of run or position.
    """

    DEFAULT_CSS = """
    SearchTreePanel {
        overflow-x: scroll;  /* its width changes with the depth: a bar that came and went
                                would make its last line come and go */
        & > .search-tree--guide { color: $foreground-muted; }
        & > .search-tree--expanded { color: $text-primary; }
        & > .search-tree--frontier { color: $foreground; }
        & > .search-tree--current {
            color: $block-cursor-foreground; background: $block-cursor-background;
            text-style: bold;
        }
        & > .search-tree--path { color: $text-success; text-style: bold; }
        & > .search-tree--cutoff { color: $text-warning; }
        & > .search-tree--detail { color: $text-muted; }
        & > .search-tree--note { color: $text-muted; text-style: italic; }
    }
    """

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "search-tree--guide",
        "search-tree--expanded",
        "search-tree--frontier",
        "search-tree--current",
        "search-tree--path",
        "search-tree--cutoff",
        "search-tree--detail",
        "search-tree--note",
    }
    """
    | Class | Description |
    | :- | :- |
    | `search-tree--guide` | The tree guides `│ ├─ └─`. |
    | `search-tree--expanded` | A node taken off the frontier and expanded (`●`). |
    | `search-tree--frontier` | A node generated and waiting on the frontier (`○`). |
    | `search-tree--current` | The line of the node being expanded at the position. |
    | `search-tree--path` | A node on the path, once the goal is found (at the end). |
    | `search-tree--cutoff` | A node cut off: at the depth limit, or over IDA*'s f-limit. |
    | `search-tree--detail` | Sibling counts and depths of the focused view. |
    | `search-tree--note` | The count above the listing, the note above the focused view. |
    """

    PINNED = 1  # the count ("8 nodes") or the focused view's note stays in view

    def __init__(self, **widget_args: Any) -> None:  # name, id, classes, disabled
        super().__init__(**widget_args)
        self.model = TreeModel()
        self._pending_scroll = False
        self.border_title = "Search tree"

    # -- the contract with the app ----------------------------------------------------------
    @property
    def run(self) -> Run | None:
        return self.model.run

    @property
    def mode(self) -> str:
        """``"list"`` (the whole tree) or ``"focus"`` (the path to the node being expanded)."""
        return self.model.mode

    def show(self, run: Run, direction: str = "", idle: bool = False) -> None:
        """Show ``run`` at its position and keep the node being expanded in view
        (``direction``: the half of a bidirectional search it is, which its title says;
        ``idle``: that half did not take the step, so none of its nodes is expanding)."""
        model = self.model
        model.idle = idle
        moved = model.update(run)
        limit, f_limit = model.limit, model.f_limit
        titles = ("Search tree", "Tree") if limit is None else (
            f"Search tree · depth limit {group_digits(limit)}",
            f"Tree · depth limit {group_digits(limit)}", f"Tree · limit {group_digits(limit)}",
            f"limit {group_digits(limit)}", "Tree")
        if f_limit is not None:  # IDA*: this iteration's contour, f up to its limit
            titles = (f"Search tree · f-limit {f_limit:.2f}", f"Tree · f-limit {f_limit:.2f}",
                      f"Tree · f ≤ {f_limit:.2f}", f"f ≤ {f_limit:.2f}", "Tree")
        goal = f"  {GLYPH_GOAL} goal" if model.path_shown else ""
        self.show_titles(directed(titles, direction), (
            f"{GLYPH_EXPANDED} expanded  {GLYPH_FRONTIER} frontier{goal}",
            f"{GLYPH_EXPANDED} expanded {GLYPH_FRONTIER} frontier{goal.replace('  ', ' ')}",
            f"{GLYPH_EXPANDED} expanded {GLYPH_FRONTIER} frontier"))
        set_virtual_size(self, Size(model.content_width(), model.line_count()))
        if moved:
            self._scroll_to_current()
        self.refresh_changed()

    def current_line(self) -> int:
        """The line of the node being expanded (of the root at step 0)."""
        return self.model.current_line()

    def line_parts(self, y: int) -> Parts:
        """Line ``y`` as (text, component class) pieces; ``[]`` past the end."""
        return [(text, PREFIX + role) for text, role in self.model.line(y)]

    def windowed(self, parts: Parts, x: int, width: int) -> tuple[Parts, int]:
        """A row shows its node whole or says it is cut: a node left of the window at its
        edge after ``◂``, a label past its right edge cut at a word before ``▸``
        (:func:`~tui_search.tui.view.tree_window.tree_window`)."""
        shown = tree_window([(text, role[len(PREFIX):]) for text, role in parts], x, width)
        if shown is None:
            return super().windowed(parts, x, width)
        return [(text, PREFIX + role) for text, role in shown if text], 0

    def _scroll_to_current(self) -> None:
        """Bring the node being expanded and its children into view (once laid out), below
        the pinned count, and its parent when there is room for it too; scrolled sideways
        only as far as :func:`scroll_column` says."""
        window = self.scrollable_content_region
        if not window:
            self._pending_scroll = True  # done on the first Resize
            return
        self._pending_scroll = False
        model = self.model
        top = self.pinned_rows()
        y = model.current_line()
        height = max(1, min(1 + len(model.kids), window.height - top))
        # (the focused view's depth column stays at the left edge: the rest scrolls)
        x = scroll_column([model.line(y + i) for i in range(height)],
                          window.width - model.depth_width())
        scroll_y = self.scroll_offset.y
        parent = model.parent_line()  # the node's parent in view too, when there is room
        first = parent if parent is not None and y + height - parent <= window.height - top \
            else y
        if first < scroll_y + top:
            scroll_y = first - top
        elif y + height > scroll_y + window.height:
            scroll_y = y + height - window.height
        self.scroll_to(x, max(0, scroll_y), animate=False, immediate=True, force=True)

    def on_resize(self) -> None:
        if self.model.run is not None:
            self._scroll_to_current()  # the first time, or a width that changes what fits


def scroll_column(lines: list[TreeParts], width: int) -> int:
    """The first column shown of a tree whose node being expanded is ``lines[0]`` and its
    children the others: 0 when all their labels fit ``width`` from there; else the first
    boundary of a guide (every 3 columns after the depth) from which they fit, else the
    node's link to its parent (``└─``, its label beside it), else the node's label's start:
    never inside a word (and the node's label always in view; a child's cut at the right
    edge says so: :mod:`~tui_search.tui.view.tree_window`)."""
    spans = [label_span(parts) for parts in lines]
    (start, end), right = spans[0], max(end for _, end in spans)
    if right <= width:
        return 0
    text = "".join(text for text, _ in lines[0])
    depth = sum(len(text) for text, role in lines[0][:1] if role == "detail")
    for column in range(depth, start, 3):
        if right - column <= width and (column == 0 or text[column - 1] == " "):
            return column
    # the node's own link to its parent ("└─ ") in view when its label fits beside it
    linked = start - 3
    return linked if linked >= depth and end - linked <= width else start


__all__ = ["PREFIX", "SearchTreePanel", "scroll_column"]

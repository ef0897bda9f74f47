"""The search tree's model: which nodes the tree panel lists at a run's position, in which
view, with which guides and labels -- plain text and roles, no Textual, so it is tested
directly (like :mod:`tui_search.tui.view.narration`).  :class:`~tui_search.tui.widgets.search_tree.
SearchTreePanel` draws it, giving each role its component class.

``●`` an expanded node (blue), ``○`` a node waiting on the frontier, the node being expanded
highlighted and kept in view, the path green once the goal is found.  Iterative deepening shows
the current iteration's tree, and the title gives its depth limit; IDA* the current
iteration's contour, its f-limit in the title and each node cut off over it marked with its f.

Two views, chosen by the size of the tree at the position, so that :meth:`SearchTreePanel.show`
stays cheap however big the run grows:

* **listing** (at most :data:`SMALL_TREE` nodes): the whole tree in preorder, under a line
  that counts its nodes (the count is not in the title: setting a title repaints the whole
  panel).  The listing is a list of event ids kept in step with the position: one step
  forwards inserts the expanded node's children after it, one step back removes them (a
  C-speed ``list.index`` and a slice assignment); a jump rebuilds it in O(nodes) from the
  record.  Tree guides (``│ ├─ └─``) are drawn per visible line from the record's parent
  array (O(depth), capped at :data:`~tui_search.tui.view.tree_shape.MAX_LEVELS`).
* **focused** (bigger trees, and those deeper than the listing's guides can draw,
  :data:`~tui_search.tui.view.tree_shape.MAX_LEVELS`: a line there would stand as far in
  as its parent's): the chain of ancestors from START to the node being expanded --
  one line per edge, each saying which of its parent's children it is -- then that node's
  children.  Only the deepest :data:`~tui_search.tui.view.tree_shape.SHOW_LEVELS` edges are
  listed (START and a "⋮ N levels not shown" line stand above them).  The chain is kept from
  one call to the next: a step walks up from the new node only to where it meets the old
  chain, the root, or :data:`~tui_search.tui.view.tree_shape.WALK_MAX` levels, so a step costs
  O(the part of the chain that changed) and a jump O(min(depth, WALK_MAX)).  The depths come
  from the walk, from the record (iterative deepening), or from BFS's level starts; a
  depth-first chain deeper than WALK_MAX reached by a jump is shown uncounted.

Both views' shape (the listing, the chain, the guides) is :mod:`~tui_search.tui.view.tree_shape`'s;
this model keeps it from one position to the next and says it as lines.
"""

from __future__ import annotations

from array import array
from typing import TYPE_CHECKING

from tui_search.engine.search.state import state_text, state_width
from tui_search.engine.util.numbers import group_digits
from tui_search.tui.view.tree_shape import (
    MAX_LEVELS,
    WALK_MAX,
    build_listing,
    chain_to,
    draw_guides,
    listing_backward,
    listing_forward,
    siblings,
)

if TYPE_CHECKING:
    from tui_search.engine.run.recorded import Run

#: A line as (text, role) pieces; the roles are the panel's component classes without their
#: ``search-tree--`` prefix: guide, expanded, frontier, current, path, cutoff, detail, note.
Parts = list[tuple[str, str]]

#: Largest tree listed in full; bigger trees get the focused view.
SMALL_TREE = 5000
#: Position changes applied one step at a time to the listing; bigger jumps rebuild it.
INCREMENTAL_STEPS = 64
#: Tree guides kept (an event's never change); the cache starts again past this many.
GUIDES_KEPT = 4 * SMALL_TREE
#: Levels of indentation in the focused view (its lines also show their depth).
FOCUS_LEVELS = 8

GLYPH_EXPANDED = "●"
GLYPH_FRONTIER = "○"
GLYPH_GOAL = "★"
SUFFIX_CURRENT = "  ◀ expanding"
SUFFIX_DISCARDED = "  ◀ discarded"  # taken off again (visit on expand): nothing expanded
SUFFIX_GOAL = "  ★ goal"
SUFFIX_CUTOFF = "  ✂ depth limit"
SUFFIX_CUT_NOW = "  ◀ cut off"  # IDA*: the node taken off, over the f-limit
SUFFIX_F_W = len("  ✂ f 999.99")  # IDA*: a node cut off, its f (the widest usual)
#: Widest suffix (all single-cell characters).
SUFFIX_W = max(len(SUFFIX_CURRENT), len(SUFFIX_GOAL), len(SUFFIX_CUTOFF))



class TreeModel:
    """The tree at a run's position: :meth:`update` after each change, then :meth:`line`."""

    def __init__(self) -> None:
        self._run: Run | None = None
        self._k = -1
        self._root = -1
        self._mode = ""  # "list" or "focus"
        self._listed = False  # the listing kept in step (a small tree, listed or too deep)
        self._current = -1  # event expanded at the position (-1 at step 0)
        self._current_discarded = False  # ...or taken off and discarded
        self._ended = False  # the run at its end: nothing is being expanded any more
        #: A bidirectional search's half that did not take the step: none of its nodes is
        #: being expanded (its last one is marked as the current, without "expanding").
        self.idle = False
        self._limit: int | None = None
        self._f_limit: float | None = None  # IDA*'s
        self._coord_w = 5
        self._tree_size = 0
        # the listing
        self._order: list[int] = []
        self._depth = array("i")  # depth of event root + i
        self._expanded: set[int] = set()
        self._guides: dict[int, str] = {}  # event -> its guides, for the run self._guides_run
        self._guides_run: Run | None = None
        # the focused view
        self._chain: list[int] = []  # the deepest SHOW_LEVELS + 1 ancestors, top to bottom
        self._chain_pos: dict[int, int] = {}
        self._top_depth: int | None = None  # depth of _chain[0], None when not counted
        self._elided = False  # START and a "⋮" line stand above the chain
        self._kids: range = range(0)
        # the path, computed once per run
        self._path_run: Run | None = None
        self._path_all: frozenset[int] = frozenset()
        self._path: frozenset[int] = frozenset()
        self._goal = -1

    @property
    def run(self) -> Run | None:
        return self._run

    @property
    def mode(self) -> str:
        """``"list"`` (the whole tree) or ``"focus"`` (the path to the node being expanded)."""
        return self._mode

    @property
    def limit(self) -> int | None:
        """Iterative deepening's depth limit at the position (None for other searches)."""
        return self._limit

    @property
    def f_limit(self) -> float | None:
        """IDA*'s limit on f at the position (None for other searches)."""
        return self._f_limit

    def _cut_f(self, g: int) -> float | None:
        """IDA*: event ``g``'s f when it is over the f-limit (None: within, or not IDA*)."""
        run = self._run
        if self._f_limit is None or run is None:
            return None
        costs = run.nodes.costs(g)
        if costs is None or costs[2] <= self._f_limit + run.semantics.cost_tolerance:
            return None
        return costs[2]

    @property
    def path_shown(self) -> bool:
        """Is the path to the goal drawn (the run at its end, the goal found)?"""
        return bool(self._path)

    @property
    def kids(self) -> range:
        """The children of the node being expanded (shown under it)."""
        return self._kids if self._mode == "focus" else self._current_kids()

    def update(self, run: Run) -> bool:
        """Follow ``run`` to its position; True when the run or the position changed.

        Cost: the listing, O(steps moved) C-speed list edits (a jump: O(nodes) <= SMALL_TREE);
        the focused view, O(the part of the ancestor chain that changed) -- never O(tree).
        """
        k = run.k
        root = run.now.tree_root()
        size = run.now.tree_size()
        moved = run is not self._run or k != self._k
        same_tree = run is self._run and root == self._root
        listed = size <= SMALL_TREE
        if listed:
            if not (same_tree and self._listed and abs(k - self._k) <= INCREMENTAL_STEPS):
                self._order, self._depth, self._expanded = build_listing(run, root, k)
            else:
                listing = self._order, self._depth, self._expanded
                for j in range(self._k + 1, k + 1):
                    listing_forward(run, root, j, *listing)
                for j in range(self._k, k, -1):
                    listing_backward(run, root, j, *listing)
        else:
            self._order, self._depth, self._expanded = [], array("i"), set()
        # deeper than the listing's guides can draw, a node's line would stand as far in as
        # its parent's: the path to the node being expanded, its depths counted, instead
        deep = listed and bool(self._depth) and max(self._depth) > MAX_LEVELS
        mode = "list" if listed and not deep else "focus"
        if mode == "list":
            self._chain, self._chain_pos, self._top_depth = [], {}, None
        else:
            self._focus(run, same_tree and self._mode == "focus", run.steps.expanded_event(k))
            self._kids = run.now.added_now()
        self._run, self._k, self._root, self._mode = run, k, root, mode
        self._listed = listed
        self._current = run.steps.expanded_event(k) if k else -1
        self._current_discarded = bool(k) and run.steps.is_discarded(k)
        self._ended = run.at_end or self.idle
        self._tree_size = size
        self._limit = run.steps.depth_limit() if run.algo.iterative else None
        f_limits = run.steps.f_limits()
        self._f_limit = None if f_limits is None else f_limits[0]
        self._coord_w = state_width(run.board)
        self._update_path(run)

        return moved

    def current_line(self) -> int:
        """The line of the node being expanded (of the root at step 0)."""
        if self._mode == "focus":
            return self._head() + len(self._chain) - 1
        if self._current < 0:
            return 1
        return 1 + self._order.index(self._current)

    def parent_line(self) -> int | None:
        """The line of the parent of the node being expanded (None: the root, or step 0)."""
        run = self._run
        if run is None or self._current < 0:
            return None
        if self._mode == "focus":
            line = self.current_line() - 1
            return line if line >= self._head() else None
        parent = run.nodes.parent(self._current)
        return None if parent < 0 or parent not in self._expanded else (
            1 + self._order.index(parent))

    def line(self, y: int) -> Parts:
        """Line ``y`` of the whole view as (text, role) pieces; ``[]`` past it."""
        if self._run is None or y < 0:
            return []
        if self._mode == "focus":
            return self._focus_parts(y)
        if y == 0:
            return [(self._count_text(), "note")]
        y -= 1
        if y >= len(self._order):
            return []
        g = self._order[y]
        depth = self._depth[g - self._root]
        parts: Parts = []
        guides = self._list_guides(g, depth)
        if guides:
            parts.append((guides, "guide"))
        parts.extend(self._node_parts(g, depth, g in self._expanded))
        return parts

    def line_text(self, y: int) -> str:
        return "".join(text for text, _ in self.line(y))

    def _focus(self, run: Run, keep: bool, current: int) -> None:
        """Make the chain of ancestors down to ``current``: walk up only to where it meets the
        old chain (a step: a level or a few), the root, or WALK_MAX levels (a jump)."""
        old = (self._chain, self._chain_pos, self._top_depth) if keep else ([], {}, None)
        new, self._top_depth = chain_to(run, current, *old)
        self._chain = new
        self._chain_pos = {g: i for i, g in enumerate(new)}
        self._elided = new[0] != run.now.tree_root()

    def _update_path(self, run: Run) -> None:
        if self._path_run is not run or self._goal != run.nodes.goal:
            self._path_run, self._goal = run, run.nodes.goal
            self._path_all = frozenset(run.nodes.path())
        self._path = self._path_all if run.at_end else frozenset()

    def line_count(self) -> int:
        if self._mode == "focus":
            return self._head() + len(self._chain) + len(self._kids)
        return 1 + len(self._order)

    def _head(self) -> int:
        """Lines above the chain in the focused view: the note (and START, "⋮"); above the
        listing: the count."""
        return 3 if self._elided else 1

    def depth_width(self) -> int:
        """Width of the focused view's depth column, which stays in view when the panel is
        scrolled sideways (0: none, or the depth is not counted)."""
        return self._depth_width() if self._mode == "focus" else 0

    def _depth_width(self) -> int:
        """Width of the focused view's depth column (0 when the depth is not counted)."""
        if self._top_depth is None:
            return 0
        return len(group_digits(self._top_depth + len(self._chain))) + 1

    def label_width(self) -> int:
        # glyph, space, direction (START: 5), space, coordinates
        return 1 + 1 + 5 + 1 + self._coord_w

    def content_width(self) -> int:
        """The widest line, near enough (exact for the lines that carry a suffix), without
        looking at every line."""
        label = 1 + 1 + 2 + 1 + self._coord_w  # glyph, move, cell of an ordinary node
        if self._mode == "focus":
            levels = min(len(self._chain) + self._elided, FOCUS_LEVELS)
            widest = (self._depth_width() + 3 * levels + label + len(SUFFIX_CURRENT)
                      + len("  child 8 of 8"))
            return max(len(self._note()), len(self._elision()), widest)
        deepest = max(self._depth) if len(self._depth) else 0
        widest = 3 * min(deepest, MAX_LEVELS) + (2 if deepest > MAX_LEVELS else 0) + label
        if self._limit and deepest >= self._limit:
            widest = max(widest, 3 * min(self._limit, MAX_LEVELS) + label + len(SUFFIX_CUTOFF))
        if self._f_limit is not None:  # IDA*: any node may be cut off, its f said
            widest = 3 * min(deepest, MAX_LEVELS) + label + SUFFIX_F_W
        widest = max(widest, 1 + 1 + 5 + 1 + self._coord_w)  # the root, START
        for g in (self._current, self._goal if self._path else -1):
            if g >= 0:
                widest = max(widest, len(self.line_text(1 + self._order.index(g))))
        return max(widest, len(self._count_text()))

    def _current_kids(self) -> range:
        run = self._run
        return run.now.added_now() if run is not None else range(0)

    def _count_text(self) -> str:
        """The listing's first line: ``8 nodes`` (a title with the count would repaint the
        whole panel on every step)."""
        size = self._tree_size
        return f"{group_digits(size)} node{'s' if size != 1 else ''}"

    def _note(self) -> str:
        return (f"({group_digits(self._tree_size)} nodes; showing the path to the node being "
                "expanded)")

    def _node_parts(self, g: int, depth: int, expanded: bool, detail: str = "") -> Parts:
        """Glyph, move and cell of ``g``, a suffix (being expanded, the goal, cut off at the
        depth limit), then ``detail`` (sibling counts)."""
        run = self._run
        assert run is not None
        label = node_label(run, g)
        goal = g == self._goal and bool(self._path)
        if g in self._path:  # the answer, at the end, outranks everything (as on the grid)
            cls = "path"
        elif g == self._current:
            cls = "current"
        else:
            cls = "expanded" if expanded else "frontier"
        glyph = GLYPH_GOAL if goal else (GLYPH_EXPANDED if expanded else GLYPH_FRONTIER)
        parts = [(f"{glyph} {label}", cls)]
        cut_f = self._cut_f(g) if expanded else None
        if g == self._current and cut_f is not None and not self._ended:
            parts.append((SUFFIX_CUT_NOW, cls))
        elif g == self._current and self._current_discarded:
            parts.append((SUFFIX_DISCARDED, cls))
        elif g == self._current and not self._ended:  # the search over: none is expanding
            parts.append((SUFFIX_CURRENT, cls))
        elif goal:
            parts.append((SUFFIX_GOAL, cls))
        elif expanded and self._limit is not None and depth >= self._limit:
            parts.append((SUFFIX_CUTOFF, "cutoff"))
        elif cut_f is not None:  # IDA*: over the f-limit, cut off
            parts.append((f"  ✂ f {cut_f:.2f}", "cutoff"))
        if detail:
            parts.append((detail, "detail"))
        return parts

    def _list_guides(self, g: int, depth: int) -> str:
        """``│  ├─ `` etc. for a node of the listing: O(min(depth, MAX_LEVELS)) the first time,
        then kept (whether each ancestor is a last child is known once it is generated; a step
        shifts the lines under the node it expands, and they are drawn again)."""
        if depth == 0:
            return ""
        if self._guides_run is not self._run or len(self._guides) > GUIDES_KEPT:
            self._guides, self._guides_run = {}, self._run
        guides = self._guides.get(g)
        if guides is None:
            run = self._run
            assert run is not None
            guides = self._guides[g] = draw_guides(run, g, depth)
        return guides

    def _elision(self) -> str:
        if not self._elided:
            return ""
        if self._top_depth is None:
            return f"⋮  more than {group_digits(WALK_MAX)} levels not shown"
        hidden = self._top_depth - 1
        return f"⋮  {group_digits(hidden)} level{'s' if hidden != 1 else ''} not shown"

    def _focus_parts(self, y: int) -> Parts:
        chain, kids = self._chain, self._kids
        if y == 0:
            return [(self._note(), "note")]
        depth_w = self._depth_width()
        if self._elided and y <= 2:
            if y == 1:
                root = self._run.now.tree_root()  # type: ignore[union-attr]
                parts: Parts = [(f"{'0':>{depth_w - 1}} " if depth_w else "", "detail")]
                return parts + self._node_parts(root, 0, True)
            return [(" " * depth_w + self._elision(), "detail")]
        i = y - self._head()
        if i < len(chain):
            g, level, expanded = chain[i], i + self._elided, True
            connector = "└─ "
        elif i - len(chain) < len(kids):
            g = kids[i - len(chain)]
            level, expanded = len(chain) - 1 + self._elided + 1, False
            connector = "└─ " if g == kids[-1] else "├─ "
        else:
            return []
        depth = None
        if self._top_depth is not None:
            depth = self._top_depth + min(i, len(chain))
        parts = [(f"{group_digits(depth):>{depth_w - 1}} " if depth is not None else "",
                  "detail")]
        if level:
            # Indentation stops growing at FOCUS_LEVELS, but children stay under their parent.
            shown = min(level, FOCUS_LEVELS) if i < len(chain) else (
                min(level - 1, FOCUS_LEVELS) + 1)
            parts.append(("   " * (shown - 1) + connector, "guide"))
        detail = self._sibling_text(g) if level and i < len(chain) else ""
        parts.extend(self._node_parts(g, depth if depth is not None else -1, expanded, detail))
        return parts

    def _sibling_text(self, g: int) -> str:
        """``child 2 of 3``: where ``g`` is among its parent's children (at most 8)."""
        run = self._run
        assert run is not None
        sibs = siblings(run, g)
        if len(sibs) == 1:
            return "  only child"
        return f"  child {g - sibs.start + 1} of {len(sibs)}"



def node_label(run: Run, g: int) -> str:
    """A node as the tree lists it: its move and its cell (``NE (3,4)``); on a graph, whose
    moves are the nodes they reach, its name and its road's cost (``Sibiu 140``)."""
    graph, nodes = run.graph, run.nodes
    if graph is None or nodes.parent(g) < 0:
        return f"{nodes.move(g)} {state_text(nodes.cell(g))}"
    name, parent = str(nodes.cell(g)), str(nodes.cell(nodes.parent(g)))
    return f"{name} {graph.cost(parent, name):g}"

__all__ = ["TreeModel"]

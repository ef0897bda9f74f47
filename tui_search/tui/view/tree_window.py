"""A search tree's line as a panel scrolled sideways shows it (no Textual): its node whole,
or marked as cut, never a fragment.

A tree deeper than its panel is wide scrolls sideways to keep the node being expanded in
view (:func:`~tui_search.tui.widgets.search_tree.scroll_column`).  The shallower nodes'
labels are then left of the window, and a deeper one's may run past its right edge: cut
where the edges fall, a row showed a lone ``(19,4)`` or nothing at all, and the node under
it looked like the root.  Here a row whose node starts left of the window shows that node
from the window's first column after :data:`CUT_LEFT` (``◂● NE (19,4)``: it is further
left, and so is every ancestor of the rows under it that is not shown), and a node's label
that runs past the right edge keeps its whole words then :data:`CUT_RIGHT` (``└─ ★ NE ▸``).
The focused view's depths, the first column of its lines, stay at the window's left edge.
"""

from __future__ import annotations

#: A line as (text, role) pieces, the roles the tree model's.
Parts = list[tuple[str, str]]

#: Before a node shown at the window's left edge: it stands further left.
CUT_LEFT = "◂"
#: After a node's label cut at the window's right edge: it goes on to the right.
CUT_RIGHT = "▸"
#: The roles that are not a node's label: the guides, the focused view's details and notes.
NOT_LABEL = ("guide", "detail", "note")


def label_span(parts: Parts) -> tuple[int, int]:
    """The columns of a tree line's label (glyph, move, cell): after its depth and guides,
    before its suffix and sibling count."""
    start = 0
    for text, role in parts:
        if role not in NOT_LABEL:
            return start, start + len(text)
        start += len(text)
    return start, start


def _from(parts: Parts, column: int) -> Parts:
    """``parts`` from ``column`` on."""
    out: Parts = []
    at = 0
    for text, role in parts:
        if at + len(text) > column:
            out.append((text[max(0, column - at):], role))
        at += len(text)
    return out


def _upto(parts: Parts, column: int) -> Parts:
    """``parts`` before ``column``."""
    out: Parts = []
    at = 0
    for text, role in parts:
        if at < column:
            out.append((text[: column - at], role))
        at += len(text)
    return out


def _cut_right(parts: Parts, start: int, width: int) -> Parts:
    """``parts`` (shown from the window's first column, the label from ``start``) within
    ``width``: a whole label and what follows it cut at a word (its suffix, its sibling
    count); a label that does not fit, its whole words that do, then :data:`CUT_RIGHT`."""
    rest = _from(parts, start)
    label = next((text for text, role in rest if role not in NOT_LABEL), "")
    role = next((role for _, role in rest if role not in NOT_LABEL), "guide")
    if start + len(label) <= width:
        text = "".join(text for text, _ in parts)
        keep = width if len(text) <= width or text[width] == " " else text.rfind(" ", 0, width)
        return _upto(parts, max(start + len(label), keep))
    if start >= width - 1:  # nothing of it in the window but its place
        return [*_upto(parts, width - 1), (CUT_RIGHT, "guide")]
    room = width - start - 2  # its words, a space, the mark
    cut = label[:room + 1]
    words = cut[:cut.rfind(" ")] if " " in cut else ""
    return [*_upto(parts, start + len(words)), (" " if words else "", role),
            (CUT_RIGHT, "guide")]


def tree_window(parts: Parts, x: int, width: int) -> Parts | None:
    """Line ``parts`` as a window ``width`` columns wide from column ``x`` shows it, from
    the window's first column: its node whole, or marked cut (see the module's docstring).
    None for a line shown as it is, cut only at word boundaries: one with no node (the
    count, the focused view's notes), or whose node's label is whole in the window."""
    lead = parts[0][0] if parts[1:] and parts[0][1] == "detail" else ""
    if lead and x > 0 and width > len(lead) + 1:  # the focused view's depths stay in view
        d = len(lead)
        rest = [(" " * d, "guide"), *parts[1:]]
        return [parts[0], *(tree_window(rest, x, width - d) or _plain(rest, x, width - d))]
    start, end = label_span(parts)
    if start == end or width < 2:
        return None
    if start < x:  # the node stands left of the window: shown at its edge, marked
        return _cut_right([(CUT_LEFT, "guide"), *_from(parts, start)], 1, width)
    if end <= x + width:
        return None
    return _cut_right(_blank_cut(parts, x), start - x, width)


def _blank_cut(parts: Parts, x: int) -> Parts:
    """``parts`` from column ``x`` on, the guide the left edge cuts through blanked."""
    shown = _from(parts, x)
    text = "".join(text for text, _ in parts)
    if x and text[x - 1] != " ":
        cut = len(text[x:].split(" ", 1)[0])
        shown = [(" " * cut, "guide"), *_from(shown, cut)]
    return shown


def _plain(parts: Parts, x: int, width: int) -> Parts:
    """``parts`` in a window ``width`` wide from ``x``, cut at word boundaries only."""
    shown = _blank_cut(parts, x)
    text = "".join(text for text, _ in shown)
    if len(text) > width and text[width] != " " and text[width - 1] != " ":
        return _upto(shown, text.rfind(" ", 0, width) + 1)
    return _upto(shown, width)


__all__ = ["CUT_LEFT", "CUT_RIGHT", "label_span", "tree_window"]

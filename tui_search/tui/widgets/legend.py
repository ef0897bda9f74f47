"""The legend: every kind of cell drawn exactly as the map draws it (same glyph, same style, read
from the map's own component classes), so a theme change changes both; on a map with terrain,
the ramp that shades a free cell by its cost too."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rich.style import Style
from rich.text import Text
from textual.geometry import Size
from textual.widget import Widget

from tui_search.tui.view.cell_codes import (
    BACK_CURRENT,
    BACK_EXPANDED,
    BACK_FRONTIER,
    BOTH,
    COMPONENTS,
    CURRENT,
    CURSOR_MARK,
    EXPANDED,
    FREE,
    FRONTIER,
    GLYPHS,
    GOAL,
    MEETING,
    PATH,
    START,
    WALL,
)
from tui_search.tui.widgets.cell_style import RAMP_NAMES
from tui_search.tui.widgets.grid_view import GridView

if TYPE_CHECKING:
    from tui_search.tui.widgets.graph_view import GraphView

ENTRIES = (
    (START, "start"),
    (GOAL, "goal"),
    (WALL, "obstacle"),
    (FRONTIER, "frontier"),
    (EXPANDED, "expanded"),
    (CURRENT, "expanding"),
    (PATH, "path"),
)
#: A bidirectional search's: each half's states named by its arrow, a cell both halves
#: reached, the best meeting.
TWO_WAY_ENTRIES = (
    (START, "start"),
    (GOAL, "goal"),
    (WALL, "obstacle"),
    (FRONTIER, "frontier →"),
    (EXPANDED, "expanded →"),
    (BACK_FRONTIER, "frontier ←"),
    (BACK_EXPANDED, "expanded ←"),
    (CURRENT, "expanding →"),
    (BACK_CURRENT, "expanding ←"),
    (BOTH, "both"),
    (MEETING, "meeting"),
    (PATH, "path"),
)

#: What a bidirectional search adds to the one-way legend (the help lists them apart).
ONLY_TWO_WAY = (
    (BACK_FRONTIER, "frontier ←"),
    (BACK_EXPANDED, "expanded ←"),
    (BACK_CURRENT, "expanding ←"),
    (BOTH, "both"),
    (MEETING, "meeting"),
)


class Legend(Widget):
    """Glyph-and-colour entries packed into as many lines as the width needs."""

    DEFAULT_CSS = """
    Legend {
        height: auto;
        padding: 0 1;
        color: $text-muted;
    }
    """

    def __init__(self, view: GridView | GraphView, *, id: str | None = None,
                 only_two_way: bool = False) -> None:
        """``only_two_way``: the kinds a bidirectional search adds, alone (no cursor, no
        terrain's ramp: the help lists them under the one-way legend)."""
        super().__init__(id=id)
        self.view = view
        #: A bidirectional search is shown: its kinds of cell too.
        self.two_way = False
        self.only_two_way = only_two_way

    @property
    def kinds(self) -> tuple[tuple[int, str], ...]:
        """The kinds of cell listed, each a code and its name."""
        if self.only_two_way:
            return ONLY_TWO_WAY
        return TWO_WAY_ENTRIES if self.two_way else ENTRIES

    def entries(self, styled: bool = True) -> list[Text]:
        """The entries, in the looks the map draws with (read once a restyle, by the map);
        not ``styled``: the same text without styles (all the packing needs)."""
        view = self.view
        if not isinstance(view, GridView):  # a graph's marks, in the graph's looks
            return self._graph_entries(view, styled)
        looks = view.cell_looks() if styled else None

        def look(code: int) -> tuple[str, Style | str]:
            return looks.codes[code] if looks else (GLYPHS[code % len(COMPONENTS)], "")

        out = [Text.assemble(look(code), f" {name}") for code, name in self.kinds]
        if self.only_two_way:
            return out
        out.append(Text.assemble(look(FREE + len(COMPONENTS)), " cursor"))
        if view.grid.costs is not None:  # terrain: the ramp that shades a free cell's cost
            ramp: list[Style | str] = list(looks.ramp[1:]) if looks else [""] * len(RAMP_NAMES)
            # the ramp's steps for each look (plain, under the cursor, marked): the plain ones named
            out.append(Text.assemble(*(
                (f" {name} ", style) for name, style in zip(RAMP_NAMES, ramp, strict=False)),
                " cost"))
        return out

    def _graph_entries(self, view: GraphView, styled: bool) -> list[Text]:
        """A graph's entries: each mark as the graph view draws it, closed for obstacle."""
        from tui_search.tui.widgets.graph_lines import MARKS

        looks = view.looks() if styled else None
        out = []
        for code, name in self.kinds:
            glyph, style = looks.mark[code] if looks else (MARKS[code], "")
            out.append(Text.assemble((glyph, style), f" {'closed' if code == WALL else name}"))
        if self.only_two_way:
            return out
        out.append(Text.assemble((CURSOR_MARK, looks.cursor if looks else ""), " cursor"))
        return out

    def _lines(self, width: int, styled: bool = True) -> Text:
        lines: list[Text] = [Text()]
        for entry in self.entries(styled):
            line = lines[-1]
            need = entry.cell_len + (2 if line.cell_len else 0)
            if line.cell_len and line.cell_len + need > width:
                lines.append(Text())
                line = lines[-1]
            if line.cell_len:
                line.append("  ")
            line.append_text(entry)
        return Text("\n").join(lines)

    def get_content_height(self, container: Size, viewport: Size, width: int) -> int:
        # the packing only: the map's looks are read once, for the frame, after the restyle
        return len(self._lines(max(1, width), styled=False).plain.split("\n"))

    def render(self) -> Text:
        return self._lines(max(1, self.content_region.width or self.size.width))

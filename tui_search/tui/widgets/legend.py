"""The legend: every kind of cell drawn exactly as the map draws it (same glyph, same style, read
from the map's own component classes), so a theme change changes both; on a map with terrain,
the ramp that shades a free cell by its cost too."""

from __future__ import annotations

from rich.text import Text
from textual.geometry import Size
from textual.widget import Widget

from tui_search.tui.cell_codes import (
    COMPONENTS,
    CURRENT,
    EXPANDED,
    FREE,
    FRONTIER,
    GOAL,
    PATH,
    START,
    WALL,
)
from tui_search.tui.widgets.cell_style import RAMP_NAMES
from tui_search.tui.widgets.grid_view import GridView

ENTRIES = (
    (START, "start"),
    (GOAL, "goal"),
    (WALL, "obstacle"),
    (FRONTIER, "frontier"),
    (EXPANDED, "expanded"),
    (CURRENT, "expanding"),
    (PATH, "path"),
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

    def __init__(self, view: GridView, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.view = view

    def entries(self) -> list[Text]:
        """The entries, in the looks the map draws with (read once a restyle, by the map)."""
        looks = self.view.cell_looks()
        out = [Text.assemble(looks.codes[code], f" {name}") for code, name in ENTRIES]
        out.append(Text.assemble(looks.codes[FREE + len(COMPONENTS)], " cursor"))
        if self.view.grid.costs is not None:  # terrain: the ramp that shades a free cell's cost
            out.append(Text.assemble(*(
                (f" {name} ", style) for name, style in zip(RAMP_NAMES, looks.ramp[1:])),
                " cost"))
        return out

    def _lines(self, width: int) -> Text:
        lines: list[Text] = [Text()]
        for entry in self.entries():
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
        return len(self._lines(max(1, width)).plain.split("\n"))

    def render(self) -> Text:
        return self._lines(max(1, self.content_region.width or self.size.width))

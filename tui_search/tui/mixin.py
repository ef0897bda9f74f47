"""The base of the app's mixins (file actions, editing actions): at run time plain ``object``;
for the type checker, a Textual app with what :class:`~tui_search.tui.app.SearchApp` adds and
the mixins use, so ``self.notify`` or ``self._new_run`` in a mixin is checked."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from tui_search.engine.grid import Cell, Grid

if TYPE_CHECKING:
    from textual.app import App

    from tui_search.engine.run import Run
    from tui_search.tui.widgets.frontier_panel import FrontierPanel
    from tui_search.tui.widgets.grid_view import GridView
    from tui_search.tui.widgets.run_pane import RunPane

    class AppMixinBase(App[int]):
        grid: Grid
        map_path: Path | None
        dirty: bool
        view: GridView
        frontier_panel: FrontierPanel
        cursor_cell: Cell
        search_run: Run | None
        note: str
        _stroke: bool | None

        @property
        def map_name(self) -> str: ...

        def _show(self, changed: list[Cell] | None = None, follow: bool = True) -> None: ...

        def _new_run(self, note: str = "") -> None: ...

        def _moved(self, before: list[tuple[int, bool]]) -> None: ...
        def _advance(self, forward: bool) -> list[tuple[int, bool]] | None: ...
        def _stop(self) -> None: ...
        @property
        def views(self) -> list[GridView]: ...
        def show_readout(self) -> None: ...
        def _move_cursor(self, cell: Cell) -> None: ...
        def _show_pick(self) -> None: ...
        @property
        def panes(self) -> list[RunPane]: ...
else:
    AppMixinBase = object

__all__ = ["AppMixinBase"]

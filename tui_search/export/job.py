"""An export asked for, as plain values (:class:`Job`): the run, its map, the file and the
flags -- what the command line and the app's palette hand to
:func:`~tui_search.export.files.make_export`.
"""

from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

from tui_search.engine.maps.grid import Grid
from tui_search.engine.search.choices import Semantics
from tui_search.export.kinds import kind_of


class Job(NamedTuple):
    """An export: ``target`` the file (its kind by its ending), the run (the map ``grid``
    read from ``path`` -- None: ``unsaved_name`` names it --, ``algorithm`` or the searches
    ``compare`` names, under ``semantics``, at most ``max_steps``), how it is drawn
    (``theme``, ``fps``, ``view``), ``force`` to replace files, and a handout's
    ``handout_steps``."""

    target: str
    grid: Grid
    path: Path | None
    unsaved_name: str
    algorithm: str
    semantics: Semantics
    compare: str | None
    max_steps: int
    theme: str | None
    fps: float
    view: str
    force: bool
    handout_steps: int

    @property
    def kind(self) -> str:
        return kind_of(self.target)

"""Saving the map from plain mode, as the app saves it: ``save`` writes the map's own file
with only the edited cells changed, in its own format; ``save as FILE`` writes a new file in
the format its name says (``.map`` MovingAI, else text) and never replaces one.  Each refusal
is one line, and the map stays unsaved.
"""

from __future__ import annotations

import os
from pathlib import Path

from tui_search.engine.maps.read import MapError
from tui_search.engine.maps.source import MOVINGAI
from tui_search.engine.maps.write import kind_for_path, save_map, save_notes
from tui_search.engine.util.filenames import describe_name
from tui_search.tui.model.file_rules import one_line
from tui_search.tui.model.session import Session

NO_FILE = "The map has no file yet: save as FILE names one."


def save_lines(session: Session, rest: str) -> list[str]:
    """``save`` (``rest`` empty) or ``save as FILE``: what was done, or why not."""
    words = rest.split(" ", 1)
    if rest and (words[0].lower() != "as" or len(words) < 2 or not words[1].strip()):
        return ["save takes nothing, or as FILE."]
    if not rest:
        if session.map_path is None:
            return [NO_FILE]
        path = session.map_path
        source = session.grid.source
        kind = source.kind if source is not None else kind_for_path(path)
    else:
        path = Path(words[1].strip())
        if os.path.lexists(path):
            return [f"{describe_name(str(path))} exists: save as another name (plain mode "
                    "never replaces a file but the map's own)."]
        kind = kind_for_path(path)
    try:
        written = save_map(session.grid, path, kind)
    except MapError as exc:
        return [f"Not saved: {one_line(exc)}."]
    except (OSError, ValueError) as exc:  # what no name may do: end plain mode
        return [f"Not saved: {describe_name(str(path))}: {exc}."]
    notes = (["the start and goal are not part of a .map file"] if kind == MOVINGAI else []
             ) + save_notes(session.grid, kind)
    session.grid.source = written
    session.saved(path)
    said = f" ({'; '.join(notes)})" if notes else ""
    return [f"Saved {describe_name(str(path))}{said}."]


__all__ = ["NO_FILE", "save_lines"]

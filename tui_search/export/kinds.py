"""Which export a file's name asks for, and the rules every export keeps: its kind by the
file's ending, never over an existing file without ``--force``, and the defaults and limits of
its flags.

Only plain values and the standard library here: the command line's parser reads them at every
start (the exports' own modules are imported only when one is made).
"""

from __future__ import annotations

import os

from tui_search.engine.util.filenames import describe_name

#: The kinds by the file's ending (docs/12-exports-and-plain.md); a Posthoc trace's by its
#: last two (as :data:`tui_search.engine.traces.posthoc.SUFFIXES` reads them).
KINDS = {".svg": "svg", ".cast": "cast", ".gif": "gif", ".md": "md", ".trace.json": "trace",
         ".trace.yaml": "trace"}
#: What a Posthoc trace's map is called beside it: ``run.trace.json`` has ``run.map``.
MAP_SUFFIX = ".map"
#: Frames (steps) a second; an export's last frame is held this much longer.
DEFAULT_FPS, MIN_FPS, MAX_FPS, HOLD_SECONDS = 2.0, 0.1, 50.0, 2.0
#: The steps a handout narrates unless ``--handout-steps`` says.
DEFAULT_HANDOUT_STEPS = 10
#: ``--export-view``: the app's screen, or its maps alone.
EXPORT_VIEWS = ("full", "map")
#: Frames an export holds at most: one a step, and step 0 (a run of more steps is refused).
MAX_FRAMES = 1000
#: What a handout's picture is called: the handout's name, this instead of ``.md``.
PICTURE_SUFFIX = "-final.svg"


def kind_of(name: str) -> str:
    """The kind of export ``name`` asks for (``svg``, ``cast``, ``gif``, ``md``, ``trace``),
    or a ValueError naming the endings (``.json`` or ``.yaml`` alone is none)."""
    ending = _ending(name)
    if ending not in KINDS:
        endings = ", ".join(KINDS)
        raise ValueError(f"--export {describe_name(name)}: the kind is the file's ending, one "
                         f"of {endings}")
    return KINDS[ending]


def _ending(name: str) -> str:
    """The ending that names ``name``'s kind: its last two (``.trace.json``) where they name
    one, else its last."""
    stem, last = os.path.splitext(name)
    two = os.path.splitext(stem)[1] + last
    return two.lower() if two.lower() in KINDS else last.lower()


def map_of(name: str) -> str:
    """A Posthoc trace's map, beside it: ``run.trace.json`` has ``run.map``."""
    return name[: len(name) - len(_ending(name))] + MAP_SUFFIX


def picture_of(name: str) -> str:
    """A handout's picture, beside it: ``run.md`` has ``run-final.svg``."""
    return os.path.splitext(name)[0] + PICTURE_SUFFIX


def targets(name: str, kind: str) -> list[str]:
    """The files an export of ``kind`` to ``name`` writes (a trace's map is written beside it
    only when the run's map is no MovingAI file: see :mod:`~tui_search.export.posthoc`)."""
    if kind == "md":
        return [name, picture_of(name)]
    return [name, map_of(name)] if kind == "trace" else [name]


def refuse_existing(name: str, kind: str, force: bool) -> None:
    """A ValueError when a file the export would write exists and ``force`` is not given."""
    refuse_any(targets(name, kind), force)


def refuse_any(names: list[str], force: bool) -> None:
    """A ValueError when one of ``names`` exists and ``force`` is not given."""
    if force:
        return
    for target in names:
        if os.path.lexists(target):
            raise ValueError(f"{describe_name(target)} exists: --force replaces it")

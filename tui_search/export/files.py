"""An export made (:func:`make_export`): the run filmed by the app
(:mod:`~tui_search.export.frames`), written in the file's kind, never over a file without
``--force``; and what the app's palette exports with (:class:`AppExporter`).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from importlib.util import find_spec

from tui_search.engine.util.atomic import os_reason, write_atomically
from tui_search.engine.util.filenames import describe_name
from tui_search.export.job import Job
from tui_search.export.kinds import (
    DEFAULT_FPS,
    DEFAULT_HANDOUT_STEPS,
    HOLD_SECONDS,
    kind_of,
    picture_of,
    refuse_existing,
    targets,
)
from tui_search.tui.model.session import Session

#: How the GIF extra is installed, from a clone of the project.
NEEDS_PILLOW = ("--export FILE.gif needs Pillow: in the tui-search folder, "
                "pip install -e '.[gif]'")


def make_export(job: Job) -> list[str]:
    """Film ``job``'s run and write it (a Posthoc trace: the run searched, not filmed); the
    files written.  A ValueError (one line) when a file exists without ``force``, the run is
    too big (naming its size), a kind's extra is missing, or a file cannot be written."""
    kind = job.kind
    if kind == "trace":  # no film: the search itself (export/posthoc.py)
        from tui_search.export.posthoc import trace_files

        return _write_all(trace_files(job), job.force)
    refuse_existing(job.target, kind, job.force)
    if kind == "gif" and find_spec("PIL") is None:
        raise ValueError(NEEDS_PILLOW)
    from tui_search.export.frames import film  # Textual: only once an export is made

    shot = film(job)
    if kind == "svg":
        from tui_search.export.svg import svg_of

        files = {job.target: svg_of(shot, job.fps, HOLD_SECONDS,
                                    description=f"{shot.title}, a frame a step").encode()}
    elif kind == "cast":
        from tui_search.export.cast import cast_of

        files = {job.target: cast_of(shot, job.fps, HOLD_SECONDS).encode()}
    elif kind == "gif":
        from tui_search.export.gif import gif_of

        files = {job.target: gif_of(shot, job.fps, HOLD_SECONDS)}
    else:
        from tui_search.export.handout import handout_of

        picture = picture_of(job.target)
        text, still = handout_of(job, shot, os.path.basename(picture))
        files = {job.target: text.encode(), picture: still.encode()}
    return _write_all(files, job.force)


def _write_all(files: dict[str, bytes], force: bool) -> list[str]:
    """Each file written (:func:`_write`); their names."""
    for target, data in files.items():
        _write(target, data, force)
    return list(files)


def _write(target: str, data: bytes, force: bool) -> None:
    """``data`` into ``target``: replacing it only with ``force`` (atomically), else into a
    new file (created exclusively: a file made in the meantime is not replaced either)."""
    try:
        if force:
            write_atomically(target, data)
        else:
            with open(target, "xb") as out:
                out.write(data)
    except FileExistsError:
        raise ValueError(f"{describe_name(target)} exists: --force replaces it") from None
    except OSError as err:
        raise ValueError(f"{describe_name(target)}: cannot write: {os_reason(err)}") from None


class AppExporter:
    """What the app's palette exports with: the command line gives it to the app
    (:func:`tui_search.cli.main.build_app`), which names no module of this package -- it
    asks this object what a name may be, and for the work of an export of the session as it
    is, to do in a thread."""

    @staticmethod
    def problem(target: str) -> str | None:
        """Why ``target`` can be no export (its ending), or None."""
        try:
            kind_of(target)
        except ValueError as exc:
            return str(exc).removeprefix("--export ")
        return None

    @staticmethod
    def targets(target: str) -> list[str]:
        """The files an export to ``target`` writes."""
        return targets(target, kind_of(target))

    @staticmethod
    def work(session: Session, target: str, theme: str | None, force: bool
             ) -> Callable[[], list[str]]:
        """The export of ``session``'s searches on its map as they are now (a copy: the
        session may change meanwhile), to run in a thread; it returns the files written or
        raises a ValueError saying why not.  A replayed trace is no search to film."""
        if session.jumps.replay is not None:
            raise ValueError("an export films the app's own searches: not a replayed trace")
        if not session.runs:
            raise ValueError("place a start and a goal first")
        contenders = session.contenders
        first = contenders[0]
        several = len(contenders) > 1
        job = Job(target, session.grid.copy(), session.map_path, session.unsaved_name,
                  first.algorithm, session.semantics if several else first.semantics,
                  session.spec if several else None, session.max_steps, theme, DEFAULT_FPS,
                  "full", force, DEFAULT_HANDOUT_STEPS)
        return lambda: make_export(job)

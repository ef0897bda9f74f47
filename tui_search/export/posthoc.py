"""A run as Posthoc's search trace (``.trace.json``, ``.trace.yaml``), and its map beside it.

The trace is written by :func:`tui_search.engine.traces.posthoc.posthoc_trace` (the format's
one writer, as ``--trace-format posthoc`` writes it) from the search the other exports film:
the same map, start and goal, search, choices and step limit.  Posthoc opens a grid map as a
MovingAI ``.map`` file: unless the run's map is one, unchanged on disk, it is written beside
the trace (``run.trace.json`` has ``run.map``), as the app saves a ``.map``.  The trace names
the map's file under its ``tui-search`` key, with the search and its choices.  The same run
gives the same bytes.
"""

from __future__ import annotations

import os

from tui_search.engine.maps.source import MOVINGAI
from tui_search.engine.maps.write import format_map, save_notes
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.traces.posthoc import posthoc_trace
from tui_search.export.job import Job
from tui_search.export.kinds import map_of, refuse_any

#: What a trace of several searches is told (a Posthoc trace is one search's).
ONE_SEARCH = ("a Posthoc trace holds one search: export the searches of --compare one at a "
              "time (-a KEY)")


def movingai_file(job: Job) -> str | None:
    """The MovingAI file on disk that is ``job``'s map, cell for cell (None: none is)."""
    grid, path = job.grid, job.path
    source = grid.source
    if path is None or source is None or source.kind != MOVINGAI:
        return None
    if format_map(grid, MOVINGAI).text() != source.text():  # edited since it was read
        return None
    return os.fspath(path)


def trace_files(job: Job) -> dict[str, bytes]:
    """The files of ``job``'s trace export by name: the trace, and the map beside it unless
    the map is a MovingAI file (:func:`movingai_file`).  A ValueError (one line) for a
    comparison, or a file that exists without ``force``."""
    if job.compare is not None:
        raise ValueError(ONE_SEARCH)
    grid = job.grid
    on_disk = movingai_file(job)
    if on_disk is None:
        map_name = map_of(job.target)
        refuse_any([job.target, map_name], job.force)  # before the search: it may be long
        files = {map_name: format_map(grid, MOVINGAI).text().encode()}
        named = os.path.basename(map_name)
    else:
        refuse_any([job.target], job.force)
        files = {}
        folder = os.path.dirname(os.path.abspath(job.target))
        named = os.path.relpath(os.path.abspath(on_disk), folder)
    about: dict[str, object] = {
        "map": named,
        "search": job.algorithm,
        "choices": job.semantics.as_json(get_algorithm(job.algorithm)),
        "max_steps": job.max_steps,
    }
    notes = save_notes(grid, MOVINGAI) if on_disk is None else []
    if notes:
        about["map_notes"] = notes
    text, _ = posthoc_trace(grid, job.algorithm, job.semantics, job.max_steps,
                            as_yaml=job.target.lower().endswith(".yaml"), about=about)
    return {job.target: text.encode(), **files}

"""The teaching model, with no UI: maps, the searches, their recorded runs, traces and the course.

Its folders are layers, each importing only those before it (a test holds it):
``util`` <- ``maps`` <- ``search`` <- ``run`` <- ``traces``, ``course``.

* :mod:`~tui_search.engine.util`: atomic writes, file names, frozen values, numbers;
* :mod:`~tui_search.engine.maps`: the grid, its files (text, MovingAI, terrain, scenarios),
  generators;
* :mod:`~tui_search.engine.search`: the registry, the choices, heuristics, the reference loop, the
  fast loops;
* :mod:`~tui_search.engine.run`: a recorded run and its named queries;
* :mod:`~tui_search.engine.traces`: another program's trace: read, checked, diagnosed, replayed;
* :mod:`~tui_search.engine.course`: exercises, their conditions, and lessons.
"""

"""tui-search: search taught in a terminal, on grids: BFS, DFS and iterative deepening, then
uniform-cost, greedy best-first and A*.

* :mod:`~tui_search.launch`: the ``tui-search`` command;
* ``__main__``: ``python -m tui_search``, the same;
* :mod:`~tui_search.cli`: the command line, and the commands that run without the app;
* :mod:`~tui_search.serve`: the class server (``--serve``);
* :mod:`~tui_search.export`: a run exported: animated SVG, asciicast, GIF, a handout;
* :mod:`~tui_search.plain`: plain mode (``--plain``): the app as lines, for screen readers;
* :mod:`~tui_search.tui`: the Textual app;
* :mod:`~tui_search.engine`: the teaching model, with no UI.
"""

__version__ = "0.1.0"

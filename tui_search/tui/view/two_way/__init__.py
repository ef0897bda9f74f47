"""A bidirectional search shown, without Textual: what its map draws, what its lines say and
which lines of its pseudocode a step ran (the app shows a
:class:`~tui_search.engine.run.bidirectional.BiRun` through these).

* :mod:`~tui_search.tui.view.two_way.cells`: each cell's drawing code from the two halves,
  the best meeting and the path;
* :mod:`~tui_search.tui.view.two_way.words`: the counts, the narration, why it stopped, the
  panels' titles;
* :mod:`~tui_search.tui.view.two_way.code_lines`: the pseudocode's lines the step ran.
"""

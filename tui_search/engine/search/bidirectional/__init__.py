"""Bidirectional search: a forward search from the start and a backward one from the goal, in
turn, until they meet -- the reference loop's bidirectional form (the specification, streamed
by the headless runs; recorded for the app by :mod:`tui_search.engine.run.bidirectional`).

* :mod:`~tui_search.engine.search.bidirectional.backward`: the backward search's space, the
  moves reversed;
* :mod:`~tui_search.engine.search.bidirectional.loop`: the two searches in turn, their meeting
  and the stopping rule (``first-meeting`` or ``proven``);
* :mod:`~tui_search.engine.search.bidirectional.pseudo`: their pseudocode's lines.
"""

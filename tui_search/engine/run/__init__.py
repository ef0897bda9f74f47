"""A recorded run: a search's steps, and the state of the search at any step, asked by name.

* :mod:`~tui_search.engine.run.recorded`: the run (``Run``) and its parts;
* :mod:`~tui_search.engine.run.recording`: the loop run in chunks into a record;
* :mod:`~tui_search.engine.run.queries`: parents, moves, costs and the path of a record;
* :mod:`~tui_search.engine.run.position`: the state after ``k`` steps, moved either way;
* :mod:`~tui_search.engine.run.facets`: the named query facets (``nodes``, ``steps``, ``now``);
* :mod:`~tui_search.engine.run.frontier`: the frontier at a position, in the order it comes out;
* :mod:`~tui_search.engine.run.rebuild`: the bulk loops of a long jump;
* :mod:`~tui_search.engine.run.peak`: the largest frontier up to any step;
* :mod:`~tui_search.engine.run.blocked`: why a search found no path;
* :mod:`~tui_search.engine.run.bidirectional`: a bidirectional search as two runs, one position;
* :mod:`~tui_search.engine.run.each_step`: a whole search at once, each step handed on.
"""

"""The fast search loops that record every expansion, for the app's runs: one module a family.

The reference -- the definition of every algorithm under every choice -- is the generic loop of
:mod:`tui_search.engine.search.reference`; each loop here is held equal to it, array for array, by a
hypothesis test in ``tests/engine``.  They exist because they pay: the app records a million
expansions in about the time a bare BFS takes.

* :mod:`~tui_search.engine.search.loops.tutorial`: BFS and DFS under the tutorial's rules, the hot
  paths;
* :mod:`~tui_search.engine.search.loops.general`: BFS and DFS, graph search, under any other choice;
* :mod:`~tui_search.engine.search.loops.tree`: BFS and DFS as tree search;
* :mod:`~tui_search.engine.search.loops.iddfs`: iterative deepening, under every choice;
* :mod:`~tui_search.engine.search.loops.best_first`: the priority queue's (UCS, greedy, A*);
* :mod:`~tui_search.engine.search.loops.graph_best_first`: the priority queue's on a graph, by
  node numbers (the plain choices);
* :mod:`~tui_search.engine.search.loops.published`: the reference loop recorded, for the choices of
  published code the others do not make (ties, a closed set, recursion, ...);
* :mod:`~tui_search.engine.search.loops.dispatch`: which loop runs an algorithm under given choices;
* :mod:`~tui_search.engine.search.loops.compiled`: which core runs, and the compiled core's loop;
* :mod:`~tui_search.engine.search.loops.buffers`: the chunk buffers the loops write through.

Each loop appends to a :class:`~tui_search.engine.search.record.Record` of a
:class:`~tui_search.engine.search.problem.Problem` and yields after every ``chunk`` expansions, so a
caller (the app, in slices) can stop and show what is there.
"""

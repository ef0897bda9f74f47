"""The searches: what each is, the choices they run under, and the loops that run them.

* :mod:`~tui_search.engine.search.registry`: every algorithm the app knows, as data;
* :mod:`~tui_search.engine.search.choices`: the search choices as one value (``Semantics``);
* :mod:`~tui_search.engine.search.heuristics`: the heuristics and what a move costs;
* :mod:`~tui_search.engine.search.reference`: the reference loop, the specification;
* :mod:`~tui_search.engine.search.space`: what it searches: a grid's cells or a graph's nodes;
* :mod:`~tui_search.engine.search.state`: a state (a cell, a node) and how it is written;
* :mod:`~tui_search.engine.search.graph_problem`: a graph prepared for a recorded run;
* :mod:`~tui_search.engine.search.estimate_check`: is a graph's estimate admissible, consistent;
* :mod:`~tui_search.engine.search.rules`: its frontiers and its rules for what was reached;
* :mod:`~tui_search.engine.search.recursion`: a recursion's calls form, from its neighbours form;
* :mod:`~tui_search.engine.search.problem`: a grid prepared for the fast loops;
* :mod:`~tui_search.engine.search.record`: the flat arrays a loop appends to;
* :mod:`~tui_search.engine.search.outcome`: what a whole search came to;
* :mod:`~tui_search.engine.search.compare`: the searches compared, and their table;
* :mod:`~tui_search.engine.search.pseudocode`: a search's pseudocode from its choices;
* :mod:`~tui_search.engine.search.pseudocode_recursive`: a recursion's pseudocode;
* :mod:`~tui_search.engine.search.loops`: the fast loops, each held equal to the reference;
* :mod:`~tui_search.engine.search.bidirectional`: the reference's bidirectional form, from the
  start and the goal in turn;
* ``_core*.c``: the optional compiled core of those loops.
"""

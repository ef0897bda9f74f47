"""Plain mode (``--plain``): the app as lines of text, for screen readers, braille displays and
SSH, on the app's own Textual-free session; no Textual or Rich here (a test holds it).

* :mod:`~tui_search.plain.mode`: the mode: a command a line in, plain sentences out;
* :mod:`~tui_search.plain.commands`: the commands, what each does, and how a line is read;
* :mod:`~tui_search.plain.telling`: a step in the tutorial's words, the frontier, the tree;
* :mod:`~tui_search.plain.two_way`: a bidirectional search's steps, frontiers and trees, and
  what either kind of run says after a key;
* :mod:`~tui_search.plain.describe`: the map, a row, a column, a cell or around, in words;
* :mod:`~tui_search.plain.settings`: the search settings said, and ``set``;
* :mod:`~tui_search.plain.editing`: the edits of the map, and opening and generating one;
* :mod:`~tui_search.plain.files`: ``save`` and ``save as``, never losing a line.
"""

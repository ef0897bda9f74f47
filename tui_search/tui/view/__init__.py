"""What the screen says and where things go, as plain text and numbers, without Textual.

* :mod:`~tui_search.tui.view.layout`: where the panes go, from the room there is;
* :mod:`~tui_search.tui.view.geometry`: where each map cell is on screen;
* :mod:`~tui_search.tui.view.narration`: the step in the tutorial's words;
* :mod:`~tui_search.tui.view.status_lines`: the status lines' text;
* :mod:`~tui_search.tui.view.pieces`: teaching text that wraps, as styled pieces;
* :mod:`~tui_search.tui.view.readout`: what the run knows of one cell;
* :mod:`~tui_search.tui.view.cell_codes`: the map's drawing codes and glyphs;
* :mod:`~tui_search.tui.view.cell_labels`: what a big cell says;
* :mod:`~tui_search.tui.view.code_trace`: the pseudocode lines a step ran;
* :mod:`~tui_search.tui.view.frontier_rows`: a frontier entry's columns and rows;
* :mod:`~tui_search.tui.view.frontier_text`: the frontier panel's wordings;
* :mod:`~tui_search.tui.view.by_hand_text`: what the by-hand panel and its summary say;
* :mod:`~tui_search.tui.view.tree_listing`: which nodes the tree panel lists;
* :mod:`~tui_search.tui.view.tree_shape`: the search tree's shape, kept in step;
* :mod:`~tui_search.tui.view.tree_window`: a tree's line as a sideways scroll shows it;
* :mod:`~tui_search.tui.view.themes`: the colour themes, as data;
* :mod:`~tui_search.tui.view.graph_layout`: a graph drawn in cells: places, labels, tiles;
* :mod:`~tui_search.tui.view.two_way`: a bidirectional search shown: its cells, its words, its
  code's lines.
"""

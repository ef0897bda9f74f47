"""One widget a module: the map, the panes' panels, the lines under them.

* :mod:`~tui_search.tui.widgets.run_pane`: a search's pane;
* :mod:`~tui_search.tui.widgets.pane_box`: the panes' grid, which says when its room changes;
* :mod:`~tui_search.tui.widgets.grid_view`: the map, drawn with the line API;
* :mod:`~tui_search.tui.widgets.map_lines`: what each row of the map draws;
* :mod:`~tui_search.tui.widgets.graph_view`: a graph, drawn with the line API;
* :mod:`~tui_search.tui.widgets.graph_lines`: what each row of the graph draws;
* :mod:`~tui_search.tui.widgets.cell_style`: how each map cell looks;
* :mod:`~tui_search.tui.widgets.frontier_panel`: the queue, stack or priority queue;
* :mod:`~tui_search.tui.widgets.search_tree`: the search tree panel;
* :mod:`~tui_search.tui.widgets.code_panel`: the pseudocode with the lines the step ran;
* :mod:`~tui_search.tui.widgets.stats`: the status lines;
* :mod:`~tui_search.tui.widgets.cell_readout`: the line that answers "what is this cell?";
* :mod:`~tui_search.tui.widgets.compare_table`: compare mode's table;
* :mod:`~tui_search.tui.widgets.challenge`: the exercise checked live;
* :mod:`~tui_search.tui.widgets.by_hand_panel`: what to do by hand, a mistake named at once;
* :mod:`~tui_search.tui.widgets.legend`: every kind of cell as the map draws it;
* :mod:`~tui_search.tui.widgets.lesson_panel`: the lesson beside the panes;
* :mod:`~tui_search.tui.widgets.key_bar`: the key hints at the bottom;
* :mod:`~tui_search.tui.widgets.map_tree`: the file picker;
* :mod:`~tui_search.tui.widgets.tick_box`: the settings' checkbox, ticked or empty;
* :mod:`~tui_search.tui.widgets.pick_button`: the settings' radio button, a dot or empty;
* :mod:`~tui_search.tui.widgets.error_line`: a prompt's error;
* :mod:`~tui_search.tui.widgets.lazy_parts`: parts mounted the first time they show;
* :mod:`~tui_search.tui.widgets.line_panel`: what the line-API views share;
* :mod:`~tui_search.tui.widgets.wrapped_lines`: lines of pieces, wrapped to the width;
* :mod:`~tui_search.tui.widgets.scrollbars`: scrolling the line-API views cheaply.
"""

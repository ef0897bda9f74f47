"""What the app shows, as state, without Textual: the session and its parts.

* :mod:`~tui_search.tui.model.session`: the map, the searches shown, their runs, the cursor;
* :mod:`~tui_search.tui.model.searches`: which searches the panes show;
* :mod:`~tui_search.tui.model.playback`: the runs' positions moved in lockstep;
* :mod:`~tui_search.tui.model.seek`: runs moved to an end in time-boxed slices;
* :mod:`~tui_search.tui.model.quiz`: predict the next node;
* :mod:`~tui_search.tui.model.by_hand`: the search made by hand, step by step, and its end;
* :mod:`~tui_search.tui.model.class_records`: what the app records of a student (``--records``);
* :mod:`~tui_search.tui.model.boards`: a grid or a graph: its rules, start and goal;
* :mod:`~tui_search.tui.model.map_edits`: the session's edits of the map, and undo;
* :mod:`~tui_search.tui.model.graph_edits`: a graph's edits (start, goal, closed), and undo;
* :mod:`~tui_search.tui.model.cell_edits`: one edit of a cell, or why it is refused;
* :mod:`~tui_search.tui.model.history`: undo, redo, and whether the map differs from its file;
* :mod:`~tui_search.tui.model.replay_jumps`: a replay's first difference and its key;
* :mod:`~tui_search.tui.model.lesson_play`: a lesson's section put on the session;
* :mod:`~tui_search.tui.model.file_rules`: where the app may read and write map files.
"""

"""The modal screens: help, settings, prompts and questions.

* :mod:`~tui_search.tui.dialogs.help`: the keys, the colours, how BFS and DFS work;
* :mod:`~tui_search.tui.dialogs.settings`: the search choices;
* :mod:`~tui_search.tui.dialogs.settings_controls`: the settings' rows of radio buttons and
  compare boxes, built and read;
* :mod:`~tui_search.tui.dialogs.settings_greying`: which choices apply to the searches shown;
  the others greyed out, and why;
* :mod:`~tui_search.tui.dialogs.settings_choice`: what the settings dismiss with;
* :mod:`~tui_search.tui.dialogs.path_prompt`: a file-name prompt with a picker;
* :mod:`~tui_search.tui.dialogs.open_map`: open a map file;
* :mod:`~tui_search.tui.dialogs.save_as`: save the map as;
* :mod:`~tui_search.tui.dialogs.generate_map`: generate a map from a recipe;
* :mod:`~tui_search.tui.dialogs.question`: a question with a row of buttons;
* :mod:`~tui_search.tui.dialogs.confirm_quit`: unsaved edits, before leaving a map;
* :mod:`~tui_search.tui.dialogs.confirm_overwrite`: saving onto a file that exists;
* :mod:`~tui_search.tui.dialogs.save_refused`: a refused save's questions;
* :mod:`~tui_search.tui.dialogs.export_prompt`: the file to export the run to;
* :mod:`~tui_search.tui.dialogs.by_hand_summary`: the end of a run by hand, and its replay;
* :mod:`~tui_search.tui.dialogs.visitor_name`: a served visitor says who they are.
"""

"""The main screen: the screen of panes, its keys, and what it does with files.

* :mod:`~tui_search.tui.screens.main`: the keys and the widgets' messages, as calls on the session;
* :mod:`~tui_search.tui.screens.panes`: the screen of panes, and the session pushed down to them;
* :mod:`~tui_search.tui.screens.keys`: the key table;
* :mod:`~tui_search.tui.screens.by_hand`: the search made by hand, on a screen of its own;
* :mod:`~tui_search.tui.screens.by_hand_keys`: the by-hand screen's key table;
* :mod:`~tui_search.tui.screens.playback_driver`: playback and seeks on the screen;
* :mod:`~tui_search.tui.screens.exercise_check`: the challenge's verdict on the map now;
* :mod:`~tui_search.tui.screens.file_commands`: saving, opening, never losing edits;
* :mod:`~tui_search.tui.screens.save_questions`: what a refused save asks;
* :mod:`~tui_search.tui.screens.export_command`: the palette's Export, made by the exporter
  the app is given.
"""

"""The Textual app.  Its folders are layers: ``model`` <- ``view`` <- ``widgets`` <-
``dialogs`` <- ``screens`` <- the app; ``model`` and ``view`` import no Textual.

* :mod:`~tui_search.tui.app`: the app: themes, the config file, start-up;
* :mod:`~tui_search.tui.commands`: the app's commands in the command palette;
* :mod:`~tui_search.tui.config`: what the app remembers between runs;
* :mod:`~tui_search.tui.model`: the session and its parts, without Textual;
* :mod:`~tui_search.tui.view`: layout and text, without Textual;
* :mod:`~tui_search.tui.widgets`: one widget a module;
* :mod:`~tui_search.tui.dialogs`: the modal screens;
* :mod:`~tui_search.tui.screens`: the main screen, its keys and its file commands.
"""

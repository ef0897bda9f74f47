"""The class server (``--serve``): the app in web browsers, one app per visitor.

* :mod:`~tui_search.serve.web`: the server, its rules for a class, and what the served app does;
* :mod:`~tui_search.serve.addresses`: this computer's own addresses, for the banner's links;
* :mod:`~tui_search.serve.guard`: who may talk to it (host names, the token off loopback);
* :mod:`~tui_search.serve.visit`: one visitor's websocket and app;
* :mod:`~tui_search.serve.teacher`: the teacher's page of the class's records, its own token;
* :mod:`~tui_search.serve.forks`: the fork server that starts each visitor's app.
"""

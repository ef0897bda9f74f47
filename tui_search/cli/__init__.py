"""The command line: argv made into one frozen options value, and the commands that run
without the app (headless searches, the class report, trace checks).

* :mod:`~tui_search.cli.main`: parse, check, then start the app, the server or a headless run;
* :mod:`~tui_search.cli.flags`: what the flags ask for (the map, the choices, the searches);
* :mod:`~tui_search.cli.headless`: one search, a comparison or the pseudocode, as text or JSON;
* :mod:`~tui_search.cli.report`: maps graded on an exercise, and the class report;
* :mod:`~tui_search.cli.traces`: ``--check-trace`` and reading a ``--replay``.
"""

"""The command line: argv made into one frozen options value, then the app, the class server,
or a command that runs without the app.

* :mod:`~tui_search.cli.main`: the options, then what they ask for, to an exit code;
* :mod:`~tui_search.cli.parse`: argv made into the options, checked, with what they name read;
* :mod:`~tui_search.cli.options`: the options, one frozen typed value;
* :mod:`~tui_search.cli.parser`: the flags and their help (argparse, seen nowhere else);
* :mod:`~tui_search.cli.serve_flags`: the flags of ``--serve``, and a visitor's command line;
* :mod:`~tui_search.cli.class_flags`: the flags of a class: by hand, records, the class list;
* :mod:`~tui_search.cli.flags`: what the options ask for: the map, the choices, the searches;
* :mod:`~tui_search.cli.graphs`: a graph as the map: built in or a file, its start and goal;
* :mod:`~tui_search.cli.headless`: one search, a comparison or the pseudocode, as text or JSON;
* :mod:`~tui_search.cli.report`: maps graded on an exercise, and the class report;
* :mod:`~tui_search.cli.records_report`: a records folder read back as the class's table;
* :mod:`~tui_search.cli.traces`: ``--check-trace`` and reading a ``--replay``;
* :mod:`~tui_search.cli.course`: a CS188 autograder's ``FILE.test`` opened or run headless;
* :mod:`~tui_search.cli.search_py`: ``--check-search-py``: a student's search.py run, checked;
* :mod:`~tui_search.cli.fork_entry`: the served apps' fork server, as a process.
"""

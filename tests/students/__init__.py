"""Students' searches and the code they copy, written the way a student, a textbook or a
library writes them: plain Python, no tui_search.  Each module's ``search(rows, moves)`` reads
a text map's rows (``S`` the start, ``G`` the goal, ``#`` an obstacle) and returns the trace
it logs, one JSON line an expansion, as its author would log it; run as a script it prints the
trace of the map file it is given.  ``tests/test_students.py`` checks that the diagnosis names
each and that ``-a`` with its flags matches it."""

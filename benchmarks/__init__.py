"""The benchmarks of tui-search (``benchmarks/bench.py`` runs them; see README.md here).

A package so that its modules import each other by one name whether ``bench.py`` is run as a
script or the tests import them; not part of the installed wheel.
"""

"""tui-search: uninformed search (BFS, DFS, iterative deepening) on a grid, taught in a terminal."""

__version__ = "0.1.0"

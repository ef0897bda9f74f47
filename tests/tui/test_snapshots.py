"""Pictures of the app (SVG snapshots), one behaviour each; the docstring says what the picture
must show.  Update with ``pytest tests/tui --snapshot-update`` and look at every changed SVG
before accepting it."""

from __future__ import annotations

from tests.tui.test_app import open_grid, tutorial_app
from tui_search.engine.maps.grid import Grid
from tui_search.tui.app import SearchApp

SIZE = (100, 30)


def patterned_grid(width: int, height: int, start, goal) -> Grid:
    """A big map with a regular pattern of wall segments (deterministic, with gaps)."""
    grid = open_grid(width, height, start=start, goal=goal)
    for y in range(3, height, 6):
        for x in range(width):
            if (x // 7 + y) % 3:
                grid.set_blocked((x, y), True)
    for x in range(5, width, 11):
        for y in range(height):
            if (y // 5 + x) % 4 == 0:
                grid.set_blocked((x, y), True)
    for cell in (start, goal):
        grid.set_blocked(cell, False)
    return grid


def test_start_screen(snap_compare) -> None:
    """The tutorial's map at step 0: S (green) top-left with the cursor on it, G (yellow),
    red obstacles; the queue holds START; the status says step 0/22 and 'START (0,0) is on the
    queue'; the footer greys out p."""
    assert snap_compare(tutorial_app(), terminal_size=SIZE)


def test_bfs_after_four_steps(snap_compare) -> None:
    """BFS after four expansions, as the tutorial tells it: (0,0), (0,1), (0,2) expanded (blue
    ●), (1,2) being expanded (◉), frontier ○ at (0,3) (1,3) (2,2) (2,1); narration 'Expanded
    (1,2): added E, NE to the queue'."""
    assert snap_compare(tutorial_app(), press=["n"] * 4, terminal_size=SIZE)


def test_dfs_after_three_steps(snap_compare) -> None:
    """DFS after three expansions: the stack panel (LIFO) with NE on top; narration 'Expanded
    (1,2): added SW, S, E, NE to the stack'."""
    assert snap_compare(tutorial_app("dfs"), press=["n"] * 3, terminal_size=SIZE)


def test_bfs_at_the_end_with_the_path(snap_compare) -> None:
    """BFS at its last step: the path ◆ from S to G (7 moves, cost 8.66) over the blue
    expanded cells; narration 'Goal (5,2) found from (5,1)' with the tutorial's bound; n, space
    greyed."""
    assert snap_compare(tutorial_app(), press=["end"], terminal_size=SIZE)


def test_dfs_at_the_end(snap_compare) -> None:
    """DFS at its last step: only 7 nodes expanded, the same 7-move path as BFS."""
    assert snap_compare(tutorial_app("dfs"), press=["end"], terminal_size=SIZE)


def test_iddfs_mid_run(snap_compare) -> None:
    """Iterative deepening part-way (step 20): the status and the tree show the depth limit;
    cells of the current iteration only are coloured."""
    assert snap_compare(tutorial_app("iddfs"), press=["n"] * 20, terminal_size=SIZE)


def test_help_screen(snap_compare) -> None:
    """The help screen over the app: the keys (from the binding table), the colour/glyph
    legend and how BFS (FIFO queue) and DFS (LIFO stack) work."""
    assert snap_compare(tutorial_app(), press=["question_mark"], terminal_size=(100, 40))


def test_big_map_scrolled_to_the_node_being_expanded(snap_compare) -> None:
    """A 160x100 map bigger than the panel, start at (140,80): the view has scrolled so the
    node being expanded (◉) and its frontier are in view, with scrollbars."""
    grid = patterned_grid(160, 100, start=(140, 80), goal=(2, 2))
    assert snap_compare(SearchApp(grid), press=["n"] * 6, terminal_size=SIZE)


def test_80_by_24(snap_compare) -> None:
    """The smallest usual terminal: every part still readable, the footer fits (ends with
    q Quit), the map centred in its panel."""
    assert snap_compare(tutorial_app(), press=["n"] * 3, terminal_size=(80, 24))


def test_too_small(snap_compare) -> None:
    """A 50x15 terminal: only the centred message 'Terminal too small: need at least 60×20,
    have 50×15'."""
    assert snap_compare(tutorial_app(), terminal_size=(50, 15))


def test_overview(snap_compare) -> None:
    """Overview (z) of a 160x100 map: the whole map visible in half blocks of 2x2 cells (160
    columns do not fit the 144 the side column leaves), the BFS search at its end painted blue
    with the green path; a block shows its most important state, so the thin walls' blocks,
    all searched, are blue; the frontier left at the end along the left edge is black."""
    grid = patterned_grid(160, 100, start=(140, 80), goal=(2, 2))
    assert snap_compare(SearchApp(grid), press=["end", "z"], terminal_size=(200, 60))


def test_no_start_or_goal(snap_compare) -> None:
    """A map without start and goal (a MovingAI map opened bare): the map, no panels, and
    'Place a start (s) and a goal (g) to search'."""
    assert snap_compare(SearchApp(Grid(20, 8)), terminal_size=SIZE)


def test_quit_with_unsaved_edits_asks(snap_compare) -> None:
    """After an edit, q shows the 'Unsaved edits' question with Save / Quit / Stay."""
    assert snap_compare(tutorial_app(), press=["down", "o", "q"], terminal_size=SIZE)


def test_bfs_after_four_steps_with_the_code_panel(snap_compare) -> None:
    """BFS after four expansions with the Code panel (v) in the search tree's place: BFS's
    pseudocode, lines 4-10 lit with ▶ and the lit colour (the while, the take-off, the loop
    over successors, "off the map or an obstacle" and "already visited" skipping, push back,
    mark visited); the narration adds 'line 8: (0,1), (0,2), (0,3) and (1,3) are already
    visited, skipped'."""
    assert snap_compare(tutorial_app(), press=["n"] * 4 + ["v"], terminal_size=SIZE)

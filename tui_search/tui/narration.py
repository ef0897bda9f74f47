"""What the search is doing, in the tutorial's words -- plain text, no Textual, so it is tested
directly.

The tutorial tells BFS as "South is taken out of the queue and expanded. S and SE are the
successors and they are added to the queue" and DFS the same with a stack; these functions say
the same thing about the step the run is at.
"""

from __future__ import annotations

from tui_search.engine.grid import Cell, path_cost
from tui_search.engine.run import Run
from tui_search.engine.search import ALGORITHM_NAMES

SHORT_NAMES = {"bfs": "BFS", "dfs": "DFS", "iddfs": "IDDFS"}


def group_digits(n: int) -> str:
    """``1234567`` -> ``1,234,567``: the one digit grouping of every count the app shows (the
    status line, the panels' titles, the README)."""
    return f"{n:,}"


def gave_up_text(run: Run) -> str:
    """Why a run stopped unfinished, naming the flag that moves the limit."""
    return f"gave up at --max-steps {group_digits(run.max_steps)}"


def cell_text(cell: Cell | None) -> str:
    return "-" if cell is None else f"({cell[0]},{cell[1]})"


def frontier_word(run: Run) -> str:
    """``queue`` for BFS (FIFO), ``stack`` for DFS and iterative deepening (LIFO)."""
    return "queue" if run.algorithm == "bfs" else "stack"


def _node_text(run: Run, g: int) -> str:
    """An event as the tutorial names it: START, or the cell (and the move that reached it)."""
    cell = cell_text(run.gen_cell(g))
    return f"START {cell}" if run.gen_parent(g) < 0 else cell


def narrate(run: Run) -> str:
    """One line about the step just taken (or, at step 0, about what happens next)."""
    word = frontier_word(run)
    k = run.k
    limit = run.depth_limit() if run.algorithm == "iddfs" else None
    if k == 0:
        first = f"START {cell_text(run.grid.start)} is on the {word}"
        if limit is not None:
            first += f" (depth limit {limit})"
        if run.at_end and run.found:
            return f"{first}: the start is the goal"
        return f"{first}. Press n to expand it."
    expanded = run.rec.exp(k)
    node = _node_text(run, expanded)
    added = run.added_now()
    dirs = [run.gen_dir(h) for h in added]
    prefix = ""
    if limit is not None and run.rec.iter_first_step[run.iteration_of(k)] == k:
        prefix = f"Depth limit {limit}, a new iteration from START. "
    if run.at_end and run.found:
        goal = cell_text(run.gen_cell(run.rec.goal_gen))
        return f"{prefix}Goal found at {goal} when expanding {node}"
    if dirs:
        text = f"{prefix}Expanded {node}: added {', '.join(dirs)} to the {word}"
    elif limit is not None and run.gen_depth(expanded) >= limit:
        text = f"{prefix}Expanded {node} at the depth limit {limit}: no successors added"
    else:
        text = f"{prefix}Expanded {node}: no new successors"
    if run.at_end and run.gave_up:
        return f"{text}. {gave_up_text(run).capitalize()}"
    if run.at_end:  # done, not found
        if limit is not None:
            return f"{text}. Depth limit {limit} cut nothing off: no path"
        return f"{text}. Frontier empty: no path"
    return text


def status_parts(run: Run) -> list[tuple[str, str]]:
    """The counts as (label, value) pairs, in the order shown."""
    total = run.total
    digits = group_digits
    step = f"{digits(run.k)}/{digits(total) if total is not None else '?'}"
    parts = [
        ("step", step),
        ("expanded", digits(run.expanded)),
        ("generated", digits(run.generated)),
        (frontier_word(run), f"{digits(run.frontier_len())} (peak {digits(run.peak_frontier())})"),
    ]
    if run.algorithm == "iddfs":
        parts.append(("depth limit", str(run.depth_limit())))
    return parts


def result_text(run: Run) -> str:
    """The answer, once the run is at its end: the path's moves and cost, or no path."""
    if not run.at_end:
        return ""
    if not run.found:
        return "no path"
    moves = run.moves() or []
    return f"path: {len(moves)} moves, cost {path_cost(moves):.2f}"


def algorithm_title(algorithm: str) -> str:
    return f"{SHORT_NAMES[algorithm]} · {ALGORITHM_NAMES[algorithm]}"

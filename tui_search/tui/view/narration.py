"""What the search is doing, in the tutorial's words -- plain text, no Textual, so it is tested
directly.

The tutorial tells BFS as "South is taken out of the queue and expanded. S and SE are the
successors and they are added to the queue" and DFS the same with a stack; these functions say
the same thing about the step the run is at.
"""

from __future__ import annotations

from typing import TYPE_CHECKING
from weakref import WeakKeyDictionary

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.registry import get_algorithm
from tui_search.engine.search.state import State, as_cell, state_text
from tui_search.engine.util.numbers import group_digits, power_text
from tui_search.tui.view.code_trace import line_notes

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph


def gave_up_text(run: Run) -> str:
    """Why a run stopped unfinished, naming the flag that moves the limit."""
    return f"gave up at --max-steps {group_digits(run.max_steps)}"


def cell_text(cell: State | None) -> str:
    return state_text(cell)


def frontier_word(run: Run) -> str:
    """``queue`` for a FIFO frontier (BFS), ``stack`` for a LIFO one (DFS, IDDFS), ``priority
    queue`` for the cost-ordered searches."""
    return run.algo.frontier.noun


def costs_text(run: Run, g: int) -> str:
    """Event ``g``'s priority said with what it adds up: "f = 7.24 (g 4.41 + h 2.83)",
    weighted A*'s "f = 10.07 (g 4.41 + 2 × h 2.83)", "g = 4.41", "h = 2.83 (g 4.41)"; empty
    for a queue or a stack."""
    costs = run.nodes.costs(g)
    if costs is None:
        return ""
    cost, h, f = costs
    order = run.algo.priority
    if order == "g":
        return f"g = {cost:.2f}"
    if order == "h":
        return f"h = {h:.2f} (g {cost:.2f})"
    weight = run.semantics.weight
    if weight != 1.0:  # weighted A*: f = g + W·h
        return f"f = {f:.2f} (g {cost:.2f} + {weight:g} × h {h:.2f})"
    return f"f = {f:.2f} (g {cost:.2f} + h {h:.2f})"


def _reopened(run: Run, added: range) -> list[str]:
    """What the step's pushes did to cells pushed before (a cost-ordered search pushes a cell
    again only with a lower g): "(4,4) re-opened with a lower g" when it had been expanded,
    "(4,4) reached with a lower g" when it was still waiting (or only taken off stale: greedy
    search takes equal priorities in push order, so a cell's costlier entry can come off
    before its cheaper one, and a discarded step is no expansion)."""
    out = []
    for h in added:
        cell = run.nodes.cell(h)
        generated, expanded = run.now.times_reached(cell)
        if expanded:
            out.append(f"{cell_text(cell)} re-opened with a lower g")
        elif generated > 1:
            out.append(f"{cell_text(cell)} reached with a lower g")
    return out


#: At most this many successors' terrain costs said in one step's narration.
TERRAIN_NOTES = 3


def _terrain(run: Run, expanded: int, added: range) -> list[str]:
    """What the terrain added to the step's successors' g: "(3,4) costs 5: g 7.41 → 12.41"
    (the expanded node's g, then the successor's), for those that do not cost 1."""
    costs = run.nodes.costs(expanded)
    if run.graph is not None:  # a graph's roads cost what they cost: no terrain
        return []
    grid = run.grid
    if costs is None or grid.costs is None:
        return []
    out = []
    for h in added:
        cell = as_cell(run.nodes.cell(h))
        reached = run.nodes.costs(h)
        if grid.cost(cell) != 1.0 and reached is not None:
            out.append(f"{cell_text(cell)} costs {grid.cost(cell):g}: "
                       f"g {costs[0]:.2f} → {reached[0]:.2f}")
    if len(out) > TERRAIN_NOTES:
        out[TERRAIN_NOTES:] = [f"{len(out) - TERRAIN_NOTES} more on terrain"]
    return out


def node_text(run: Run, g: int) -> str:
    """An event as the tutorial names it: START, or the cell (and the move that reached it)."""
    cell = cell_text(run.nodes.cell(g))
    return f"START {cell}" if run.nodes.parent(g) < 0 else cell


def narrate(run: Run, code: bool = False) -> str:
    """One line about the step just taken (or, at step 0, about what happens next); with
    ``code`` (the Code panel shown), naming the lines that skipped a successor or discarded
    the node: "...; line 8: (0,1) is already visited, skipped"."""
    text = _narrate(run)
    if code:
        text = "; ".join([text, *line_notes(run)])
    return text


def _narrate(run: Run) -> str:
    word = frontier_word(run)
    k = run.k
    limit = run.steps.depth_limit() if run.algo.iterative else None
    if k == 0:
        return _before_the_first_step(run, word, limit)
    expanded = run.steps.expanded_event(k)
    node = node_text(run, expanded)
    costs = costs_text(run, expanded)
    if costs:
        node = f"{node} {costs}"
    prefix = ""
    f_limits = run.steps.f_limits()
    new_iteration = run.steps.first_of_iteration(run.steps.iteration_of(k)) == k
    if limit is not None and new_iteration:
        prefix = f"Depth limit {group_digits(limit)}, a new iteration from START. "
    elif f_limits is not None and new_iteration and run.steps.iteration_of(k):
        prefix = (f"f-limit {f_limits[0]:.2f} (the smallest f cut off before), a new "
                  "iteration from START. ")
    if f_limits is not None and run.steps.is_cut_off(k):
        limit_now, next_limit = f_limits
        return _how_it_ended(run, f"{prefix}Took {node} off the {word}: over the f-limit "
                             f"{limit_now:.2f}, cut off (the next limit at most "
                             f"{next_limit:.2f})", word, limit)
    if run.at_end and run.found:
        goal = cell_text(run.nodes.cell(run.nodes.goal))
        if run.nodes.goal == expanded:  # the goal tested when taken off the frontier
            return f"{prefix}Took the goal {goal} off the {word}: found"
        return f"{prefix}Goal {goal} found from {node}"
    return _how_it_ended(run, prefix + what_the_step_did(run, node, expanded, word, limit),
                         word, limit)


def _before_the_first_step(run: Run, word: str, limit: int | None) -> str:
    """Step 0: the start on the frontier, and what the first step does."""
    first = f"START {cell_text(run.start)} is on the {word}"
    f_limits = run.steps.f_limits()
    if limit is not None:
        first += f" (depth limit {group_digits(limit)})"
    elif f_limits is not None:  # IDA*: its first limit, the start's own f
        first += f" (f-limit {f_limits[0]:.2f}, the start's f)"
    if run.at_end and run.found:
        return f"{first}: the start is the goal"
    return f"{first}. Press n to expand it."


def what_the_step_did(run: Run, node: str, expanded: int, word: str, limit: int | None
                       ) -> str:
    """The step's node (``node``, event ``expanded``) discarded, or expanded and what that
    added to the frontier."""
    added = run.now.added_now()
    dirs = [run.nodes.move(h) for h in added]
    if run.steps.is_discarded(run.k) and run.algo.weighted:
        return (f"Took {node} off the {word}: stale (its cell was reached with a "
                f"lower g since), discarded")
    if run.steps.is_discarded(run.k):
        return f"Took {node} off the {word}: already expanded, discarded"
    if dirs and run.algo.weighted:
        text = f"Expanded {node}: added {', '.join(dirs)}"
        reopened = _reopened(run, added)
        if reopened:
            text += "; " + ", ".join(reopened)
        terrain = _terrain(run, expanded, added)
        if terrain:
            text += "; " + ", ".join(terrain)
        return text
    if dirs:
        return f"Expanded {node}: added {', '.join(dirs)} to the {word}"
    if limit is not None and run.nodes.depth(expanded) >= limit:
        return (f"Expanded {node} at the depth limit {group_digits(limit)}: no successors "
                "added")
    return f"Expanded {node}: no new successors"


def _how_it_ended(run: Run, text: str, word: str, limit: int | None) -> str:
    """``text`` and, once the run is at its end without the goal, why it ended there."""
    if not run.at_end:
        return text
    if run.gave_up:
        return f"{text}. {gave_up_text(run).capitalize()}"
    if run.now.frontier_len() and limit is None:
        # ended with cells still to expand: only a replayed trace stops so (a search of
        # the app goes on until its frontier is empty), and nothing blocked it
        return (f"{text}. It stops here, {group_digits(run.now.frontier_len())} still on the "
                f"{word}: no path found")
    why = blocked_by(run)
    why = f" — {why}" if why else ""
    f_limits = run.steps.f_limits()
    if f_limits is not None:
        return f"{text}. f-limit {f_limits[0]:.2f} cut nothing off: no path{why}"
    if limit is not None:
        return f"{text}. Depth limit {group_digits(limit)} cut nothing off: no path{why}"
    return f"{text}. Frontier empty: no path{why}"


_BLOCKED: WeakKeyDictionary[Run, str | None] = WeakKeyDictionary()


#: Maps bigger than this are not searched again to name the rule that blocked a path (up to
#: three BFS runs, too slow on the biggest maps: benchmarks/README.md, "limits").
BLOCKED_BY_CELLS = 300_000


def blocked_by(run: Run) -> str | None:
    """The rule that left the map without a path, if one did (searched once per run, on
    maps of at most :data:`BLOCKED_BY_CELLS` cells: the app must not freeze to say it).  Never
    for a replayed trace: its rules are the matched search's, not ones the trace declared."""
    if run.graph is not None:  # a graph's rules block no road
        return None
    too_big = run.grid.width * run.grid.height > BLOCKED_BY_CELLS
    if run.replayed or run.semantics.is_default or too_big:
        return None
    if run not in _BLOCKED:
        from tui_search.engine.run.blocked import blocking_rule  # only when a choice is changed

        _BLOCKED[run] = blocking_rule(run.grid, run.semantics)
    return _BLOCKED[run]


def status_parts(run: Run) -> list[tuple[str, str]]:
    """The counts as (label, value) pairs, in the order shown."""
    total = run.total
    digits = group_digits
    step = f"{digits(run.k)}/{digits(total) if total is not None else '?'}"
    parts = [
        ("step", step),
        ("expanded", digits(run.now.expanded)),
    ]
    if run.k and run.algo.weighted:  # the node just expanded: "f 7.24 (g 4.41 + h 2.83)"
        name, _, value = costs_text(run, run.steps.expanded_event(run.k)).partition(" = ")
        parts.insert(1, (name, value))
    if (run.semantics.visit == "expand" or run.algo.queued) and not run.semantics.tree_search:
        parts.append(("discarded", digits(run.now.discarded)))
    parts += [
        ("generated", digits(run.now.generated)),
        (frontier_word(run),
         f"{digits(run.now.frontier_len())} (peak {digits(run.steps.peak_frontier())})"),
    ]
    f_limits = run.steps.f_limits()
    if f_limits is not None:  # IDA*: the limit in force, and the next as it stands
        parts.append(("f-limit", f"{f_limits[0]:.2f}"))
        parts.append(("next", "∞" if f_limits[1] == float("inf") else f"{f_limits[1]:.2f}"))
    elif run.algo.iterative:
        parts.append(("depth limit", str(run.steps.depth_limit())))
    return parts


def result_text(run: Run) -> str:
    """The answer, once the run is at its end: the path's moves and cost, or no path."""
    if not run.at_end:
        return ""
    if not run.found:
        return "no path"
    moves = run.moves() or []
    cost = run.path_cost()
    path = run.path() or []
    if run.graph is not None and len(path) <= ROUTE_NAMED:  # "Arad → Sibiu → …, cost 418"
        text = f"path {' → '.join(map(str, path))}, cost {cost:g}"
    elif run.graph is not None:
        text = f"path: {group_digits(len(moves))} roads, cost {cost:g}"
    else:
        text = f"path: {group_digits(len(moves))} moves, cost {cost:.2f}"
    lowest = lowest_cost(run)
    weight = run.semantics.weight if run.algo.priority == "g+h" else 1.0
    if lowest is not None and weight != 1.0:  # weighted A*: the ratio its bound is about
        text += f" ({weight_ratio(cost, lowest)} the lowest, {lowest:.2f})"
    elif lowest is not None:
        text += " (the lowest)" if cost <= lowest * (1 + 1e-9) else f" (lowest {lowest:.2f})"
    return f"{text} · {bound_text(run)}"


def weight_ratio(cost: float, lowest: float) -> str:
    """A path's cost over the lowest, as weighted A*'s bound says it: "1.08 ×"."""
    return f"{cost / lowest if lowest > 0 else 1.0:.2f} ×"


def weight_bound(run: Run) -> str:
    """Weighted A*'s promise: "at most 2 × the optimum" ("" for any other search, A* with
    weight 1, or an inadmissible heuristic, which promises nothing)."""
    weight = run.semantics.weight
    if run.algo.priority != "g+h" or weight == 1.0 or not run.admissible:
        return ""
    return f"at most {weight:g} × the optimum"


_LOWEST: WeakKeyDictionary[Run, float | None] = WeakKeyDictionary()


#: A graph's path is named node by node up to this many nodes (beyond: its roads counted).
ROUTE_NAMED = 8

#: Maps bigger than this are not searched again for the lowest cost (a whole uniform-cost
#: search: benchmarks/README.md, "limits").
LOWEST_COST_CELLS = 40_000


def lowest_cost(run: Run) -> float | None:
    """The cheapest path's cost under the run's moves and corner rule: the benchmark's
    optimum when the run knows it (``known_lowest``), else a uniform-cost search, once per
    run, on maps of at most :data:`LOWEST_COST_CELLS` cells (None above)."""
    if run.known_lowest is not None:
        return run.known_lowest
    graph = run.graph
    size = len(graph) if graph is not None else run.grid.width * run.grid.height
    if size > LOWEST_COST_CELLS:
        return None
    if run not in _LOWEST:
        sem = run.semantics.replace(goal_test=None, tree_search=False, visit="generate",
                                    weight=1.0)
        _LOWEST[run] = Run(run.board, "ucs", sem).outcome().cost
    return _LOWEST[run]


def most_roads(graph: Graph) -> int:
    """The most roads out of one node: a graph's branching factor ``b``."""
    starts = graph.data.outgoing()[0]
    return max((b - a for a, b in zip(starts, starts[1:], strict=False)), default=1)


def bound_text(run: Run) -> str:
    """The generated count beside the tutorial's bound: at most ``(b-1)^(d+1)`` nodes, with
    ``b`` moves and the goal at depth ``d`` ("7^(d+1)" for eight moves) -- the loose bound made
    something a student can test.  Past 13 digits it says how big, not every digit (a path of
    10,295 moves has a bound of 8,701 digits)."""
    depth = len(run.moves() or [])
    graph = run.graph
    base = max(1, (most_roads(graph) if graph is not None else run.semantics.branching) - 1)
    return f"generated {run.now.generated:,} of at most {power_text(base, depth + 1)}"


def algorithm_title(algorithm: str) -> str:
    algo = get_algorithm(algorithm)
    return f"{algo.short} · {algo.name}"

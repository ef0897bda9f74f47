"""Which lines of the pseudocode the step at a run's position executed -- plain data, no
Textual, read from the run's named queries (``run.steps``, ``run.nodes``, ``run.now``).

A line is lit when the step did what it says: the take-off and the loop's head on every step;
a check ("if s is already visited: skip s", the corner rule, "discard it") only when it held
for the step's node or for one of its successors; a push and its mark when something was
pushed; a goal test when it found the goal.  Step 0 lights the lines that set the search up.
Stepping back lights that earlier step's lines: everything here is computed from the position.
"""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import TYPE_CHECKING, NamedTuple

from tui_search.engine.maps.grid import DELTAS
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import corner_allowed
from tui_search.engine.search.state import State, as_cell

if TYPE_CHECKING:  # imported by code_of: the first frame shows no code
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.search.pseudocode import Pseudocode


#: Each move by its offset.
MOVE_OF = {delta: move for move, delta in DELTAS.items()}


class Skip(NamedTuple):
    """A successor the step did not push, and the kind of line that skipped it."""

    kind: str  # "blocked", "corner", "reached" or "on_path"
    move: str
    cell: State  # a graph's: the node's name


def code_of(run: "Run | BiRun") -> "Pseudocode":
    """The pseudocode of ``run``'s search (generated once per algorithm and choices); on a
    map with terrain, g adds the cost of the cell a move enters."""
    from tui_search.engine.search.pseudocode import MOVE_COST, TERRAIN_MOVE_COST, pseudocode

    costed = run.graph is None and run.grid.costs is not None
    move_cost = TERRAIN_MOVE_COST if costed else MOVE_COST
    return pseudocode(run.algo, run.semantics, move_cost=move_cost)


def skipped(run: Run, k: int | None = None, reverse: bool = False) -> list[Skip]:
    """The successors step ``k`` (default: the position's) considered and did not push, in
    the order of the moves, each with the line that skipped it (empty for a step that
    expanded no successors: step 0, a discarded step, the goal taken off, a cut-off).
    ``reverse``: a bidirectional search's backward half on a grid, whose successors are the
    cells each move reaches the node *from* (named by the offset from the node, as the
    half's own moves are)."""
    k = run.k if k is None else k
    if k == 0 or run.steps.is_discarded(k):
        return []
    nodes = run.nodes
    event = run.steps.expanded_event(k)
    if event == nodes.goal:
        return []
    limit = run.steps.depth_limit(k) if run.algo.iterative else None
    if (limit is not None and nodes.depth(event) >= limit) or run.steps.is_cut_off(k):
        return []
    added = run.steps.succ_range(k)
    pushed = {nodes.move(h) for h in added}
    last = nodes.move(nodes.goal) if nodes.goal in added else None  # the loop stopped there
    reached_kind = "on_path" if run.semantics.tree_search else "reached"
    closed_set = run.algo.weighted and not run.semantics.reopen and not run.semantics.tree_search
    graph = run.graph
    if graph is not None:  # a node's roads in order: a move is named by the node it reaches
        out: list[Skip] = []
        node = str(nodes.cell(event))
        by_name = run.semantics.order == ("name",)
        roads = sorted(graph.roads_out(graph.index[node]), key=lambda road: graph.names[
            road[0]]) if by_name else list(graph.roads_out(graph.index[node]))
        for b, _, _ in roads:
            name = graph.names[b]
            if name == last:
                break
            if name in pushed:
                continue
            closed = name in graph.closed
            expanded = closed_set and run.now.times_reached(name)[1]
            out.append(Skip("blocked" if closed else "closed" if expanded else reached_kind,
                            name, name))
        return out
    grid, corners = run.grid, run.semantics.corners
    x, y = as_cell(nodes.cell(event))
    out = []
    for move in run.semantics.order:
        if move == last:
            break
        dx, dy = DELTAS[move]
        if reverse:
            dx, dy = -dx, -dy
            move = MOVE_OF[(dx, dy)]
        if move in pushed:
            continue
        cell = (x + dx, y + dy)
        if not grid.is_free(cell):
            kind = "blocked"
        elif dx and dy and not corner_allowed(corners, grid.is_free((x + dx, y)),
                                             grid.is_free((x, y + dy))):
            kind = "corner"
        elif closed_set and run.now.times_reached(cell)[1]:
            kind = "closed"  # expanded already: a closed set never pushes it again
        else:
            kind = reached_kind
        out.append(Skip(kind, move, cell))
    return out


def lit_kinds(run: Run) -> frozenset[str]:
    """The kinds of the lines the step at ``run``'s position executed (see the module's
    docstring)."""
    k = run.k
    algo = run.algo
    kinds: set[str] = set()
    if k == 0 or (algo.iterative and run.steps.first_of_iteration(run.steps.iteration_of(k)) == k):
        kinds |= {"deepen", "init", "mark_start", "next_init"}  # IDA*'s next too
        kinds.add("limit_init" if k == 0 else "next_limit")  # its limit: the first, the next
        if k == 0:
            if run.at_end and run.found:
                kinds.add("goal_start")
            return frozenset(kinds)
    kinds |= {"while", "take"}
    if run.at_end and run.done and not run.found and not run.gave_up:
        kinds.add("fail")
    if run.steps.is_discarded(k):
        kinds.add("discard")
        return frozenset(kinds)
    nodes = run.nodes
    event = run.steps.expanded_event(k)
    kinds |= {"mark_node", "close_node", "recurse"}
    if run.steps.is_cut_off(k):  # IDA*: over the limit, before the goal test
        kinds.add("cutoff")
        return frozenset(kinds)
    if event == nodes.goal:
        kinds.add("goal_node")
        return frozenset(kinds)
    limit = run.steps.depth_limit(k) if algo.iterative else None
    if limit is not None and nodes.depth(event) >= limit:
        kinds.add("cutoff")
        return frozenset(kinds)
    kinds.add("for")
    skips = skipped(run, k)
    kinds.update(skip.kind for skip in skips)
    added = run.steps.succ_range(k)
    if len(added) or any(skip.kind in ("reached", "on_path") for skip in skips):
        kinds.add("cost")  # a successor got past the map's checks: its g was worked out
    if len(added):
        kinds |= {"push", "mark_succ"}
        if nodes.goal in added:
            kinds.add("goal_succ")
    return frozenset(kinds)


#: How the narration says why a successor was skipped, by the kind of line (one, several).
_SKIP_WORDS = {
    "reached": ("is already visited", "are already visited"),
    "closed": ("is closed (expanded already)", "are closed (expanded already)"),
    "on_path": ("is on the path to the node", "are on the path to the node"),
    "corner": ("is past a blocked corner", "are past a blocked corner"),
}
_REACHED_WORDS = {"weighted": ("was reached as cheaply", "were reached as cheaply"),
                  "iterative": ("was reached no deeper", "were reached no deeper")}


def line_notes(run: Run, short: bool = False) -> list[str]:
    """What the step at ``run``'s position did by a line worth naming, for the narration:
    "line 8: (0,1) is already visited, skipped", "line 5 discards it"; none for the skips
    off the map or into an obstacle (every step has some).  ``short``: for a narrow pane,
    "line 8 skipped (0,1)", "line 8 skipped 4"."""
    code = code_of(run)
    k = run.k
    if k and run.steps.is_discarded(k):
        return [f"line {code.number('discard')} discards it"]
    cells: dict[str, list[str]] = {}
    for skip in skipped(run, k):
        if skip.kind != "blocked":
            cells.setdefault(skip.kind, []).append(f"({skip.cell[0]},{skip.cell[1]})")
    words = dict(_SKIP_WORDS)
    if run.algo.weighted:
        words["reached"] = _REACHED_WORDS["weighted"]
    elif run.algo.iterative:
        words["reached"] = _REACHED_WORDS["iterative"]
    out = []
    for kind, named in cells.items():
        if short:
            out.append(f"line {code.number(kind)} skipped "
                       f"{named[0] if len(named) == 1 else len(named)}")
            continue
        one, several = words[kind]
        listed = named[0] if len(named) == 1 else f"{', '.join(named[:-1])} and {named[-1]}"
        out.append(f"line {code.number(kind)}: {listed} "
                   f"{one if len(named) == 1 else several}, skipped")
    return out


def lit_lines(run: Run) -> frozenset[int]:
    """The numbers of the lines of :func:`code_of` the step at ``run``'s position executed."""
    return code_of(run).numbers(lit_kinds(run))


#: The lit lines that say most about a step, the most specific first: the line the
#: narration names (a discard, a skip) or that ends the search (the goal found, a cut-off).
FOCUS_KINDS = ("discard", "corner", "closed", "reached", "on_path", "goal_node", "goal_succ",
               "goal_start", "cutoff", "fail")


def focus_line(run: Run) -> int | None:
    """The number of the most specific line the step at ``run``'s position lit
    (:data:`FOCUS_KINDS`), the one the Code panel keeps in view; None: only the loop's
    ordinary lines (the panel keeps the first lit line in view)."""
    kinds = lit_kinds(run)
    code = code_of(run)
    for kind in FOCUS_KINDS:
        if kind in kinds and (number := code.number(kind)) is not None:
            return number
    return None


def named_lines(run: Run) -> list[int]:
    """The lit lines the narration names, in order: the push ("added E, NE to the queue")
    when the step pushed, and :func:`focus_line` -- what the Code panel keeps in sight before
    the rest of the lit lines."""
    code = code_of(run)
    push = code.number("push") if "push" in lit_kinds(run) else None
    return sorted({number for number in (push, focus_line(run)) if number is not None})


__all__ = ["FOCUS_KINDS", "Skip", "code_of", "focus_line", "line_notes", "lit_kinds", "lit_lines",
           "named_lines", "skipped"]

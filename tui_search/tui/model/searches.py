"""Which searches the panes show, without Textual: a spec (``bfs,dfs``, as ``--compare``
spells it; one key, one pane), what a search's key does to it, and the searches it names
under the settings in force.  The :class:`~tui_search.tui.model.session.Session` keeps the spec
shown and what ``c`` goes between; these functions decide.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import Semantics
from tui_search.engine.search.compare import Contender, parse_compare
from tui_search.engine.search.registry import get_algorithm

if TYPE_CHECKING:
    from tui_search.engine.maps.graph import Graph
    from tui_search.engine.maps.grid import Grid
    from tui_search.engine.run.bidirectional import BiRun
    from tui_search.engine.search.state import State

#: The searches ``c`` compares until the settings pick others.
DEFAULT_COMPARE = "bfs,dfs"
#: Panes: one at least, four at most; the number keys take none out of fewer than two.
MIN_COMPARED, MAX_PANES = 2, 4


def normal_spec(spec: str) -> str:
    """``bfs, dfs,`` as ``bfs,dfs``: the searches of a spec, no blanks."""
    return ",".join(part.strip() for part in spec.split(",") if part.strip())


def searches_of(spec: str, semantics: Semantics) -> tuple[list[Contender], str]:
    """The searches of ``spec`` under ``semantics``, and a note when a setting does not
    apply to one of them (that one takes the default: the visit rule, a priority queue's
    choices, recursion).  What a search's part names itself (``astar:w=2``,
    ``biastar:first-meeting``) is its own choice, not a setting that did not apply."""
    contenders = parse_compare(spec, semantics, fit=True, fewest=1)
    fitted = [c.label for c in contenders if c.semantics.visit != semantics.visit]
    note = (f"Visit on expand does not apply to {', '.join(fitted)}: visit on generate "
            "there" if fitted else "")
    if not note:
        others = [c.label for c in contenders
                  if parse_compare(c.algorithm, semantics, fit=True, fewest=1)[0]
                  .semantics.replace(heuristic=semantics.heuristic) != semantics]
        if others:
            note = (f"Some settings do not apply to {', '.join(others)}: their defaults "
                    "there")
    return contenders, note


def run_of(board: Grid | Graph, algorithm: str, semantics: Semantics, max_steps: int
           ) -> Run | BiRun:
    """A pane's run: a bidirectional search's two halves and one position
    (:class:`~tui_search.engine.run.bidirectional.BiRun`), any other search's run.
    ``ValueError`` (its one-line reason) where the app cannot show it."""
    if get_algorithm(algorithm).bidirectional:
        from tui_search.engine.run.bidirectional import BiRun

        return BiRun(board, algorithm, semantics, max_steps)
    return Run(board, algorithm, semantics, max_steps)


def current_node(run: Run | BiRun) -> State | None:
    """The node expanded by the step just taken, in either kind of run (None at step 0)."""
    return run.now.current_node() if isinstance(run, Run) else run.current_node()


def with_key(spec: str, key: str) -> tuple[str, str | None]:
    """A search's key pressed while ``spec`` is shown.  One pane: run ``key`` there.
    Several: add it, or take it out (two stay, four at most).  The spec to show then, and
    None; or ``spec`` as it is, and a warning why nothing changed."""
    parts = spec.split(",")
    keys = [p.partition(":")[0] for p in parts]
    name = get_algorithm(key).short
    if len(parts) == 1:  # rule over N: a key picks one pane's search, adds to several
        parts = [key]
    elif key in keys:
        if len(parts) == MIN_COMPARED:
            return spec, f"Compare keeps two searches at least: {name} stays (c for one search)"
        del parts[keys.index(key)]
    elif len(parts) == MAX_PANES:
        return spec, (f"Compare shows four searches at most: take one out to add {name}"
                      " (its key again)")
    else:
        parts.append(key)
    return ",".join(parts), None


def with_ticked(spec: str, ticked: list[str]) -> str:
    """The settings' compare boxes ticked (``ticked``, registry keys) over the comparison
    ``spec``: its searches whose box is still ticked, as it names them and in its order (a
    heuristic, a weight, a stopping rule kept; ``biastar:proven,biastar:first-meeting`` is
    one box), then the boxes newly ticked, in ``ticked``'s order."""
    parts = [p.strip() for p in spec.split(",") if p.strip()]
    named = {p.partition(":")[0] for p in parts}
    return ",".join([p for p in parts if p.partition(":")[0] in ticked]
                    + [key for key in ticked if key not in named])


__all__ = ["DEFAULT_COMPARE", "MAX_PANES", "MIN_COMPARED", "current_node", "normal_spec", "run_of",
           "searches_of", "with_key", "with_ticked"]

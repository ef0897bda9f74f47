"""A tie of the priority taken another way: which tie rule would take the cell the trace (or
the student stepping by hand) took, in a sentence
(:class:`~tui_search.engine.traces.differences.Causes` asks it where a cost-ordered search
parts from the trace).
"""

from __future__ import annotations

from collections.abc import Sequence

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.choices import TIE_RULES
from tui_search.engine.search.state import State
from tui_search.engine.traces.causes import Voice
from tui_search.engine.traces.read import show

#: Two priorities closer than this tie (the floats of one cost summed in another order).
TIE = 1e-9

#: How a tie rule takes an entry of a tie, and why a student's code does so.
RULE_WORDS = {"fifo": "the oldest entry", "lifo": "the newest entry",
              "node": "the smallest cell", "low-h": "the lower h", "high-h": "the higher h",
              "low-g": "the lower g", "high-g": "the higher g"}
_RULE_WHY = {"node": ", as a heap of (f, (x, y)) tuples does"}
#: The tie rules in the order a difference names them (a student's tuple first).
TIE_ORDER = ("node", "low-h", "high-h", "lifo", "low-g", "high-g", "fifo")
assert set(TIE_ORDER) == set(TIE_RULES)

Entry = tuple[int, State, tuple[float, float, float]]  # event, cell, (g, h, priority)


def tie(run: Run, k: int, mine: State, theirs: State, name: str, voice: Voice,
        prefer: Sequence[str] = TIE_ORDER) -> tuple[str, str, list[str]] | None:
    """When ``theirs`` (the trace's cell) ties with ``mine`` (the search's, ``name``) on the
    priority before the search's step ``k``: the sentence, the tie's kind ("h" where the
    trace took the lower or higher h of an f tie, else "entry") and the tie rules that would
    take the trace's cell, the sentence naming the first of them in ``prefer``'s order; None
    when they do not tie."""
    algo, sem = run.algo, run.semantics
    run.goto(k - 1)
    now, cell_of, costs = run.now, run.nodes.cell, run.nodes.costs
    entries: list[Entry] = []
    stale: list[Entry] = []  # the trace's cell's out-of-date entries (pushed again cheaper)
    for g in now.frontier():
        c = costs(g)
        if c is not None:
            if not now.is_stale(g):
                entries.append((g, cell_of(g), c))
            elif cell_of(g) == theirs:
                stale.append((g, theirs, c))
    if not any(cell == theirs for _, cell, _ in entries):
        # code with no check of what it takes off (heapq A* with no closed set) takes an
        # out-of-date entry where its tie rule puts it; this search would drop it there
        entries += stale
    top = next((c for _, cell, c in entries if cell == mine), None)
    got = next((c for _, cell, c in entries if cell == theirs), None)
    if top is None or got is None or abs(top[2] - got[2]) > TIE:
        return None
    tied = [(g, cell, c) for g, cell, c in entries if abs(c[2] - top[2]) <= TIE]
    rules = [r for r in prefer if r != sem.ties and _picks(r, tied) == theirs
             and not sem.replace(ties=r).refusal(algo)]
    p = algo.priority_name
    mine_words = RULE_WORDS[sem.ties]
    start = f"{name} expands {show(mine)} next; {voice.says('expands')} {show(theirs)}: "
    you = voice.says("takes", search=True)
    if rules:
        rule = rules[0]
        how = f"{RULE_WORDS[rule]} of the tie"
        if rule in ("low-h", "high-h"):
            how += f" ({got[1]:.2f}, not {top[1]:.2f})"
        elif rule in ("low-g", "high-g"):
            how += f" ({got[0]:.2f}, not {top[0]:.2f})"
        words = (f"{start}{p} ties at {top[2]:.2f}, and {you} {how}"
                 f"{_RULE_WHY.get(rule, '')}; this search takes {mine_words}"
                 f"{voice.flag('--ties ' + rule)}")
        kind = "h" if rule in ("low-h", "high-h") and p == "f" else "entry"
        return words, kind, rules
    words = (f"{start}{p} ties at {top[2]:.2f}, and {you} another entry of the "
             f"tie, one no tie rule here takes; this search takes {mine_words}")
    return words, "entry", []


def _picks(rule: str, tied: list[Entry]) -> State:
    """The cell the tie ``rule`` takes of ``tied`` entries; then the oldest, as
    :func:`~tui_search.engine.search.rules.tie_key` orders them."""
    def key(entry: Entry) -> tuple[object, int]:
        g, cell, (cost, h, _) = entry
        by: dict[str, object] = {"fifo": 0, "lifo": -g, "node": cell, "low-h": h,
                                 "high-h": -h, "low-g": cost, "high-g": -cost}
        return by[rule], g

    return min(tied, key=key)[1]


__all__ = ["RULE_WORDS", "TIE", "TIE_ORDER", "tie"]

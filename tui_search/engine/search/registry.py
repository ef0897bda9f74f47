"""The algorithm registry: every search the app knows, as data.

An algorithm is its frontier discipline (which generated node is expanded next) and whether it
iterates (iterative deepening restarts with a growing depth limit, IDA* with a growing limit on
f = g + h).  Everything that names or
describes an algorithm -- the command line's choices, the app's keys, the help screen, the
frontier panel's title, the narration -- reads it from here, so adding one is adding an entry,
and no UI module compares algorithm names.
"""

# No future import: CONTRIBUTING.md, "Start-up".
from enum import Enum
from typing import NamedTuple


class Frontier(Enum):
    """How the frontier orders its entries (room for a priority queue)."""

    FIFO = "fifo"  # a queue: the oldest entry comes out first
    LIFO = "lifo"  # a stack: the newest entry comes out first
    PRIORITY = "priority"  # a priority queue: the lowest priority first, ties oldest first
    #: what a replayed trace added and has not expanded, in the order added: any one may
    #: leave next (a trace does not say its discipline)
    ADDED = "added"

    @property
    def title(self) -> str:
        """The frontier panel's title: "Queue (FIFO)", "Stack (LIFO)"."""
        return _TITLES[self]

    @property
    def noun(self) -> str:
        """What the narration calls it: "queue", "stack"."""
        return _NOUNS[self]

    @property
    def next_end(self) -> str:
        """Where the next entry to come out is: "front", "top"."""
        return _ENDS[self]

    def count_text(self, n: str) -> str:
        """``n`` entries said the tutorial's way: "4 in the queue", "5 on the stack"."""
        return f"{n} {_PREPOSITIONS[self]} the {self.noun}"

    @property
    def next_known(self) -> bool:
        """Is it known which entry leaves next (all but a replayed trace's)?"""
        return self is not Frontier.ADDED

    @property
    def end_hints(self) -> tuple[str, str, str]:
        """What the panel writes beside its entries: the only one, the next out, the far end."""
        return _HINTS[self]

    def take_words(self, priority: str = "") -> str:
        """The pseudocode's words for taking the next entry off: "take off the front of the
        queue (pop front)"; a priority queue's name the ``priority`` ("f")."""
        return _TAKES[self].format(p=priority)

    def push_words(self, priority: str = "") -> str:
        """The pseudocode's words for putting successor ``s`` on: "push s at the back of the
        queue (push back)"; a priority queue's say by what (``priority``: "f = g + h")."""
        return _PUSHES[self].format(p=priority)


_TITLES = {Frontier.FIFO: "Queue (FIFO)", Frontier.LIFO: "Stack (LIFO)",
           Frontier.PRIORITY: "Priority queue", Frontier.ADDED: "Frontier, as added"}
_NOUNS = {Frontier.FIFO: "queue", Frontier.LIFO: "stack", Frontier.PRIORITY: "priority queue",
          Frontier.ADDED: "frontier"}
_ENDS = {Frontier.FIFO: "front", Frontier.LIFO: "top", Frontier.PRIORITY: "front",
         Frontier.ADDED: "oldest end"}
_PREPOSITIONS = {Frontier.FIFO: "in", Frontier.LIFO: "on", Frontier.PRIORITY: "in",
                 Frontier.ADDED: "on"}
_HINTS = {
    Frontier.FIFO: ("← front and back", "← front (next out)", "← back (newest)"),
    Frontier.LIFO: ("← top and bottom", "← top (next out)", "← bottom (oldest)"),
    # none: the order is the priorities', shown on every line (and ▶ marks the next out)
    Frontier.PRIORITY: ("", "", ""),
    # a trace's: the order added, not the order out (the trace does not say it)
    Frontier.ADDED: ("← the only one", "← oldest", "← newest"),
}

_TAKES = {Frontier.FIFO: "take off the front of the queue (pop front)",
          Frontier.LIFO: "take off the top of the stack (pop)",
          Frontier.PRIORITY: "take off the entry of lowest {p} (pop min)",
          Frontier.ADDED: "take off the entry the trace expanded (its rule unknown)"}
_PUSHES = {Frontier.FIFO: "push s at the back of the queue (push back)",
           Frontier.LIFO: "push s on top of the stack (push)",
           Frontier.PRIORITY: "push s into the priority queue by {p}",
           Frontier.ADDED: "add s to the frontier"}

#: How an informed search orders its priority queue: what the panel's title and the narration
#: call the priority, and what it adds up.
PRIORITIES: dict[str, str] = {"g": "g", "h": "h", "g+h": "f = g + h"}


class Algorithm(NamedTuple):
    """One search algorithm, described."""

    key: str  # what the command line and the JSON call it: "bfs"
    name: str  # "Breadth-first search"
    short: str  # "BFS"
    frontier: Frontier
    app_key: str  # the key that picks it in the app
    summary: str  # one line for the help screen
    tag: str  # the key bar's shortest name: "BFS", "ID"
    #: restarts with depth limits 0, 1, 2, ... (with a priority: IDA*'s limits on f)
    iterative: bool = False
    #: A priority queue's order: "g" (the path's cost so far), "h" (the heuristic's estimate
    #: of the cost to the goal) or "g+h"; None for a queue or a stack.
    priority: str | None = None
    #: When the goal is tested unless the semantics say otherwise: "generate" for the
    #: tutorial's searches, "expand" for the cost-ordered ones (testing on generation would
    #: stop before a cheaper path to the goal comes off the queue).
    goal_test: str = "generate"
    #: Is its key in the key bar's group of searches?  The tutorial's and the next lesson's
    #: are; the chapter's further searches have their key in the help (``?``), the palette
    #: and the docs, so that the bar keeps its other hints at 80 columns.
    key_bar: bool = True
    #: A forward search from the start and a backward one from the goal, one expansion each
    #: in turn (:mod:`~tui_search.engine.search.bidirectional.loop`).
    bidirectional: bool = False

    @property
    def informed(self) -> bool:
        """Does its order use a heuristic (so ``--heuristic`` applies)?"""
        return self.priority is not None and "h" in self.priority

    @property
    def weighted(self) -> bool:
        """Does it order by cost (a priority queue, or IDA*'s f-limits: moves costing 1 and
        sqrt(2))?"""
        return self.priority is not None

    @property
    def contours(self) -> bool:
        """Does it deepen by limits on f (IDA*: a stack, each iteration an f-contour)?"""
        return self.iterative and self.priority is not None

    @property
    def queued(self) -> bool:
        """Does a priority queue order it (UCS, greedy, A*: ties and re-opening apply)?"""
        return self.frontier is Frontier.PRIORITY

    @property
    def frontier_title(self) -> str:
        """The frontier panel's title: "Queue (FIFO)", "Priority queue (A*: f = g + h)"."""
        if self.priority is None:
            return self.frontier.title
        if self.contours:
            return f"{self.frontier.title} ({self.short}: f = g + h ≤ limit)"
        return f"{self.frontier.title} ({self.short}: {PRIORITIES[self.priority]})"

    @property
    def priority_name(self) -> str:
        """What the priority is called: "g", "h" or "f"."""
        return {"g": "g", "h": "h", "g+h": "f"}[self.priority or "g"]


ALGORITHMS: dict[str, Algorithm] = {
    a.key: a
    for a in (
        Algorithm("bfs", "Breadth-first search", "BFS", Frontier.FIFO, "1",
                  "takes the oldest node from a FIFO queue: the fewest moves, much memory",
                  "BFS"),
        Algorithm("dfs", "Depth-first search", "DFS", Frontier.LIFO, "2",
                  "takes the newest node from a LIFO stack: little memory, any path", "DFS"),
        Algorithm("iddfs", "Iterative deepening", "IDDFS", Frontier.LIFO, "3",
                  "depth-limited DFS with limits 0, 1, 2, ...: the fewest moves, a small stack",
                  "ID", iterative=True),
        Algorithm("ucs", "Uniform-cost search", "UCS", Frontier.PRIORITY, "4",
                  "takes the cheapest path so far (g) from a priority queue: the cheapest path",
                  "UCS", priority="g", goal_test="expand"),
        Algorithm("greedy", "Greedy best-first search", "Greedy", Frontier.PRIORITY, "5",
                  "takes the node that looks closest to the goal (h): fast, any path",
                  "GBF", priority="h", goal_test="expand"),
        Algorithm("astar", "A* search", "A*", Frontier.PRIORITY, "6",
                  "takes the lowest f = g + h: the cheapest path, fewer nodes than UCS",
                  "A*", priority="g+h", goal_test="expand"),
        Algorithm("idastar", "Iterative deepening A*", "IDA*", Frontier.LIFO, "7",
                  "depth-first within f-limits h(start), then the least f over: A*'s path, "
                  "a small stack", "IDA", iterative=True, priority="g+h", goal_test="expand",
                  key_bar=False),
    )
}

#: The bidirectional searches: each a forward search from the start and a backward one from
#: the goal, in turn (headless and in the app; not beside a replayed trace).
BIDIRECTIONAL: dict[str, Algorithm] = {
    a.key: a
    for a in (
        Algorithm("bibfs", "Bidirectional BFS", "BiBFS", Frontier.FIFO, "",
                  "BFS from the start and from the goal in turn, until they meet", "BiBFS",
                  bidirectional=True),
        Algorithm("biucs", "Bidirectional uniform-cost search", "BiUCS", Frontier.PRIORITY,
                  "", "UCS from the start and from the goal in turn, until they meet",
                  "BiUCS", priority="g", goal_test="expand", bidirectional=True),
        Algorithm("biastar", "Bidirectional A*", "BiA*", Frontier.PRIORITY, "",
                  "A* from the start and from the goal in turn, until they meet", "BiA*",
                  priority="g+h", goal_test="expand", bidirectional=True),
    )
}

#: The algorithm a run uses unless told otherwise.
DEFAULT_ALGORITHM = "bfs"


def get_algorithm(key: str) -> Algorithm:
    """The registry entry for ``key``; ``ValueError`` with the choices when there is none."""
    try:
        return ALGORITHMS[key] if key in ALGORITHMS else BIDIRECTIONAL[key]
    except KeyError:
        raise ValueError(f"unknown algorithm {key!r} (use "
                         f"{', '.join([*ALGORITHMS, *BIDIRECTIONAL])})") from None

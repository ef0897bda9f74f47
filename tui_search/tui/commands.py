"""The app's own commands in Textual's command palette (``ctrl+p``), beside Textual's: each
algorithm of the registry (the bidirectional ones too: they have no key), each theme, each cost
of the terrain brush, and the actions a key does (settings, save, save as, open, overview,
zoom, cell labels, help), and the run exported.

A command runs the same action as its key (the main screen's ``run_action``), so the palette
can never do
something the keys do not; its help line is the key's tooltip and the key, so the palette also
teaches the keys.  The app imports this module only when the palette first opens.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from textual.binding import Binding
from textual.command import DiscoveryHit, Hit, Hits, Provider

from tui_search.engine.course.exercise_file import BUILT_IN_FILES, built_in_exercise
from tui_search.engine.search.compare import parse_compare
from tui_search.engine.search.registry import ALGORITHMS, BIDIRECTIONAL
from tui_search.tui.model.map_edits import BRUSHES, brush_name
from tui_search.tui.screens.keys import KEYS
from tui_search.tui.view.themes import THEMES

#: Comparisons offered by name: the tutorial's, the next lesson's, and A*'s heuristics.
COMPARISONS = {
    "bfs,dfs": "the tutorial's demo: a queue against a stack",
    "bfs,ucs,astar": "fewest moves, the cheapest path, and the cheapest with fewer expansions",
    "astar,astar:manhattan": "an admissible heuristic against an inadmissible one",
    "ucs,greedy,astar": "g, h and g + h: what each priority buys",
    "biastar:proven,biastar:first-meeting": "bidirectional A*'s trap: stopped at the first "
    "meeting, its path is not always the cheapest",
}

#: The actions of the app's key table offered by name, with the palette's name for each.
ACTIONS = {
    "compare": "Compare searches side by side (on / off)",
    "by_hand": "By hand: make the search's steps yourself, checked step by step",
    "settings": "Search settings",
    "code": "Code panel: the search's pseudocode, the step's lines lit (on / off)",
    "undo": "Undo the last edit of the map",
    "redo": "Redo the edit undone",
    "save": "Save the map",
    "save_as": "Save the map as…",
    "open": "Open a map…",
    "generate": "Generate a map: maze, prim, kruskal, division, rooms, random…",
    "overview": "Overview: the whole map",
    "zoom(1)": "Zoom in: bigger cells",
    "zoom(-1)": "Zoom out: smaller cells",
    "labels": "Cell labels: arrows, depth/cost, none",
    "help": "Help: keys, colours, how the searches work",
}

Command = tuple[str, Callable[[], object], str]  # name, what it does, help line


class SearchCommands(Provider):
    """Algorithms, themes and the app's actions, found by name."""

    def commands(self) -> list[Command]:
        app = self.app
        main = app.screen_stack[0]  # the main screen: its keys' actions
        found: list[Command] = [
            (f"Algorithm: {a.name}", partial(main.run_action, f"algorithm({a.key!r})"),
             f"{a.summary} (key {a.app_key})" if a.app_key else
             f"{a.summary} (no key: here, or ticked in the settings for c)")
            for a in (*ALGORITHMS.values(), *BIDIRECTIONAL.values())
        ]
        for spec in THEMES.values():
            now = " · the theme now" if app.theme == spec.name else ""
            found.append((f"Theme: {spec.title}", partial(setattr, app, "theme", spec.name),
                          f"{spec.description} · t cycles the themes{now}"))
        for n in BUILT_IN_FILES:
            found.append((f"Exercise {n}: {built_in_exercise(n).text}",
                          partial(main.run_action, f"show_exercise({n})"),
                          "the tutorial's exercise, checked live as you edit (key x cycles)"))
        found.append(("Exercise: off", partial(main.run_action, "show_exercise(0)"),
                      "hide the challenge panel (key x)"))
        for spec_text, why in COMPARISONS.items():
            labels = [c.label for c in parse_compare(spec_text)]
            found.append((f"Compare: {' · '.join(labels)}",
                          partial(main.run_action, f"show_compare({spec_text!r})"),
                          f"{why} (side by side, in lockstep; key c toggles)"))
        for cost in (*BRUSHES, 0.0):
            found.append((f"Terrain brush: {brush_name(cost) if cost else 'off'}",
                          partial(main.run_action, f"brush({cost})"),
                          "m or a mouse drag paints it (key b cycles the brush)"))
        if getattr(app, "exporter", None) is not None:
            found.append(("Export the run as a file…", partial(main.run_action, "export"),
                          "an animated SVG (.svg), a terminal recording (.cast), a GIF (.gif) "
                          "or a handout (.md), drawn as the app draws the run, or a Posthoc "
                          "search trace (.trace.json, .trace.yaml)"))
        bindings = {b.action: b for b in Binding.make_bindings(KEYS)}
        for action, name in ACTIONS.items():
            binding = bindings[action]
            found.append((name, partial(main.run_action, action),
                          f"{binding.tooltip} (key {app.get_key_display(binding)})"))
        return found

    async def discover(self) -> Hits:
        for name, command, help_text in self.commands():
            yield DiscoveryHit(name, command, help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for name, command, help_text in self.commands():
            score = matcher.match(name)
            if score > 0:
                yield Hit(score, matcher.highlight(name), command, help=help_text)


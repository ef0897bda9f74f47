"""The key hints at the bottom, drawn like Textual's ``Footer`` but as one widget.

The ``Footer`` builds a widget per key and builds them all again whenever a key is enabled or
disabled -- which happens on many steps (``p`` at step 0, ``n`` at the end): that cost more
than the step itself, and its sixteen widgets were half the app's start-up.  This bar renders
the same hints as one line of text: keys that cannot act now are dimmed, bindings of a group
(``n``/``p``, ``1``/``2``/``3``) share one label, and clicking a hint presses its key.  When
the bar is too narrow for every hint it leaves out the least important ones first (each action's
importance is given by the app), so help and quit stay in sight.
"""

from __future__ import annotations

from collections.abc import Mapping
from itertools import groupby
from typing import ClassVar

from rich.cells import cell_len
from rich.segment import Segment
from textual import events
from textual.binding import ActiveBinding
from textual.screen import Screen
from textual.strip import Strip
from textual.widget import Widget

#: A hint: its keys as ``(display, key, enabled)``, its description, whether it can act.
Hint = tuple[list[tuple[str, str, bool]], str, bool]


#: The importance of a raised hint: above every other but help's and quit's (10).
RAISED = 9
#: Between the keys of one hint when one of them is a word (``pgdn/pgup``): keys of a
#: character each read as a row of keys (``np``, ``123456``), a word's would run together.
KEY_SEP = "/"


def key_gaps(keys: list[tuple[str, str, bool]]) -> str:
    """What goes between two keys of a hint: nothing when each is one character, else
    :data:`KEY_SEP`."""
    return KEY_SEP if any(cell_len(display) > 1 for display, _, _ in keys) else ""


class KeyBar(Widget):
    """One line of key hints for the active bindings of the screen."""

    COMPONENT_CLASSES: ClassVar[set[str]] = {
        "key-bar--key",
        "key-bar--description",
        "key-bar--disabled",
    }

    DEFAULT_CSS = """
    KeyBar {
        dock: bottom;
        height: 1;
        padding: 0 1;
        background: $footer-background;
        & > .key-bar--key {
            color: $footer-key-foreground;
            background: $footer-key-background;
            text-style: bold;
        }
        & > .key-bar--description {
            color: $footer-description-foreground;
        }
        & > .key-bar--disabled {
            color: $text-disabled;
        }
    }
    """

    def __init__(
        self, importance: Mapping[str, int] | None = None, *, id: str | None = None
    ) -> None:
        super().__init__(id=id)
        #: How much each action's hint matters (by action name, without parameters): when
        #: the bar is too narrow, the lowest go first; an action not listed counts 0.
        self.importance: Mapping[str, int] = importance or {}
        #: Actions whose hint matters most for now (a mode that is on: its key ends it), kept
        #: in sight before all but the ones of importance 10 (help and quit).
        self.raised: frozenset[str] = frozenset()
        #: Descriptions that say a state (``Paint cost 5``), by action, over the bindings'.
        self.labels: dict[str, str] = {}
        self._spans: list[tuple[int, int, str]] = []  # (start, end, key) of each hint drawn

    def relabel(self, action: str, description: str | None) -> None:
        """Describe ``action``'s hint as ``description`` (None: the binding's again)."""
        if self.labels.get(action) != description:
            if description is None:
                self.labels.pop(action, None)
            else:
                self.labels[action] = description
            self.refresh()

    def raise_hint(self, action: str, raised: bool) -> None:
        """Keep ``action``'s hint in sight (``raised``), or back to its own importance."""
        now = self.raised | {action} if raised else self.raised - {action}
        if now != self.raised:
            self.raised = now
            self.refresh()

    def _importance(self, action: str) -> int:
        return RAISED if action in self.raised else self.importance.get(action, 0)

    def on_mount(self) -> None:
        self.screen.bindings_updated_signal.subscribe(self, self._bindings_changed)

    def on_unmount(self) -> None:
        self.screen.bindings_updated_signal.unsubscribe(self)

    def _bindings_changed(self, screen: Screen[object]) -> None:
        if screen is self.screen:
            self.refresh()

    def hints(self) -> list[Hint]:
        """The hints in order (also for tests): ``(keys, description, enabled)`` where
        ``keys`` lists ``(display, key, enabled)``.  One hint per action shown; a group of
        two or more actions (``n``/``p``) is one hint with the group's description, enabled
        when any of its keys is."""
        return [hint for hint, _ in self._hints()]

    def _hints(self) -> list[tuple[Hint, str]]:
        """The hints, each with the name of its (first) action."""
        by_action: dict[str, list[ActiveBinding]] = {}
        for active in self.screen.active_bindings.values():
            if active.binding.show:
                by_action.setdefault(active.binding.action, []).append(active)
        firsts = [actives[0] for actives in by_action.values()]
        hints: list[tuple[Hint, str]] = []
        for group, grouped in groupby(firsts, lambda active: active.binding.group):
            members = list(grouped)
            keys = [
                (self.app.get_key_display(a.binding), a.binding.key, a.enabled) for a in members
            ]
            actions = [a.binding.action.split("(")[0] for a in members]
            if group is not None and len(members) > 1:
                hint = (keys, group.description, any(a.enabled for a in members))
                hints.append((hint, actions[0]))
            else:
                hints.extend((([key], self.labels.get(action, a.binding.description),
                               a.enabled), action)
                             for key, a, action in zip(keys, members, actions, strict=True))
        return hints

    def shown_hints(self, width: int | None = None) -> list[Hint]:
        """The hints that fit in ``width`` cells (default: the bar's), in order: while they
        do not fit, the least important one goes (the rightmost of equals first).  What is
        left still too wide ends in an ellipsis."""
        width = self.content_size.width if width is None else width
        hints = self._hints()
        sizes = [
            sum(cell_len(display) for display, _, _ in keys)
            + cell_len(key_gaps(keys)) * (len(keys) - 1) + 1 + cell_len(description)
            for (keys, description, _), _ in hints
        ]
        kept = list(range(len(hints)))
        while len(kept) > 1 and sum(sizes[i] for i in kept) + 2 * (len(kept) - 1) > width:
            kept.remove(min(reversed(kept), key=lambda i: self._importance(hints[i][1])))
        return [hints[i][0] for i in kept]

    def render_line(self, y: int) -> Strip:
        """The hints as one line of segments (the line API: Textual lays out no text for it,
        work every start paid for: benchmarks/README.md, "startup").  What is still too wide
        ends in "…"."""
        width = self.content_size.width
        base = self.rich_style
        self._spans = []
        if y or width <= 0:
            return Strip.blank(width, base)
        key_style, description_style, disabled_style = (
            base + self.get_component_rich_style(f"key-bar--{name}")
            for name in ("key", "description", "disabled"))
        segments: list[Segment] = []
        x = 0
        for n, (keys, description, enabled) in enumerate(self.shown_hints(width)):
            if n:
                segments.append(Segment("  ", base))
                x += 2
            gap = key_gaps(keys)
            for i, (display, key, key_enabled) in enumerate(keys):
                if i and gap:
                    segments.append(Segment(gap, description_style))
                    x += cell_len(gap)
                self._spans.append((x, x + cell_len(display), key))
                segments.append(Segment(display, key_style if key_enabled else disabled_style))
                x += cell_len(display)
            label = f" {description}"
            segments.append(Segment(label, description_style if enabled else disabled_style))
            self._spans.append((x, x + cell_len(label), keys[0][1]))
            x += cell_len(label)
        line = Strip(segments, x)
        if x > width:  # one hint left, still too wide
            cut = line.crop(0, width - 1)
            last = segments[-1].style if cut.cell_length == 0 else list(cut)[-1].style
            line = Strip([*cut, Segment("…", last)], width)
        return line.extend_cell_length(width, base)

    def on_click(self, event: events.Click) -> None:
        """Clicking a hint presses its key (a group's description, its first key)."""
        offset = event.get_content_offset(self)
        if offset is None:
            return
        for start, end, key in self._spans:
            if start <= offset.x < end:
                self.app.simulate_key(key)
                return

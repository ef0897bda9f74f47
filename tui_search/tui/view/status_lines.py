"""What the status lines say, built from the session without Textual: the screen's under the
panes (where the panes have no lines of their own: the run's counts and narration; else the
searches shown and how the lockstep goes) and a pane's own (its search's counts), as
:class:`~tui_search.tui.view.pieces.Line` s that :class:`~tui_search.tui.widgets.stats.Stats`
draws.

The counts are pieces ranked by what a student can do without, so that when the rows run out
the playing speed, the frontier's peak, ... go first, never the narration or the bound (see
:func:`~tui_search.tui.view.pieces.lay_out`).  Which lines go under the panes is the layout's rule
over the number of panes, :func:`~tui_search.tui.view.layout.own_lines`.
"""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import TYPE_CHECKING, NamedTuple

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.registry import get_algorithm
from tui_search.tui.model import playback
from tui_search.tui.model.session import Session
from tui_search.tui.view.code_trace import line_notes
from tui_search.tui.view.layout import own_lines
from tui_search.tui.view.narration import (
    frontier_word,
    narrate,
    result_text,
    status_parts,
    weight_bound,
)
from tui_search.tui.view.pieces import Line, Piece, lay_out

if TYPE_CHECKING:
    from tui_search.engine.run.bidirectional import BiRun

#: Between two counts on a row.
SEP = (" │ ", "stats--label")
#: At most this many rows while some piece can go; a pane's own, at most PANE_ROWS (its map
#: comes first).
MAX_ROWS, PANE_ROWS = 4, 3
#: What goes first when the rows run out (the highest rank; 0 never goes).
#: (The frontier's size goes after its peak and the counts of lesser note: the frontier's
#: panel says it too.)
BOUND_RANK, PLAYING_RANK, PEAK_RANK, DONE_RANK, FRONTIER_RANK = 9, 8, 7, 6, 3
#: The narration's naming of the code's lines (the Code panel shown) is shortened at this
#: rank ("line 8 skipped 4"), and goes at the next (after the counts of lesser note).
NOTES_RANK, NOTES_SHORT_RANK = 7, 2
#: Where the panes have no lines of their own, a search's path's moves go (its counts stay)
#: when the rows under the panes run out, after the playing speed.
PATH_RANK = 5
#: The step and the nodes expanded are what the lessons count: they never go (rank 0), they
#: take another row instead (as the path's moves and cost do).
RANKS = {"discarded": 5, "generated": 4, "step": 0, "expanded": 0}


class Status(NamedTuple):
    """Status lines: the counts, then the narration (or a note, or the lockstep's sentence),
    shown in at most ``max_rows`` rows while some piece can go."""

    lines: list[Line]
    max_rows: int


def search_status(run: "Run | BiRun | None", name: str, *, in_pane: bool, playing: str = "",
                  note: str = "", done: bool = False, code: bool = False) -> Status:
    """One search's lines: ``name`` names it; ``done`` adds "done at step k" (a run that
    ended before the others); ``note`` replaces the narration (e.g. the quiz's question, while
    computing the end of a big run, or when the map lacks a start or a goal); ``code`` (the
    Code panel shown) has the narration name the code's lines.

    ``in_pane``: a pane's own lines, under which its map comes first: at most
    :data:`PANE_ROWS`, and the bound may go (the comparison table under the panes says it
    too), never the path's moves and cost (they wrap instead, as the step and the nodes
    expanded do: the lessons are about them); else the lines under the panes, at most
    :data:`MAX_ROWS`, and they never go."""
    if run is not None and not isinstance(run, Run):
        return _two_way_status(run, name, in_pane=in_pane, playing=playing, note=note,
                               done=done)
    status = [Piece([(name, "stats--value")])]
    if done and run is not None:
        status.append(Piece([(f"done at step {run.k:,}", "stats--result")], DONE_RANK, SEP))
    differences = run.differences() if run is not None else []
    warning = run.estimate_warning() if run is not None else ""
    if warning:  # a heuristic that may mislead the search
        differences.append(warning)
    bound = weight_bound(run) if run is not None else ""
    if bound:  # weighted A*: "weight 2: at most 2 × the optimum"
        differences = [f"{d}: {bound}" if d.startswith("weight ") else d for d in differences]
    if differences:  # always say what differs
        status.append(Piece([("· " + " · ".join(differences), "stats--note")], 0,
                            (" ", "stats--note")))
    if run is not None:
        noun = frontier_word(run)
        for count, value in status_parts(run):
            parts = [(f"{count} ", "stats--label"), (value, "stats--value")]
            if count == noun:  # "(peak 8)": the first to go, but for the playing speed
                short = [parts[0], (value.partition(" (")[0], "stats--value")]
                status.append(Piece(parts, PEAK_RANK, SEP, short, FRONTIER_RANK))
            else:
                status.append(Piece(parts, RANKS.get(count, 1), SEP))
    if playing:
        status.append(Piece([(playing, "stats--play")], PLAYING_RANK, SEP))
    line: list[Piece]
    if note:
        line = [Piece([(note, "stats--note")])]
    elif run is None:
        line = []
    else:
        failed = run.at_end and not run.found and not run.gave_up  # "no path", in red
        cls = "stats--no-path" if failed else "stats--narration"
        line = [Piece([(narrate(run), cls)])]
        if code:  # the lines named: shortened, then gone, before a count goes (a narrow pane)
            named = "; ".join(line_notes(run))
            if named:
                brief = "; ".join(line_notes(run, short=True))
                line.append(Piece([(named, cls)], NOTES_RANK, ("; ", cls), [(brief, cls)],
                                  NOTES_SHORT_RANK))
        if run.at_end and run.found:  # the path, and the bound: what the lesson is about
            # (a pane's own: the map comes first, and the comparison table says the bound
            # too: it may go; the path's moves and cost never go, they take another row)
            ranks = (0, BOUND_RANK) if in_pane else (0, 0)
            line += [Piece([(text, "stats--result")], rank, (" · ", "stats--label"))
                     for text, rank in zip(result_text(run).split(" · "), ranks, strict=False)]
    return Status([Line(status), Line(line, prose=True)], PANE_ROWS if in_pane else MAX_ROWS)


def _two_way_status(run: "BiRun", name: str, *, in_pane: bool, playing: str, note: str,
                    done: bool) -> Status:
    """A bidirectional search's lines: its name and rules, both halves' counts and μ, then
    its narration (:mod:`~tui_search.tui.view.two_way.words`) and at the end its path."""
    from tui_search.tui.view.two_way.words import (
        stop_words,
        two_way_narration,
        two_way_parts,
        two_way_result,
    )

    status = [Piece([(name, "stats--value")])]
    if done:
        status.append(Piece([(f"done at step {run.k:,}", "stats--result")], DONE_RANK, SEP))
    # a pane's own lines (the map comes first) may drop the rule: its label names a first
    # meeting, and the narration says why it stopped
    status.append(Piece([("· " + stop_words(run), "stats--note")], PEAK_RANK if in_pane else 0,
                        (" ", "stats--note")))
    for count, value in two_way_parts(run):
        parts = [(f"{count} ", "stats--label"), (value, "stats--value")]
        status.append(Piece(parts, RANKS.get(count, 1), SEP))
    if playing:
        status.append(Piece([(playing, "stats--play")], PLAYING_RANK, SEP))
    failed = run.at_end and not run.found and not run.gave_up
    cls = "stats--no-path" if failed else "stats--narration"
    line = [Piece([(note, "stats--note")] if note else [(two_way_narration(run, in_pane),
                                                          cls)])]
    if not note and run.at_end and run.found:
        line.append(Piece([(two_way_result(run), "stats--result")], 0, (" · ", "stats--label")))
    return Status([Line(status), Line(line, prose=True)], PANE_ROWS if in_pane else MAX_ROWS)


def lockstep_status(labels: list[str], *, playing: str = "", note: str = "",
                    sentence: str = "", runs: "list[Run | BiRun] | None" = None) -> Status:
    """The lines of several searches: their names and the playback, then a note or
    ``sentence`` (how the lockstep goes).  ``runs``: the panes have no lines of their own
    (no room): each search's step and nodes expanded, which the lessons count, are said
    here, a search a piece."""
    status = [Piece([("compare ", "stats--label"), (" · ".join(labels), "stats--value")])]
    if playing:
        status.append(Piece([(playing, "stats--play")], PLAYING_RANK, SEP))
    lines = [Line(status)]
    if runs:  # a search's path goes to its counts alone when the rows run out (4 searches)
        lines.append(Line([Piece(_counts(label, run) + _path(run), PATH_RANK, SEP,
                                 _counts(label, run))
                           for label, run in zip(labels, runs, strict=True)]))
    line = [Piece([(note, "stats--note")] if note else [(sentence, "stats--narration")])]
    return Status([*lines, Line(line, prose=True)], MAX_ROWS)


def _counts(label: str, run: "Run | BiRun") -> list[tuple[str, str]]:
    """``BFS step 5/22 expanded 5``: a search's counts that never go."""
    parts = [(label, "stats--value")]
    if not isinstance(run, Run):
        from tui_search.tui.view.two_way.words import two_way_parts

        counted = two_way_parts(run)
    else:
        counted = status_parts(run)
    for count, value in counted:
        if RANKS.get(count) == 0:
            parts += [(f" {count} ", "stats--label"), (value, "stats--value")]
    return parts


def _path(run: "Run | BiRun") -> list[tuple[str, str]]:
    """`` path 7 moves`` (or `` no path``) once ``run`` is at its end: what its pane's own
    lines said that a lesson is about (none before)."""
    if not run.at_end or run.gave_up:
        return []
    moves = run.moves()
    if run.found and moves is not None:
        return [(" path ", "stats--label"), (f"{len(moves)} moves", "stats--result")]
    return [(" no path", "stats--no-path")]


def playing_text(session: Session) -> str:
    """``▶ playing 5/s`` while playing, else ``speed 5/s``."""
    speed = playback.speed_text(session.speed)
    return f"▶ playing {speed}" if session.playing else f"speed {speed}"


def screen_status(session: Session, width: int, panes_lines: bool = True) -> Status:
    """The status lines under the panes, ``width`` cells wide: where the panes have lines of
    their own, the lockstep's (the short sentence where the long one would take two lines:
    the panes need them more), with each search's step and nodes expanded when the layout
    left the panes no room for their lines (``panes_lines`` false); else the run's (and the
    session's note)."""
    labels = session.labels
    if own_lines(len(labels)):
        return lockstep_status(labels, playing=playing_text(session), note=session.note,
                               sentence=session.jumps.lockstep_sentence(width),
                               runs=None if panes_lines else session.runs)
    name = get_algorithm(session.contenders[0].algorithm).short  # its heuristic: said after
    return search_status(session.run, name, in_pane=False, playing=playing_text(session),
                         note=session.note, code=session.show_code)


def screen_rows(session: Session, width: int, content_width: int,
                panes_lines: bool) -> tuple[int, int]:
    """The rows :func:`screen_status`'s lines take wrapped to ``content_width`` (as the
    status line widget wraps them), and how many lines they are."""
    status = screen_status(session, width, panes_lines=panes_lines)
    return len(lay_out(status.lines, content_width, status.max_rows)), len(status.lines)


__all__ = ["MAX_ROWS", "PANE_ROWS", "Status", "lockstep_status", "playing_text",
           "screen_rows", "screen_status", "search_status"]

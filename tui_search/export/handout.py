"""A Markdown handout of a run (``--export FILE.md``): what ran on which map, the search's
pseudocode (:mod:`~tui_search.engine.search.pseudocode`), the first steps told as plain mode
tells them (:mod:`~tui_search.plain.telling`: the tutorial's own words for a queue or a stack),
the figures at the end, and the picture -- the app's screen at the last step, a still SVG
written beside the handout and linked from it.
"""

from __future__ import annotations

from tui_search.engine.run.recorded import Run
from tui_search.engine.search.compare import MARKS_KEY, comparison, summary_sentence, table_cells
from tui_search.export.frames import Film
from tui_search.export.job import Job
from tui_search.export.svg import svg_of
from tui_search.plain.two_way import report, result
from tui_search.tui.model.session import Session
from tui_search.tui.view.code_trace import code_of
from tui_search.tui.view.two_way.words import stop_words


def _markdown_table(cells: list[tuple[str, ...]]) -> list[str]:
    head, *rows = cells
    return [f"| {' | '.join(head)} |", f"|{'---|' * len(head)}",
            *(f"| {' | '.join(cell.strip().replace('|', '/') for cell in row)} |"
              for row in rows)]


def handout_of(job: Job, film: Film, picture: str) -> tuple[str, str]:
    """The handout's Markdown, naming ``picture`` (the still's file, beside it), and the
    still: ``film``'s last frame."""
    session = Session(job.grid, job.path, job.algorithm, job.semantics, job.max_steps,
                      job.unsaved_name, compare=job.compare)
    runs, labels = session.runs, session.labels
    several = len(runs) > 1
    first = runs[0]
    rules = "; ".join(first.differences() if isinstance(first, Run) else
                      [stop_words(first)]) if not several else ""
    lines = [f"# {film.title}", "",
             f"A search run by tui-search, step by step: {film.title}, under "
             f"{'these rules: ' + rules if rules else 'the tutorial' + chr(39) + 's rules'}.",
             "", f"![{film.title} at the last step, as the app shows it]({picture})", ""]
    seen: set[str] = set()
    lines += ["## The search", ""]
    for run in runs:
        code = code_of(run)
        if code.title in seen:
            continue
        seen.add(code.title)
        lines += [f"**{code.title}**", "", "```text", *code.numbered(), "```", ""]
    steps = job.handout_steps
    for run in runs:
        run.goto(0)
    lines += [f"## The first {steps} steps" if steps else "## The start", ""]
    for k in range(steps + 1):
        said = []
        for name, run in zip(labels, runs, strict=True):
            if run.k == k:
                said += report(run, name if several else "", False)
            if not run.at_end:
                run.forward()
        if not said:
            break
        lines += [f"- {' '.join(said)}"]
    lines.append("")
    for run in runs:
        run.goto(job.max_steps)
    lines += ["## At the end", ""]
    rows = comparison(labels, [run.outcome() for run in runs], marks=several)
    lines += _markdown_table(table_cells(rows))
    lines += ["", MARKS_KEY if several else "", summary_sentence(rows, job.grid.costs is not None)
              if several else "", ""]
    lines += [f"- {labels[i] + ': ' if several else ''}{result(run)}"
              for i, run in enumerate(runs)]
    lines += ["", f"Made with `tui-search --export`; the picture is the app at step "
              f"{len(film.frames) - 1}, the last.", ""]
    text = "\n".join(line for i, line in enumerate(lines)
                     if line or not (i and not lines[i - 1]))  # no two blank lines in a row
    still = svg_of(film, 1.0, 0.0, frames=[film.frames[-1]],
                   description=f"{film.title} at its last step")
    return text, still

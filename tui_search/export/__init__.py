"""Exports of a run: the app's screen a step at a time, as files for slides, pages and bug
reports (``--export FILE`` with ``--headless``, and the app's palette).

* :mod:`~tui_search.export.kinds`: an export's kind by the file's ending, and its rules;
* :mod:`~tui_search.export.job`: an export asked for, as plain values;
* :mod:`~tui_search.export.files`: an export made, and its files written;
* :mod:`~tui_search.export.frames`: the app run headless, a screen a step;
* :mod:`~tui_search.export.cells`: the app's screen as styled cells, from its screenshot;
* :mod:`~tui_search.export.svg`: an animated SVG, and a still one;
* :mod:`~tui_search.export.cast`: an asciicast v2 recording;
* :mod:`~tui_search.export.gif`: an animated GIF (the ``gif`` extra: Pillow);
* :mod:`~tui_search.export.glyphs`: a character drawn in a cell of the GIF;
* :mod:`~tui_search.export.handout`: a Markdown handout of the run;
* :mod:`~tui_search.export.posthoc`: a Posthoc search trace of the run, its map beside it.
"""

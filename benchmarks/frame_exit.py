"""A program run to its first frame and ended there, for the "instructions" section:

    python benchmarks/frame_exit.py trivial
    python benchmarks/frame_exit.py tui-search maps/tutorial.txt [MORE ARGUMENTS]

``trivial`` runs ``benchmarks/trivial_app.py`` by path, as a user runs a script; ``tui-search``
does what the console script does (:func:`tui_search.launch.main`: the command's modules
imported with the collector paused, then :func:`tui_search.cli.main.main`).  The process ends with
``os._exit(0)`` just after Textual has written its first frame, so that callgrind counts the
work to that frame and nothing after, the interpreter's own start included.  To see the frame,
it wraps ``App._display``, a private method of Textual's (benchmarks only: the app never does).
"""

from __future__ import annotations

import os
import sys
from typing import Any

# os.path, not pathlib: the probe adds as little as it can to what it counts.
HERE = os.path.dirname(os.path.abspath(__file__))
TRIVIAL_APP = os.path.join(HERE, "trivial_app.py")


def exit_after_first_frame() -> None:
    """Wrap ``App._display`` to end the process once a frame has been written."""
    import textual.app

    display = textual.app.App._display

    def _display(self: Any, screen: Any, renderable: Any) -> None:
        display(self, screen, renderable)
        if renderable is not None:
            os._exit(0)

    textual.app.App._display = _display  # type: ignore[method-assign]


def run_trivial() -> None:
    import runpy

    exit_after_first_frame()
    sys.argv = [TRIVIAL_APP]
    runpy.run_path(TRIVIAL_APP, run_name="__main__")


def run_tui_search(args: list[str]) -> None:
    from tui_search.engine.util.collector import collector_paused

    with collector_paused():  # as tui_search.launch.main imports the command
        from tui_search.cli import main as cli
    build_app = cli.build_app

    def build_and_watch(*a: Any) -> Any:
        app = build_app(*a)  # Textual is imported by now, as it is in a real start
        exit_after_first_frame()
        return app

    cli.build_app = build_and_watch  # type: ignore[assignment]
    sys.argv = ["tui-search", *args]
    cli.main()


def main() -> None:
    # Run as a script, this folder is sys.path[0]: drop it (a module here must not shadow one
    # the programs import).
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != HERE]
    what, args = sys.argv[1], sys.argv[2:]
    if what == "trivial":
        run_trivial()
    else:
        run_tui_search(args)
    sys.exit("no frame was drawn")


if __name__ == "__main__":
    main()

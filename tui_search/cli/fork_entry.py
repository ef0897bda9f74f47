"""The fork server's process (``python -m tui_search.cli.fork_entry SOCKET -- APP-ARGS``), which
``--serve`` starts: :func:`tui_search.serve.forks.main`, given the command line's ways to build
an app (once, before the first fork) and to run one (in each fork).
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from tui_search.cli.main import build_app, main
from tui_search.cli.parse import parse_options
from tui_search.serve import forks

if TYPE_CHECKING:
    from tui_search.tui.app import SearchApp


def built(app_args: list[str]) -> SearchApp:
    """The app of a visitor's command line, not run."""
    return build_app(parse_options(app_args))


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(forks.main(sys.argv[1:], build_app=built, app_main=main))

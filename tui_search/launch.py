"""The ``tui-search`` command (and ``python -m tui_search``): :func:`tui_search.cli.main.main`,
with the cyclic collector paused while the program's modules are imported
(:func:`~tui_search.engine.util.collector.collector_paused`: why).
"""

from __future__ import annotations

from tui_search.engine.util.collector import collector_paused


def main() -> int:
    with collector_paused():
        from tui_search.cli.main import main as cli_main
    return cli_main()

"""``python -m tui_search`` is the same as the ``tui-search`` command."""

from tui_search.cli import main

raise SystemExit(main())

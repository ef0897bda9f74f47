"""``python -m tui_search`` is the same as the ``tui-search`` command."""

from tui_search.launch import main

raise SystemExit(main())

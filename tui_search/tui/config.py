"""What the app remembers between runs (the theme), in ``config.json`` in the user's config
directory (``platformdirs``: ``~/.config/tui-search`` on Linux), or in the directory named by
``TUI_SEARCH_CONFIG_DIR`` (the tests point it at a temporary directory).

The file never stops the app.  One that cannot be read, or is not a JSON object, gives a
one-line problem (file, line and column where JSON says) that the app shows once, and the
defaults; such a file is never written over (it may hold what its owner wants back).  A file
that reads but names an unknown theme gives a problem too, and is updated by the next choice,
keeping every other key.  No Textual here: the command line may read it.

The app served to browsers (``tui-search --serve``) neither reads nor writes the file
(:meth:`Config.in_memory`): its visitors are not the file's owner, and thirty of them choosing
themes at once would each overwrite the teacher's choice.  The server passes the theme the
file remembers (or ``--theme``) to every visitor's app; a theme a visitor picks lasts for
their session.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from tui_search.engine.maps.read import MapError
from tui_search.engine.util.atomic import os_reason, write_atomically
from tui_search.tui.view.themes import THEMES, theme_choices

CONFIG_DIR_ENV = "TUI_SEARCH_CONFIG_DIR"
FILE_NAME = "config.json"


def config_path() -> Path:
    """Where the config file is: ``$TUI_SEARCH_CONFIG_DIR/config.json`` when set, else in the
    user's config directory."""
    folder = os.environ.get(CONFIG_DIR_ENV)
    if not folder:
        from platformdirs import user_config_dir

        folder = user_config_dir("tui-search", appauthor=False)
    return Path(folder) / FILE_NAME


class Config:
    """The config file as read: its keys (kept when saving), and why it was not used."""

    # Not a dataclass, which compiles its methods when the app starts.
    def __init__(self, path: Path, data: dict[str, Any] | None = None, problem: str | None = None,
                 keep: bool = False, writable: bool = True) -> None:
        self.path = path
        self.data: dict[str, Any] = data if data is not None else {}
        self.problem = problem  # one line for the user, or None when all is well
        self.keep = keep  # the file could not be read as a config: never write over it
        self.writable = writable  # False: choices are kept in memory only (the served app)

    @classmethod
    def in_memory(cls) -> Config:
        """A config that starts with the defaults and never touches a file."""
        return cls(config_path(), writable=False)

    @classmethod
    def load(cls, path: Path | None = None) -> Config:
        path = config_path() if path is None else path
        where = str(path)
        try:
            text = path.read_text("utf-8")
        except FileNotFoundError:
            return cls(path)
        except UnicodeDecodeError:
            return cls(path, problem=_using_defaults(where, "not UTF-8 text"), keep=True)
        except OSError as err:
            return cls(path, problem=_using_defaults(where, f"cannot read it: {os_reason(err)}"),
                       keep=True)
        import json  # only when there is a file (start-up)

        try:
            data = json.loads(text)
        except json.JSONDecodeError as err:
            return cls(path, problem=_using_defaults(where, f"not valid JSON: {err.msg.lower()}",
                                                     err.lineno, err.colno), keep=True)
        if not isinstance(data, dict):
            return cls(path, problem=_using_defaults(where, "not a JSON object"), keep=True)
        config = cls(path, data)
        theme = data.get("theme")
        if theme is not None and theme not in THEMES:
            config.problem = str(MapError(
                where, f"unknown theme {theme!r} (use {theme_choices()}): using the default"))
        return config

    @property
    def theme(self) -> str | None:
        """The theme the file names, when it is one of ours."""
        theme = self.data.get("theme")
        return theme if isinstance(theme, str) and theme in THEMES else None

    def save_theme(self, name: str) -> str | None:
        """Remember ``name``; None when written (or nothing to write), else why not."""
        if self.keep or self.data.get("theme") == name:
            return None
        data = {**self.data, "theme": name}
        if not self.writable:
            self.data = data
            return None
        import json

        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            write_atomically(str(self.path),
                             (json.dumps(data, indent=2, ensure_ascii=False) + "\n").encode())
        except OSError as err:
            return f"{self.path}: cannot save the theme: {os_reason(err)}"
        self.data = data
        return None


def _using_defaults(where: str, why: str, line: int | None = None,
                    col: int | None = None) -> str:
    message = f"{why}: using the defaults (the file is left as it is)"
    return str(MapError(where, message, line, col))

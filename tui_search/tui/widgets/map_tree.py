"""The file picker beside the open and save-as prompts' name field: Textual's DirectoryTree
showing only folders and map files (``.txt``, ``.map``), every name shown escaped.

Served with a save folder, it shows that folder's map files and nothing else (no folders, no
links): what a visitor may pick is what the folder's rule would take.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from rich.text import Text, TextType
from textual.widgets import DirectoryTree
from textual.widgets.directory_tree import DirEntry
from textual.widgets.tree import TreeNode

from tui_search.engine.util.filenames import describe_name
from tui_search.tui.model.file_rules import MAP_ENDINGS

if TYPE_CHECKING:
    from typing_extensions import Self  # typing's from Python 3.11


class MapTree(DirectoryTree):
    """Folders and map files under ``path``; ``flat``: its map files only (the served app)."""

    # Plain characters: emoji icons take a width that differs from one terminal to the next.
    ICON_NODE_EXPANDED = "▾ "
    ICON_NODE = "▸ "
    ICON_FILE = ""

    DEFAULT_CSS = """
    MapTree { height: 10; width: 30; background: $surface; overflow-x: hidden; }
    """

    def __init__(self, path: Path, *, flat: bool = False, id: str | None = None) -> None:
        self.flat = flat
        self.root_label = describe_name(path.name or str(path))
        super().__init__(path, id=id)
        self.root.set_label(self.root_label)

    def reset_node(self, node: TreeNode[DirEntry], label: TextType,
                   data: DirEntry | None = None) -> Self:
        """The root is labelled with its folder's name alone (not its whole path)."""
        return super().reset_node(node, self.root_label if node is self.root else label, data)

    def filter_paths(self, paths: Iterable[Path]) -> Iterable[Path]:
        return [path for path in paths if self.shows(path)]

    def shows(self, path: Path) -> bool:
        """Whether the picker lists ``path``."""
        if path.name.startswith("."):
            return False
        try:
            if self.flat:
                return (path.is_file() and not path.is_symlink()
                        and path.suffix.lower() in MAP_ENDINGS)
            return path.is_dir() or (path.is_file() and path.suffix.lower() in MAP_ENDINGS)
        except (OSError, ValueError):
            return False

    def process_label(self, label: TextType) -> Text:
        """Each name as :func:`~tui_search.engine.util.filenames.describe_name` shows it."""
        if isinstance(label, str):
            label = describe_name(label)
        return super().process_label(label)

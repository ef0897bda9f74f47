"""The palette's Export command: the run as a file (an animated SVG, a terminal recording, a
GIF, a handout), made by the exporter the command line gives the app (``tui_search/export``,
a layer above the app, which the app never imports): the name asked for, a file that exists
replaced only once the user says so, the export made in a thread (the app films each step
in a headless twin of itself) and its end said in a notification.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any, Protocol

from textual.screen import Screen

from tui_search.engine.util.filenames import describe_name
from tui_search.tui.model.file_rules import FileAccess
from tui_search.tui.model.session import Session

#: What the command says where the app was started without an exporter.
NO_EXPORTER = "Export is not available in this app"


class Exporter(Protocol):
    """What the app exports with (:class:`tui_search.export.files.AppExporter`)."""

    def problem(self, target: str) -> str | None: ...

    def targets(self, target: str) -> list[str]: ...

    def work(self, session: Session, target: str, theme: str | None, force: bool
             ) -> Callable[[], list[str]]: ...


def suggestion(session: Session) -> str:
    """``tutorial-bfs.svg``: the map's name and the searches shown."""
    stem = Path(session.map_name).stem.split(" ")[0] or "run"
    return f"{stem}-{session.spec.replace(',', '-').replace(':', '-')}.svg"


def ask_export(screen: Screen[Any], session: Session, access: FileAccess,
               exporter: Exporter | None) -> None:
    """Ask for the file, then export ``session`` to it (``screen``: the main screen; ``access``:
    where the app may write)."""
    if exporter is None:
        screen.notify(NO_EXPORTER, severity="warning", timeout=5)
        return
    off = access.off
    if off is not None:
        screen.notify(off, title="Not available", severity="warning", timeout=8)
        return
    from tui_search.tui.dialogs.export_prompt import Chosen, ExportScreen

    def chosen(result: Chosen | None) -> None:
        if result is not None:
            _export(screen, session, exporter, *result)

    screen.app.push_screen(
        ExportScreen(exporter.problem, exporter.targets, suggestion(session),
                     to_path=access.path_for, folder=access.folder_for(session.map_path),
                     flat=access.served), chosen)


def _export(screen: Screen[Any], session: Session, exporter: Exporter, path: Path,
            force: bool) -> None:
    app = screen.app
    name = describe_name(str(path))
    try:
        work = exporter.work(session, str(path), app.theme, force)
    except ValueError as exc:
        screen.notify(f"Not exported: {exc}", title="Export", severity="error", timeout=8,
                      markup=False)
        return
    screen.notify(f"Exporting {name}: the app films each step…", title="Export", timeout=4,
                  markup=False)

    def run() -> None:
        try:
            written = work()
        except Exception as exc:  # whatever it was: said, and the app goes on
            said = f"Not exported: {exc}"
            app.call_from_thread(screen.notify, said, title="Export", severity="error",
                                 timeout=10, markup=False)
            return
        done = "Exported " + ", ".join(describe_name(n) for n in written)
        app.call_from_thread(screen.notify, done, title="Export", timeout=6, markup=False)

    screen.run_worker(run, thread=True, group="export", exit_on_error=False)

"""Every test runs with its own empty config directory (``TUI_SEARCH_CONFIG_DIR``), so no test
reads or writes the user's real config file, and a theme remembered there cannot change a
snapshot.  Hypothesis checks no timing (no deadline, no "too slow" health check): on a busy
machine generating an example can take seconds, which says nothing about the code.

The suite leaves the clone as it found it: a file or folder that a test made or changed in the
repository (a served app's save folder in ``maps/``, a screenshot in the current folder) fails
the run, named (:func:`pytest_sessionfinish`; not with ``--snapshot-update``, which is meant
to change files)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

from tui_search.tui.config import CONFIG_DIR_ENV

settings.register_profile("untimed", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("untimed")


@pytest.fixture(autouse=True)
def _own_config_dir(tmp_path_factory: pytest.TempPathFactory,
                    monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(CONFIG_DIR_ENV, str(tmp_path_factory.mktemp("config")))


ROOT = Path(__file__).resolve().parent.parent


def _changed_files() -> set[str] | None:
    """The repository's changed and untracked files (git's porcelain lines; ignored files
    are not among them), or None where there is no git work tree."""
    try:
        out = subprocess.run(["git", "status", "--porcelain", "--untracked-files=all"],
                             cwd=ROOT, capture_output=True, text=True, timeout=60, check=True)
    except (OSError, subprocess.SubprocessError):
        return None
    return set(out.stdout.splitlines())


def _checks_the_clone(config: pytest.Config) -> bool:
    """Only the controlling process checks (not each xdist worker), and not on a snapshot
    update."""
    return (not hasattr(config, "workerinput")
            and not config.getoption("--snapshot-update", default=False))


def pytest_sessionstart(session: pytest.Session) -> None:
    if _checks_the_clone(session.config):
        session.config.stash[_BEFORE] = _changed_files()


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    before = session.config.stash.get(_BEFORE, None)
    if before is None:
        return
    after = _changed_files()
    made = sorted((after or set()) - before)
    if made:
        print("\nThe tests changed the clone (each test must write only in its tmp_path):")
        for line in made:
            print(f"  {line}")
        session.exitstatus = pytest.ExitCode.TESTS_FAILED


_BEFORE = pytest.StashKey[set[str] | None]()

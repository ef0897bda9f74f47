"""Every test runs with its own empty config directory (``TUI_SEARCH_CONFIG_DIR``), so no test
reads or writes the user's real config file, and a theme remembered there cannot change a
snapshot.  Hypothesis checks no timing (no deadline, no "too slow" health check): on a busy
machine generating an example can take seconds, which says nothing about the code."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, settings

from tui_search.tui.config import CONFIG_DIR_ENV

settings.register_profile("untimed", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("untimed")


@pytest.fixture(autouse=True)
def _own_config_dir(tmp_path_factory: pytest.TempPathFactory,
                    monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(CONFIG_DIR_ENV, str(tmp_path_factory.mktemp("config")))

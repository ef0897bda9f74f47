"""``--theme NAME``: the app starts in that theme for this run; a wrong name is one line naming
the choices and exit code 2, like every bad flag; without it the app takes the remembered one."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.test_cli import TUTORIAL, run_cli
from tui_search.cli.flags import EXIT_BAD_INPUT
from tui_search.tui.config import CONFIG_DIR_ENV
from tui_search.tui.view.themes import THEMES


@pytest.fixture
def started(monkeypatch) -> list[str]:
    """The theme each app the command line starts is in (the app is not run)."""
    from tui_search.tui.app import SearchApp

    themes: list[str] = []

    def run(self: SearchApp) -> None:
        themes.append(self.theme)

    monkeypatch.setattr(SearchApp, "run", run)
    return themes


@pytest.mark.parametrize("name", list(THEMES))
def test_theme_flag_starts_the_app_in_that_theme(capsys, started, name) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--theme", name)
    assert (code, out, err) == (0, "", "")
    assert started == [name]


def test_without_the_flag_the_remembered_theme(capsys, started) -> None:
    (Path(os.environ[CONFIG_DIR_ENV]) / "config.json").write_text('{"theme": "light"}')
    assert run_cli(capsys, TUTORIAL)[0] == 0
    assert started == ["light"]


def test_a_wrong_theme_is_one_line_naming_the_choices(capsys, started) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--theme", "neon")
    assert code == EXIT_BAD_INPUT and out == "" and started == []
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith("tui-search: error: argument --theme: invalid choice: 'neon'")
    assert all(repr(name) in err for name in THEMES)


def test_theme_is_refused_with_headless(capsys) -> None:
    code, out, err = run_cli(capsys, TUTORIAL, "--headless", "--theme", "light")
    assert (code, out) == (EXIT_BAD_INPUT, "")
    assert err == "tui-search: error: --theme is for the app and --export, not --headless alone\n"


def test_help_names_every_theme(capsys) -> None:
    with pytest.raises(SystemExit):
        run_cli(capsys, "--help")
    out = " ".join(capsys.readouterr().out.split())
    assert all(f"{spec.name}: {spec.description}" in out for spec in THEMES.values())

"""``--export FILE --headless`` on the command line: the kind by the ending, the flags that go
with it, never over a file without ``--force``, ``--theme``'s colours, the map view, and a
one-line refusal (exit 2) for what cannot be exported -- naming the map's or the run's size.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.export.test_exports import job
from tests.test_cli import TUTORIAL, run_cli
from tui_search.cli.flags import EXIT_BAD_INPUT
from tui_search.export.cells import row_text
from tui_search.export.files import NEEDS_PILLOW
from tui_search.export.frames import film
from tui_search.tui.view.themes import THEMES


def one_line_error(code: int, out: str, err: str) -> str:
    assert code == EXIT_BAD_INPUT and out == "" and err.count("\n") == 1, (code, out, err)
    assert "Traceback" not in err
    return err.removeprefix("tui-search: error: ").strip()


def test_a_cast_written_from_the_command_line(capsys, tmp_path: Path) -> None:
    target = tmp_path / "run.cast"
    code, out, err = run_cli(capsys, TUTORIAL, "-a", "dfs", "--headless", "--export",
                             str(target), "--fps", "4")
    assert (code, err) == (0, "") and out == f"Wrote {target}\n"
    lines = target.read_text().splitlines()
    assert json.loads(lines[0])["title"] == "DFS on tutorial.txt"
    assert [json.loads(line)[0] for line in lines[1:9]] == [k / 4 for k in range(8)]  # 7 steps


def test_an_existing_file_is_replaced_only_with_force(capsys, tmp_path: Path) -> None:
    target = tmp_path / "run.svg"
    target.write_text("mine")
    said = one_line_error(*run_cli(capsys, TUTORIAL, "--headless", "--export", str(target)))
    assert said == f"{target} exists: --force replaces it" and target.read_text() == "mine"
    code, out, err = run_cli(capsys, TUTORIAL, "-a", "dfs", "--headless", "--export",
                             str(target), "--force")
    assert (code, err) == (0, "") and target.read_text().startswith("<svg")


@pytest.mark.parametrize(("argv", "said"), [
    (["--export", "run.svg"], "--export writes a file from a run without the app: add "
     "--headless (in the app: the palette's Export command, ctrl+p)"),
    (["--headless", "--export", "run.txt"], "--export run.txt: the kind is the file's ending, "
     "one of .svg, .cast, .gif, .md, .trace.json, .trace.yaml"),
    (["--headless", "--fps", "3"], "--fps goes with --export FILE"),
    (["--headless", "--export-view", "map"], "--export-view goes with --export FILE"),
    (["--headless", "--force"], "--force goes with --export FILE"),
    (["--headless", "--export", "run.svg", "--handout-steps", "3"],
     "--handout-steps goes with a handout, --export FILE.md"),
    (["--headless", "--export", "run.svg", "--json"],
     "--export writes one run (or a comparison): leave out --json"),
    (["--headless", "--export", "run.svg", "--fps", "0"],
     "argument --fps: '0': give frames a second from 0.1 to 50 (see tui-search --help)"),
])
def test_flags_that_make_no_sense_are_one_line(capsys, tmp_path: Path, monkeypatch,
                                               argv: list[str], said: str) -> None:
    monkeypatch.chdir(tmp_path)
    assert one_line_error(*run_cli(capsys, TUTORIAL, *argv)) == said
    assert list(tmp_path.iterdir()) == []


def test_a_gif_without_pillow_is_one_line_saying_how_to_install_it(capsys, tmp_path: Path,
                                                                   monkeypatch) -> None:
    monkeypatch.setattr("tui_search.export.files.find_spec", lambda name: None)
    target = tmp_path / "run.gif"
    said = one_line_error(*run_cli(capsys, TUTORIAL, "--headless", "--export", str(target)))
    assert said == NEEDS_PILLOW and not target.exists()


def test_a_run_longer_than_an_export_holds_is_refused_naming_its_steps(capsys, tmp_path: Path,
                                                                       monkeypatch) -> None:
    monkeypatch.setattr("tui_search.export.frames.MAX_FRAMES", 10)
    target = tmp_path / "run.svg"
    said = one_line_error(*run_cli(capsys, TUTORIAL, "--headless", "--export", str(target)))
    assert said == ("the run takes 22 steps: an export holds at most 10 frames, one a step (a "
                    "smaller map, or --max-steps)")
    assert not target.exists()


def test_the_theme_s_colours_are_the_export_s() -> None:
    light = film(job(theme="light", view="map", algorithm="dfs"))
    background = THEMES["light"].colours["background"]
    assert light.frames[0][0][0][1].bg == background
    dark = film(job(view="map", algorithm="dfs"))
    assert dark.frames[0][0][0][1].bg != background
    assert [[row_text(r) for r in f] for f in light.frames] == [
        [row_text(r) for r in f] for f in dark.frames]  # the same screens, other colours


def wide_map(tmp_path: Path) -> Path:
    """60 x 20 free cells, the goal beside the start: too wide for 2 x 1 cells beside the
    panels at 100 x 30, and one step long."""
    rows = ["SG" + "." * 58] + ["." * 60] * 19
    path = tmp_path / "wide.txt"
    path.write_text("\n".join(rows) + "\n")
    return path


def test_a_map_too_big_for_the_full_view_is_refused_naming_its_size(capsys,
                                                                   tmp_path: Path) -> None:
    target = tmp_path / "run.svg"
    said = one_line_error(*run_cli(capsys, str(wide_map(tmp_path)), "--headless", "--export",
                                   str(target)))
    assert said == ("the map is 60x20: at 100x30 it does not show whole beside the frontier "
                    "and the tree (--export-view map: the map alone)")
    assert not target.exists()


def test_the_map_view_is_the_maps_alone_whole(tmp_path: Path) -> None:
    from tui_search.engine.maps.load import load_map

    path = wide_map(tmp_path)
    shot = film(job(grid=load_map(path), path=path, view="map"))
    assert len(shot.frames) == 2 and shot.width < 200 and shot.height < 60
    top = row_text(shot.frames[0][0])
    assert "wide.txt" in top and "part of the map" not in "".join(
        row_text(r) for r in shot.frames[0])
    assert "Queue" not in "".join(row_text(r) for r in shot.frames[-1])  # no panels


def test_a_comparison_is_filmed_in_lockstep(tmp_path: Path) -> None:
    shot = film(job(compare="bfs,dfs", view="map"))
    assert shot.title == "BFS and DFS on tutorial.txt"
    assert len(shot.frames) == 23  # until the longer run, BFS's 22 steps, ends


def test_a_map_too_big_to_show_cell_by_cell_is_exported_in_the_app_s_overview(
        tmp_path: Path) -> None:
    from tui_search.engine.maps.load import load_map

    path = tmp_path / "big.txt"
    path.write_text("\n".join(["SG" + "." * 298] + ["." * 300] * 199) + "\n")
    shot = film(job(grid=load_map(path), path=path, view="map"))
    assert len(shot.frames) == 2 and shot.width <= 200 and shot.height <= 60
    text = "\n".join(row_text(r) for r in shot.frames[0])
    assert "big.txt" in text and "part of the map" not in text
    assert "▀" in text  # the overview's half blocks, two rows of blocks a line

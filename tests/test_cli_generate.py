"""--generate on the command line: writing a new file, opening the map untitled, and one-line
errors with exit 2."""

from __future__ import annotations

from pathlib import Path

import pytest

from tui_search.cli import main as cli
from tui_search.cli.main import main
from tui_search.engine.maps.generate import generate, generated_text, make_recipe


def run_cli(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_output_writes_the_map_and_exits_0(capsys, tmp_path: Path) -> None:
    out = tmp_path / "maze.txt"
    code, stdout, err = run_cli(capsys, "--generate", "maze", "--size", "15x9", "--seed", "7",
                                "--output", str(out))
    assert (code, stdout, err) == (0, "", "")
    assert out.read_text("utf-8") == generated_text(make_recipe("maze", "15x9", "7"))
    assert out.read_text("utf-8").startswith("; generated: maze 15x9 seed 7\nS")


def test_output_dash_is_standard_output(capsys, tmp_path: Path, monkeypatch) -> None:
    """``--output -`` prints the map (the convention, as --trace -): no file named ``-``;
    ``./-`` still names one."""
    monkeypatch.chdir(tmp_path)
    code, stdout, err = run_cli(capsys, "--generate", "maze", "--size", "15x9", "--seed", "7",
                                "--output", "-")
    assert (code, err) == (0, "") and not (tmp_path / "-").exists()
    assert stdout == generated_text(make_recipe("maze", "15x9", "7"))
    assert run_cli(capsys, "--generate", "maze", "--output", "./-")[:2] == (0, "")
    assert (tmp_path / "-").read_text("utf-8").startswith("; generated: maze 21x15 seed 1\n")


def test_text_seeds_and_the_defaults(capsys, tmp_path: Path) -> None:
    out = tmp_path / "a.txt"
    assert run_cli(capsys, "--generate", "random:25", "--seed", "alice", "--output",
                   str(out))[0] == 0
    assert out.read_text("utf-8").splitlines()[0] == "; generated: random:25 21x15 seed alice"


def test_an_existing_file_is_never_replaced(capsys, tmp_path: Path) -> None:
    out = tmp_path / "mine.txt"
    out.write_text("my work\n")
    code, _, err = run_cli(capsys, "--generate", "prim", "--output", str(out))
    assert code == 2
    assert err == (f"tui-search: error: --output {out}: the file exists; a generated map never "
                   "replaces a file (choose another name)\n")
    assert out.read_text() == "my work\n"


def test_a_dangling_link_is_not_followed(capsys, tmp_path: Path) -> None:
    link = tmp_path / "link.txt"
    link.symlink_to(tmp_path / "elsewhere.txt")
    assert run_cli(capsys, "--generate", "maze", "--output", str(link))[0] == 2
    assert not (tmp_path / "elsewhere.txt").exists()


@pytest.mark.parametrize(("argv", "message"), [
    (["--generate", "blob"], ("--generate: unknown kind 'blob' (kinds: random:P, maze, prim, "
                              "kruskal, division, rooms)")),
    (["--generate", "maze", "--size", "2x2"], "--generate: size 2x2: maze needs at least 3x3"),
    (["--generate", "maze", "--size", "1000x10"], "--generate: size 1000x10: at most 999x999"),
    (["--generate", "random:100.5"], "--generate: random:100.5: P must be a number from 0 to 100"),
    (["--generate", "random:x"], "--generate: random:x: P must be a number from 0 to 100"),
    (["--size", "9x9"], "--size goes with --generate"),
    (["--output", "x.txt"], "--output goes with --generate"),
    (["--generate", "maze", "some.txt"], "--generate makes the map: leave out MAP"),
    (["--generate", "maze", "--output", "x.txt", "--headless"],
     "--output writes the map and exits: leave out --headless"),
    (["--generate", "maze", "--output", "x.txt", "--exercise", "1"],
     "--output writes the map and exits: leave out --exercise"),
    (["--generate", "maze", "--output", "x.txt", "--compare", "bfs,dfs"],
     "--output writes the map and exits: leave out --compare"),
    (["--generate", "maze", "--seed", ""], "--seed is empty: give a number or a word"),
    (["--generate", "maze", "--size", " "], "--size is empty: give WxH, as 40x20"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path: Path, monkeypatch,
                                          argv: list[str], message: str) -> None:
    monkeypatch.chdir(tmp_path)  # no file may be left in the clone
    code, out, err = run_cli(capsys, *argv)
    assert (code, out, err) == (2, "", f"tui-search: error: {message}\n")
    assert list(tmp_path.iterdir()) == []


def test_a_missing_folder_is_one_line(capsys, tmp_path: Path) -> None:
    target = tmp_path / "no" / "x.txt"
    code, _, err = run_cli(capsys, "--generate", "maze", "--output", str(target))
    assert code == 2
    assert err == f"tui-search: error: --output {target}: cannot save: the folder does not exist\n"


def test_without_output_the_app_opens_the_map_untitled(capsys, monkeypatch) -> None:
    seen = {}

    def fake_run_app(options) -> int:
        seen["app"] = cli.build_app(options)
        return 0

    monkeypatch.setattr(cli, "run_app", fake_run_app)
    assert run_cli(capsys, "--generate", "kruskal", "--size", "11x7", "--seed", "3")[0] == 0
    session = seen["app"].session
    assert session.map_path is None and not session.dirty
    assert session.title == "kruskal 11x7 seed 3"
    assert session.grid == generate(make_recipe("kruskal", "11x7", "3"))


def test_headless_names_the_recipe(capsys) -> None:
    code, out, _ = run_cli(capsys, "--generate", "maze", "--size", "9x9", "--headless",
                           "--order", "N,E,S,W")
    assert code == 0
    assert out.splitlines()[0] == "Breadth-first search on maze 9x9 seed 1: path found"


def test_the_help_says_the_maze_is_dfs(capsys) -> None:
    with pytest.raises(SystemExit):
        main(["--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "maze: recursive backtracker: depth-first search carving a maze" in text
    assert "random: random:P, P% (0-100) of cells obstacles" in text

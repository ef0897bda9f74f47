"""Installing tui-search as its users do: from the built sdist and wheel into a fresh venv, and
on a machine with no C compiler, where the Python search core runs and says so.

Each test builds in a fresh venv (~10-25 s): the package's own dependencies come from the
running environment (a ``.pth`` file), the build's from the package index, as ``pip install``
gets them on a fresh clone (``.ci/run``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import zipfile
from pathlib import Path

from tests.helpers import ROOT
from tui_search.engine.search.loops.compiled import CORE_ENV

#: What a build reads: the package and the files beside it the sdist carries.
BUILD_INPUT = ["tui_search", "maps", "docs", "pyproject.toml", "setup.py", "MANIFEST.in",
               "README.md", "CONTRIBUTING.md"]


def _source(tmp: Path) -> Path:
    """A copy of what the build reads, without the editable install's built module."""
    src = tmp / "src"
    for name in BUILD_INPUT:
        path = ROOT / name
        if path.is_dir():
            shutil.copytree(path, src / name,
                            ignore=shutil.ignore_patterns("*.so", "*.pyd", "__pycache__"))
        else:
            src.mkdir(exist_ok=True)
            shutil.copy2(path, src / name)
    return src


def _venv(tmp: Path) -> Path:
    """A fresh venv that sees this environment's packages (Textual and the rest), not its
    tui-search: the one to test is installed into it."""
    venv = tmp / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    purelib = Path(sysconfig.get_paths(vars={"base": str(venv), "platbase": str(venv)})["purelib"])
    (purelib / "deps.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    return venv / ("Scripts" if os.name == "nt" else "bin")


def _run(*argv: str | Path, **env: str) -> subprocess.CompletedProcess[str]:
    environ = {k: v for k, v in os.environ.items() if k != CORE_ENV} | env
    return subprocess.run([str(a) for a in argv], check=False, capture_output=True, text=True,
                          env=environ, timeout=300)


def _pip_install(bin_dir: Path, target: Path, **env: str) -> None:
    done = _run(sys.executable, "-m", "pip", "--python", bin_dir / "python", "install", "-q",
                "--no-deps", target, **env)
    assert done.returncode == 0, done.stderr


def _check_the_app_runs(bin_dir: Path, core: str) -> None:
    """``tui-search --version`` names ``core``; the tutorial (the packaged map) runs headless."""
    version = _run(bin_dir / "tui-search", "--version")
    assert version.returncode == 0 and version.stdout.strip().endswith(f"({core})")
    tutorial = _run(bin_dir / "tui-search", "--headless")
    assert tutorial.returncode == 0 and "tutorial.txt: path found" in tutorial.stdout


def test_without_a_compiler_the_python_core_runs_and_says_so(tmp_path: Path) -> None:
    bin_dir = _venv(tmp_path)
    _pip_install(bin_dir, _source(tmp_path), CC="false")  # the optional build fails: no error
    _check_the_app_runs(bin_dir, "Python search core; the compiled one is not built")


def test_the_sdist_and_the_wheel_carry_the_core_and_the_maps(tmp_path: Path) -> None:
    """``python -m build``: the sdist carries the C source, the maps and the docs and builds the
    compiled core (the wheel is built from it); the wheel, installed, runs it."""
    dist = tmp_path / "dist"
    built = _run(sys.executable, "-m", "build", "--outdir", dist, _source(tmp_path))
    assert built.returncode == 0, built.stderr
    (sdist,), (wheel,) = dist.glob("*.tar.gz"), dist.glob("*.whl")
    with tarfile.open(sdist) as tar:
        names = {name.split("/", 1)[1] for name in tar.getnames() if "/" in name}
    assert {"setup.py", "tui_search/engine/search/_core.c",
            "tui_search/engine/search/_core_loops.c", "tui_search/engine/search/_core_position.c",
            "tui_search/engine/search/_core.h", "maps/tutorial.txt",
            "tui_search/maps/tutorial.txt", "tui_search/tui/app.tcss", "docs/README.md",
            "docs/03-traces.md"} <= names
    with zipfile.ZipFile(wheel) as whl:
        names = set(whl.namelist())
    assert {"tui_search/maps/tutorial.txt", "tui_search/tui/app.tcss",
            "tui_search/lessons/tutorial.md", "tui_search/lessons/choices.md",
            "tui_search/lessons/dfs-longer.txt", "tui_search/lessons/bidirectional.md",
            "tui_search/lessons/pathfinding-js-28.txt",
            "tui_search/exercises/1-bfs-expands-less.toml",
            "tui_search/exercises/2-dfs-not-optimal.toml"} <= names
    assert any(name.startswith("tui_search/engine/search/_core.")
               and not name.endswith((".c", ".h")) for name in names)
    bin_dir = _venv(tmp_path)
    _pip_install(bin_dir, wheel)
    _check_the_app_runs(bin_dir, "compiled search core")

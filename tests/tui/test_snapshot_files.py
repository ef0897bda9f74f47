"""Every snapshot picture belongs to a test that still exists.

syrupy reports unused snapshots at the end of a session, but not when the suite runs on
several workers (pytest-xdist): this check does it for any run, so a renamed or deleted
snapshot test cannot leave a stale picture behind."""

from __future__ import annotations

import ast
from pathlib import Path

HERE = Path(__file__).resolve().parent


def stale_snapshots(here: Path) -> list[str]:
    """Snapshot pictures under ``here`` whose test function no longer exists."""
    stale = []
    for folder in sorted((here / "__snapshots__").iterdir()):
        module = here / f"{folder.name}.py"
        tests = set()
        if module.is_file():
            tree = ast.parse(module.read_text("utf-8"))
            tests = {node.name for node in ast.walk(tree)
                     if isinstance(node, ast.FunctionDef) and node.name.startswith("test_")}
        for svg in sorted(folder.glob("*.svg")):
            if svg.stem.split("[")[0] not in tests:
                stale.append(f"{folder.name}/{svg.name}")
    return stale


def test_every_snapshot_svg_has_its_test() -> None:
    stale = stale_snapshots(HERE)
    assert stale == [], "snapshots without a test (delete them): " + ", ".join(stale)


def test_the_check_sees_a_stale_picture(tmp_path) -> None:
    """The check above can fail: a picture with no test is reported."""
    (tmp_path / "__snapshots__" / "test_gone").mkdir(parents=True)
    (tmp_path / "__snapshots__" / "test_gone" / "test_old.svg").write_text("<svg/>")
    assert stale_snapshots(tmp_path) == ["test_gone/test_old.svg"]

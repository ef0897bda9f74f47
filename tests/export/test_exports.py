"""Exports of a run (``--export``): the app filmed a screen a step, then written as an animated
SVG, an asciicast v2 recording, a GIF or a Markdown handout.

Each kind is checked by reading it back, not by looking at it: the SVG parses as XML and its
frames, put together as a viewer does, show the app's screen at each step; the recording
follows asciicast v2's rules and, played into a screen, draws each step; the GIF has a frame
a step; the handout says the tutorial's words and links its picture.  The same run gives the
same bytes: two films of it are the same, and so is everything written from them.
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from html import unescape
from io import BytesIO

import pytest

from tests.helpers import TUTORIAL
from tui_search.engine.maps.load import load_map
from tui_search.engine.search.choices import Semantics
from tui_search.export.cast import cast_of
from tui_search.export.cells import CHAR_WIDTH, LINE_HEIGHT, row_text
from tui_search.export.files import make_export
from tui_search.export.frames import Film, film
from tui_search.export.gif import gif_of
from tui_search.export.handout import handout_of
from tui_search.export.job import Job
from tui_search.export.svg import svg_of

FPS, HOLD = 2.0, 2.0
SVG_NS = "{http://www.w3.org/2000/svg}"
XLINK = "{http://www.w3.org/1999/xlink}href"
#: The tutorial's own narration of BFS's first four steps, word for word.
TUTORIAL_WORDS = [
    "Start is taken out of the queue and expanded. South is the only successor so it is "
    "added to the queue.",
    "South is taken out of the queue and expanded. S and SE are the successors and they are "
    "added to the queue.",
    "S is taken out of the queue and expanded adding S and SE to the queue.",
    "Next SE is expanded adding E and NE to the queue.",
]


def job(target: str = "run.svg", **changes: object) -> Job:
    grid = load_map(TUTORIAL)
    values: dict[str, object] = dict(
        target=target, grid=grid, path=TUTORIAL, unsaved_name="tutorial (built-in)",
        algorithm="bfs", semantics=Semantics(), compare=None, max_steps=1_000_000, theme=None,
        fps=FPS, view="full", force=False, handout_steps=10)
    values.update(changes)
    return Job(**values)  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def films() -> tuple[Film, Film]:
    """BFS on the tutorial's map, filmed twice, each time by an app of its own."""
    return film(job()), film(job())


def test_a_run_filmed_twice_gives_the_same_frames_a_frame_a_step(films) -> None:
    one, two = films
    assert one == two
    assert (len(one.frames), one.width, one.height) == (23, 100, 30)  # steps 0 to 22
    assert one.title == "BFS on tutorial.txt"
    for k, screen in enumerate(one.frames):
        assert any(f"step {k}/22" in row_text(row) for row in screen), k


@pytest.mark.parametrize("kind", ["svg", "cast", "gif", "md"])
def test_every_kind_is_the_same_bytes_for_the_same_run(films, kind: str) -> None:
    def written(shot: Film) -> bytes:
        if kind == "svg":
            return svg_of(shot, FPS, HOLD).encode()
        if kind == "cast":
            return cast_of(shot, FPS, HOLD).encode()
        if kind == "gif":
            return gif_of(shot, FPS, HOLD)
        text, still = handout_of(job("run.md"), shot, "run-final.svg")
        return (text + still).encode()

    one, two = films
    assert written(one) == written(two)


def svg_frames(svg: str) -> list[list[str]]:
    """Each frame of an animated SVG as a viewer shows it, read back as text: frame 0's
    pieces, then frame k's laid over them; each piece a def whose texts place a character at
    each x."""
    root = ET.fromstring(svg)
    defs = {g.get("id"): g for g in root.iter(f"{SVG_NS}g") if (g.get("id") or "").startswith("r")}
    steps = [g for g in root.iter(f"{SVG_NS}g") if (g.get("id") or "").startswith("step-")]
    assert [g.get("id") for g in steps] == [f"step-{k}" for k in range(len(steps))]
    width = round((float(root.get("viewBox", "").split()[2]) - 18) / CHAR_WIDTH)

    def laid(rows: dict[int, list[str]], group: ET.Element) -> None:
        for use in group.iter(f"{SVG_NS}use"):
            piece = defs[use.get(XLINK, "#")[1:]]
            x0, y = float(use.get("x", 0)), round(float(use.get("y", 0)) / LINE_HEIGHT)
            row = rows.setdefault(y, [" "] * width)
            n = round(sum(float(r.get("width", 0)) for r in piece.iter(f"{SVG_NS}rect"))
                      / CHAR_WIDTH)
            start = round(x0 / CHAR_WIDTH)
            row[start:start + n] = [" "] * n  # the piece paints its whole width
            for text in piece.iter(f"{SVG_NS}text"):
                for x, ch in zip(text.get("x", "").split(), unescape(text.text or ""),
                                 strict=True):
                    row[round((x0 + float(x)) / CHAR_WIDTH)] = ch.replace("\xa0", " ")

    base: dict[int, list[str]] = {}
    laid(base, steps[0])
    frames = []
    for group in steps:
        rows = {y: list(row) for y, row in base.items()}
        laid(rows, group)
        frames.append(["".join(rows[y]).rstrip() for y in sorted(rows)])
    return frames


def test_the_svg_parses_as_xml_with_a_frame_a_step_each_the_app_s_screen(films) -> None:
    shot = films[0]
    svg = svg_of(shot, FPS, HOLD)
    frames = svg_frames(svg)
    assert len(frames) == 23
    for k, frame in enumerate(frames):
        assert frame == [row_text(row).rstrip() for row in shot.frames[k]], k
    root = ET.fromstring(svg)
    animations = list(root.iter(f"{SVG_NS}animate"))
    assert len(animations) == 22  # frame 0 is under all of them; each later one shows in turn
    total = 23 / FPS + HOLD
    for k, animate in enumerate(animations, start=1):
        assert animate.get("attributeName") == "visibility"
        assert animate.get("repeatCount") == "indefinite" and animate.get("calcMode") == "discrete"
        assert animate.get("dur") == f"{total:.3f}s"
        assert float(animate.get("keyTimes", "").split(";")[1]) == pytest.approx(k / FPS / total,
                                                                                  abs=1e-6)
    assert not list(root.iter(f"{SVG_NS}script")) and "javascript" not in svg.lower()
    assert root.find(f"{SVG_NS}title").text == "BFS on tutorial.txt (23 frames, tui-search)"


CSI = re.compile(r"\x1b\[([?\d;]*)([A-Za-z])")


def played(events: list[str], width: int, height: int) -> list[list[str]]:
    """The screen after each event's output, as a terminal draws it: cursor moves, clears
    and text (colours are not kept)."""
    screen = [[" "] * width for _ in range(height)]
    x = y = 0
    after = []
    for data in events:
        at = 0
        for m in CSI.finditer(data):
            for ch in data[at:m.start()]:
                screen[y][x] = ch
                x = min(x + 1, width - 1)
            params, final = m.groups()
            if final == "H":
                row, _, col = params.partition(";")
                y, x = int(row or 1) - 1, int(col or 1) - 1
            elif final == "J" and params == "2":
                screen = [[" "] * width for _ in range(height)]
            at = m.end()
        for ch in data[at:]:
            screen[y][x] = ch
            x = min(x + 1, width - 1)
        after.append(["".join(row).rstrip() for row in screen])
    return after


def test_the_cast_is_asciicast_v2_and_replays_the_run(films) -> None:
    shot = films[0]
    lines = cast_of(shot, FPS, HOLD).splitlines()
    header = json.loads(lines[0])
    assert header["version"] == 2 and (header["width"], header["height"]) == (100, 30)
    assert "timestamp" not in header  # no wall clock: the same run, the same bytes
    events = [json.loads(line) for line in lines[1:]]
    times = [e[0] for e in events]
    assert all(isinstance(e, list) and len(e) == 3 and e[1] == "o" and isinstance(e[2], str)
               for e in events)
    assert times == sorted(times) and times[:23] == [k / FPS for k in range(23)]
    assert times[-1] == pytest.approx(22 / FPS + HOLD)
    screens = played([e[2] for e in events], 100, 30)
    for k in range(23):
        assert screens[k] == [row_text(row).rstrip() for row in shot.frames[k]], k


def test_the_gif_has_a_frame_a_step(films) -> None:
    from PIL import Image

    image = Image.open(BytesIO(gif_of(films[0], FPS, HOLD)))
    assert image.format == "GIF" and image.size == (800, 480)
    assert image.n_frames == 23 and image.info["loop"] == 0
    durations = []
    for k in range(23):
        image.seek(k)
        durations.append(image.info["duration"])
    assert durations == [500] * 22 + [2500]


def test_the_handout_tells_the_first_steps_in_the_tutorial_s_words(films) -> None:
    text, still = handout_of(job("run.md", handout_steps=4), films[0], "run-final.svg")
    assert "![BFS on tutorial.txt at the last step, as the app shows it](run-final.svg)" in text
    assert "```text\n 1  frontier ← a queue holding START" in text
    for k, words in enumerate(TUTORIAL_WORDS, start=1):
        assert f"- Step {k}: {words}" in text
    assert "Step 5:" not in text and "## The first 4 steps" in text
    assert "| BFS | yes | 7 | 8.657 | 22 | 24 | 8 |" in text
    assert len(svg_frames(still)) == 1 and "step 22/22" in "\n".join(svg_frames(still)[0])


def test_make_export_writes_new_files_and_replaces_only_with_force(tmp_path) -> None:
    target = tmp_path / "run.md"
    picture = tmp_path / "run-final.svg"
    picture.write_text("a picture of mine")
    with pytest.raises(ValueError, match="run-final.svg exists: --force replaces it"):
        make_export(job(str(target), handout_steps=1))
    assert picture.read_text() == "a picture of mine" and not target.exists()
    assert make_export(job(str(target), handout_steps=1, force=True)) == [str(target),
                                                                          str(picture)]
    assert picture.read_text().startswith("<svg") and "Step 1:" in target.read_text()

"""Every reader of a file someone else wrote (a map, a table, a scenario, a student's trace, a
teacher's exercise or lesson) survives hostile input: a one-line error naming the file (and
the line and column where they apply), never a traceback, in memory within ten times the
file (plus :data:`ALLOWANCE`) and in a bounded time.

Each reader is a line of :data:`READERS`; every case below runs on each: nesting 200,000
deep, a YAML alias bomb, a line of 100 MB, a NUL, a byte that is not UTF-8, a file of 1 GB,
the most memory-hungry files of its format, and random bytes and text (hypothesis).  A new
reader (a ``.graph`` map, a Posthoc trace) joins by adding its line (CONTRIBUTING.md,
"Untrusted files")."""

from __future__ import annotations

import os
import resource
import tempfile
import tracemalloc
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.helpers import MAPS
from tui_search.engine.course.autograder_files import MAX_TEST_BYTES, read_course_test
from tui_search.engine.course.exercise_file import MAX_EXERCISE_BYTES, load_exercise
from tui_search.engine.course.lesson import MAX_LESSON_BYTES, read_lesson
from tui_search.engine.maps.graph_file import MAX_GRAPH_BYTES, load_graph
from tui_search.engine.maps.layouts import parse_layout
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.read import MAX_MAP_BYTES, MapError, read_text
from tui_search.engine.maps.scenarios import MAX_SCEN_BYTES, load_scenario
from tui_search.engine.maps.terrain import MAX_TERRAIN_BYTES, load_terrain
from tui_search.engine.traces.posthoc import (
    MAX_POSTHOC_JSON_BYTES,
    MAX_POSTHOC_YAML_BYTES,
    load_posthoc,
)
from tui_search.engine.traces.read import MAX_TRACE_BYTES, load_trace

#: Memory a reader may take beyond ten times the file: its fixed costs (the parser's tables,
#: a small map's grid), which no small file pays back.
ALLOWANCE = 1024 * 1024
#: The size of the files the memory is measured on (or the reader's limit, if smaller).
MEASURED = 1024 * 1024
#: The trace's map: the one examples/student_bfs.jsonl is a trace of.
TRACE_MAP = load_map(MAPS / "exercise2-dfs-longer.txt")


def read_markdown_lesson(path: str) -> object:
    """What ``--lesson FILE`` reads, and what its panel's parser makes of each section."""
    from markdown_it import MarkdownIt

    lesson = read_lesson(Path(path))
    parser = MarkdownIt("gfm-like")
    return [parser.parse(section.text) for section in lesson.sections]


def read_layout(path: str) -> object:
    """What a ``.lay`` file's reader makes of the file (whatever its name here)."""
    return parse_layout(read_text(path), path)


#: A Posthoc trace of the trace map's first steps (examples/student_bfs.jsonl's map), as JSON
#: and YAML (its line 2 has 2 characters or more).
POSTHOC_JSON = ('{"version": "1.4.0",\n "events": [{"type": "source", "id": 0, "x": 1, "y": 1},\n'
                '  {"type": "expanding", "id": 0, "x": 1, "y": 1}]}\n')
POSTHOC_YAML = ("version: 1.4.0\nevents:\n  - {type: source, id: 0, x: 1, y: 1}\n"
                "  - {type: expanding, id: 0, x: 1, y: 1}\n")


class Reader(NamedTuple):
    """A reader of files someone else wrote, and files of its format to read."""

    name: str
    read: Callable[[str], object]  # reads the file named; MapError when it is bad
    limit: int  # the largest file it reads
    sample: str  # a file it reads (its line 2 has 2 characters or more)
    nested: Callable[[int], str]  # a file nested that deep in the format's own way
    #: Files of about this size costing the reader the most memory for their size.
    heavy: tuple[Callable[[int], str], ...]
    #: The most memory it may take, in times the file: ten, but for a Posthoc document,
    #: parsed whole by json and PyYAML (a streaming reader would meet ten; its files are
    #: capped smaller instead: MAX_POSTHOC_YAML_BYTES).
    factor: int = 10
    #: The size its heaviest files are measured at (PyYAML reads a MB in seconds: a quarter
    #: of one tells its ratio as well, the allowance aside).
    measured: int = 1024 * 1024


def one_cell_rows(size: int) -> str:
    return "S\n" + ".\n" * (size // 2 - 2) + "G\n"


def brackets(n: int) -> str:
    return "[" * n + "]" * n


READERS = [
    Reader("text map", load_map, MAX_MAP_BYTES, "S.#\n..G\n", brackets, (
        one_cell_rows,
        lambda n: "S\n" + ".\n; c\n" * (n // 6) + "G\n",  # each row read on its own
        lambda n: "S" + "." * (n - 2) + "G",  # one long line
        lambda n: "; terrain f 5\n" * (n // 14),  # a table in the comments, no rows
    )),
    Reader("MovingAI map", load_map, MAX_MAP_BYTES,
           "type octile\nheight 2\nwidth 3\nmap\n..@\n.T.\n",
           lambda n: "type octile\nheight 1\nwidth 1\nmap\n" + brackets(n), (
               lambda n: f"type octile\nheight {n // 2}\nwidth 1\nmap\n" + ".\n" * (n // 2),
               lambda n: f"type octile\nheight 1\nwidth {n}\nmap\n" + "." * n,
           )),
    Reader("terrain table", load_terrain, MAX_TERRAIN_BYTES, "f 5\nw blocked\n", brackets, (
        lambda n: "".join(f"{chr(0x4E00 + i)} {i % 90 + 1}\n" for i in range(n // 7)),
        lambda n: "\n" * n,
    )),
    Reader("scenario file", lambda p: load_scenario(p, 0), MAX_SCEN_BYTES,
           "version 1\n0\tm.map\t9\t9\t0\t0\t8\t8\t11.3\n", brackets, (
               lambda n: "version 1\n" + "0\tm.map\t9\t9\t0\t0\t8\t8\t11.3\n" * (n // 31),
               lambda n: "version 1\n" + "\n" * n,
           )),
    Reader("graph", load_graph, MAX_GRAPH_BYTES, "edge A B 2\nedge B C\nstart A\ngoal C\n",
           lambda n: "edge " + brackets(n) + " B\n", (
               lambda n: "".join(f"edge a{i} b{i}\n" for i in range(n // 14)),
               lambda n: "".join(f"node n{i} {i} 1\n" for i in range(n // 16)),
               lambda n: "edge A B\n" + "; c\n" * (n // 4),
           )),
    Reader("trace", lambda p: load_trace(p, TRACE_MAP), MAX_TRACE_BYTES,
           (Path(__file__).parents[2] / "examples" / "student_bfs.jsonl").read_text(),
           lambda n: '{"node": ' + brackets(n) + "}\n", (
               lambda n: '{"node":[1,1]}\n' * (n // 15),
               lambda n: '{"node":[1,1],"successors":[' + "[1,1]," * (n // 6 - 6) + "[1,1]]}",
               lambda n: '{"node":[1,1],"x":[' + "[]," * (n // 3 - 8) + "[]]}",
               lambda n: '{"node":[1,1],"x":[' + '"ab",' * (n // 5 - 5) + '"ab"]}',
               lambda n: "\n" * n,
           )),
    Reader("Posthoc JSON trace", lambda p: load_posthoc(p, TRACE_MAP, as_json=True),
           MAX_POSTHOC_JSON_BYTES, POSTHOC_JSON, lambda n: '{"events": ' + brackets(n) + "}\n", (
               lambda n: '{"events": [' + '{"type":"expanding","id":1},' * (n // 28 - 1)
               + '{"type":"end","id":1}]}',
               lambda n: '{"events": [' + "[]," * (n // 3 - 6) + "[]]}",
               lambda n: '{"events": [], "x": [' + '"ab",' * (n // 5 - 6) + '"ab"]}',
           ), factor=20),
    Reader("Posthoc YAML trace", lambda p: load_posthoc(p, TRACE_MAP, as_json=False),
           MAX_POSTHOC_YAML_BYTES, POSTHOC_YAML, lambda n: "events: " + brackets(n) + "\n", (
               lambda n: "events:\n" + "  - {type: expanding, id: 1}\n" * (n // 30),
               lambda n: "events: []\nx:\n" + "  - ab\n" * (n // 7 - 3),
               lambda n: "events:\n  " + "- " * (n // 2 - 8) + "x\n",
           ), factor=100, measured=256 * 1024),
    Reader("exercise file", load_exercise, MAX_EXERCISE_BYTES,
           (Path(__file__).parents[1] / "data" / "exercises" / "greedy-not-optimal.toml")
           .read_text().replace('map = "../../../maps/tutorial.txt"   # relative to this file',
                               'generate = "maze 9x9 1"'),
           lambda n: "hint = " + brackets(n) + "\n", (
               lambda n: "x = [" + "[]," * (n // 3 - 3) + "]\n",
               lambda n: "".join(f"k{i} = 1\n" for i in range(n // 10)),
               lambda n: "x." + ".".join(["a"] * (n // 2 - 6)) + " = 1\n",
           )),
    Reader("Pacman layout", read_layout, MAX_MAP_BYTES, "%%%%\n%P.%\n%%%%\n",
           lambda n: "%P" + brackets(n) + ".\n", (
               lambda n: "P\n" + "%\n" * (n // 2 - 2) + ".\n",  # a row a line
               lambda n: "P" + "." * (n - 1),  # every cell a dot
               lambda n: "%P.%\n" * (n // 5),  # a P on every line: stops at the second
           )),
    Reader("course test", read_course_test, MAX_TEST_BYTES,
           'class: "GraphSearchTest"\nalgorithm: "bfs"\ngraph: """\nstart_state: A\n'
           'goal_states: B\nA 0 B\n"""\n',
           lambda n: 'graph: """\n' + brackets(n) + '\n"""\n', (
               lambda n: 'algorithm: "bfs"\ngraph: """\nstart_state: A\ngoal_states: B\n'
               + "".join(f"a{i} x b{i}\n" for i in range(n // 14)) + '"""\n',
               lambda n: 'algorithm: "bfs"\nlayout: """\nP\n' + "%\n" * (n // 2 - 30)
               + '.\n"""\n',
               lambda n: "#\n" * (n // 2),
           )),
    Reader("lesson", read_markdown_lesson, MAX_LESSON_BYTES,
           "# A lesson\nIts introduction.\n## One\n\nText.\n\n## Two\n\n"
           "```lesson\nalgorithm: dfs\n```\n",
           lambda n: "## One\n\n" + "> " * n + "x\n", (
               lambda n: "## a\n" * (n // 5),
               lambda n: "## One\n" + "\n" * n,
               lambda n: "".join(f"## {i}\n" + "[a](" * 900 + "\n" for i in range(4))
               + "\n" * (n - 15_000),
           )),
]
IDS = [reader.name for reader in READERS]


def error_of(reader: Reader, path: Path) -> MapError:
    """The reader's error for the file at ``path``: one line, naming the file."""
    with pytest.raises(MapError) as caught:
        reader.read(str(path))
    message = str(caught.value)
    assert message.startswith(f"{path}:") and "\n" not in message, message
    return caught.value


def spoiled(reader: Reader, bad: bytes) -> bytes:
    """The reader's sample with ``bad`` at line 2, column 3."""
    first, second, *rest = reader.sample.encode().split(b"\n")
    return b"\n".join([first, second[:2] + bad + second[2:], *rest])


@pytest.mark.parametrize("reader", READERS, ids=IDS)
def test_each_reader_reads_its_sample(tmp_path: Path, reader: Reader) -> None:
    """(So that the cases below put their hostile part into a file the reader reads.)"""
    path = tmp_path / "sample"
    path.write_text(reader.sample)
    assert reader.read(str(path)) is not None


@pytest.mark.parametrize("reader", READERS, ids=IDS)
def test_nesting_200_000_deep_is_one_line(tmp_path: Path, reader: Reader) -> None:
    path = tmp_path / "deep"
    path.write_text(reader.nested(200_000))
    error_of(reader, path)


BILLION_LAUGHS = "\n".join(
    ['a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]']
    + [f"{chr(98 + i)}: &{chr(98 + i)} [{','.join(['*' + chr(97 + i)] * 9)}]"
       for i in range(8)]) + "\n"


@pytest.mark.parametrize("reader", READERS, ids=IDS)
def test_a_yaml_alias_bomb_is_not_expanded(tmp_path: Path, reader: Reader) -> None:
    """A billion "lol"s in nine lines of YAML: no reader here expands an alias (a YAML
    reader must not either): refused in one line, or read as the text it is (a lesson's)."""
    bomb = tmp_path / "bomb"
    bomb.write_text(BILLION_LAUGHS)
    error_of(reader, bomb)
    path = tmp_path / "inside"
    path.write_text(reader.sample + BILLION_LAUGHS)
    assert peak_of(reader, path) <= 10 * len(reader.sample + BILLION_LAUGHS) + ALLOWANCE


@pytest.mark.parametrize("reader", READERS, ids=IDS)
def test_a_line_of_100_mb_is_refused_before_reading(tmp_path: Path, reader: Reader) -> None:
    path = tmp_path / "long"
    with open(path, "wb") as handle:  # (sparse: the line's middle takes no disk)
        handle.write(reader.sample.encode().split(b"\n")[0])
        handle.seek(100 * 1024 * 1024)
        handle.write(b"x\n")
    assert "may be at most" in str(error_of(reader, path))


@pytest.mark.parametrize("reader", READERS, ids=IDS)
def test_a_file_of_1_gb_is_refused_naming_the_limit(tmp_path: Path, reader: Reader) -> None:
    path = tmp_path / "huge"
    with open(path, "wb") as handle:
        handle.truncate(2**30)
    message = str(error_of(reader, path))
    assert message.startswith(f"{path}: file is 1024.0 MB; ") and "may be at most" in message


@pytest.mark.parametrize("reader", READERS, ids=IDS)
def test_a_nul_is_named_at_its_line_and_column(tmp_path: Path, reader: Reader) -> None:
    path = tmp_path / "nul"
    path.write_bytes(spoiled(reader, b"\x00"))
    error = error_of(reader, path)
    assert (error.line, error.col) == (2, 3) and "NUL" in error.message


@pytest.mark.parametrize("reader", READERS, ids=IDS)
@pytest.mark.parametrize("bad", [b"\xff", b"\xc3", b"\xed\xa0\x80"])  # a lone surrogate too
def test_bytes_that_are_not_utf8_are_named_at_their_line_and_column(
        tmp_path: Path, reader: Reader, bad: bytes) -> None:
    path = tmp_path / "latin"
    path.write_bytes(spoiled(reader, bad))
    error = error_of(reader, path)
    assert (error.line, error.col) == (2, 3) and "not UTF-8" in error.message


def peak_of(reader: Reader, path: Path) -> int:
    """The most memory reading the file at ``path`` took (a MapError or not), in bytes: the
    read in a child process, its peak resident size less its size before (tracemalloc would
    make a read of a million lines take minutes).  Where there is no fork, tracemalloc's."""
    if not hasattr(os, "fork") or not Path("/proc/self/statm").exists():
        return traced_peak(reader, path)
    out, into = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: measure, say, and leave at once
        try:
            pages = int(Path("/proc/self/statm").read_text().split()[1])
            before = pages * os.sysconf("SC_PAGESIZE")
            try:
                reader.read(str(path))
            except MapError as err:
                assert "\n" not in str(err)
            peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
            os.write(into, str(peak - before).encode())
        except BaseException as exc:  # noqa: BLE001 - handed to the test
            os.write(into, repr(exc).encode()[:1000])
        finally:
            os._exit(0)
    os.close(into)
    with os.fdopen(out, "rb") as said:
        answer = said.read().decode()
    os.waitpid(pid, 0)
    assert answer.lstrip("-").isdigit(), answer
    return int(answer)


def traced_peak(reader: Reader, path: Path) -> int:
    tracemalloc.start()
    try:
        reader.read(str(path))
    except MapError as err:
        assert "\n" not in str(err)
    finally:
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
    return peak


@pytest.mark.parametrize("reader, heavy", [(r, h) for r in READERS for h in r.heavy],
                         ids=[f"{r.name}-{i}" for r in READERS for i in range(len(r.heavy))])
def test_the_heaviest_files_take_at_most_ten_times_their_size(
        tmp_path: Path, reader: Reader, heavy: Callable[[int], str]) -> None:
    """Files of the format at their most memory-hungry for their size (or nearly at the
    reader's limit, for the small ones), read or refused within ten times their size.  The
    largest (64 MB) are measured in benchmarks/big_map.py."""
    path = tmp_path / "heavy"
    measured = min(reader.measured, reader.limit)
    path.write_text(heavy(measured - 100))
    size = path.stat().st_size
    assert 0.5 * measured < size <= reader.limit
    # the format's modules imported here first: each measure is a fork of this process, so
    # a read in a child (as this test once warmed up) leaves the imports it made behind
    # (they counted when this worker had not imported them: on CI once, 1.31 MB)
    sample = tmp_path / "sample"
    sample.write_text(reader.sample)
    try:
        reader.read(str(sample))
    except MapError:
        pass
    assert peak_of(reader, path) <= reader.factor * size + ALLOWANCE


FUZZ = settings(max_examples=60, deadline=None,
                suppress_health_check=[HealthCheck.function_scoped_fixture])


def reads_or_says_why(reader: Reader, folder: str, data: bytes) -> None:
    path = Path(folder) / "fuzz"
    path.write_bytes(data)
    try:
        reader.read(str(path))
    except MapError as err:
        assert str(err).startswith(f"{path}") and "\n" not in str(err)


@pytest.mark.parametrize("reader", READERS, ids=IDS)
@FUZZ
@given(data=st.binary(max_size=200))
def test_random_bytes_are_read_or_one_line(reader: Reader, data: bytes) -> None:
    with tempfile.TemporaryDirectory() as folder:
        reads_or_says_why(reader, folder, data)


@pytest.mark.parametrize("reader", READERS, ids=IDS)
@FUZZ
@given(data=st.data())
def test_random_text_of_the_format_is_read_or_one_line(reader: Reader, data: st.DataObject
                                                         ) -> None:
    """Random text of the format's own characters, and the sample with random lines put in."""
    alphabet = sorted(set(reader.sample) | set('[]{}"\\\n\r\t .,:=#;é'))
    text = data.draw(st.text(alphabet=alphabet, max_size=200))
    lines = reader.sample.split("\n")
    at = data.draw(st.integers(0, len(lines)))
    with tempfile.TemporaryDirectory() as folder:
        reads_or_says_why(reader, folder, text.encode())
        mixed = "\n".join([*lines[:at], text, *lines[at:]])
        reads_or_says_why(reader, folder, mixed.encode())

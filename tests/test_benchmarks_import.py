"""The benchmark modules import, and their smallest pieces work (nothing here is timed).

The benchmarks run by hand, not in CI, so a split or a rename that breaks one would go unseen
until someone measures; these checks catch that in the test suite, in well under a second or
two: every module imports, the entry point knows its sections and refuses a wrong one, the
trivial Textual app answers its keys, and the press harness counts the lines Textual draws
(it patches a Textual internal, which an upgrade could move).
"""

from __future__ import annotations

import asyncio
import importlib
import json
import pkgutil
from array import array

import pytest

import benchmarks
from benchmarks import bench, choices, core, fallback, graphs, harness, jump, step, terrain
from benchmarks.baselines import (
    bare_bfs,
    bare_dfs,
    bare_dfs_recorded,
    bare_dfs_visit_on_expand_recorded,
    bare_path_len,
    bare_search_visit_on_expand,
    walled_in,
)
from benchmarks.harness import interleaved, paired
from benchmarks.maps import TUTORIAL, open_grid
from benchmarks.table import Row, fmt_ratio, print_table
from benchmarks.trivial_app import Lines, TrivialApp
from tests.helpers import MOVINGAI
from tui_search.engine.maps.load import load_map
from tui_search.engine.maps.scenarios import load_scenario
from tui_search.engine.run.recorded import Run, recording_of
from tui_search.engine.search.choices import Semantics

ARENA_MAP = MOVINGAI / "arena.map"


def test_every_benchmark_module_imports() -> None:
    names = sorted(m.name for m in pkgutil.iter_modules(benchmarks.__path__))
    assert {"bench", "choices", "engine", "jump", "step", "startup", "trivial_app"} <= set(names)
    for name in names:
        importlib.import_module(f"benchmarks.{name}")


def test_the_entry_point_has_its_sections_and_refuses_another(capsys) -> None:
    assert list(bench.SECTIONS) == ["core", "fallback", "engine", "choices", "informed", "jump",
                                    "step", "compare", "startup", "instructions", "class_load",
                                    "terrain", "big_map", "diagnose", "graph",
                                    "weighted", "bidirectional"]
    with pytest.raises(SystemExit) as info:
        bench.main(["--only", "engine,nope"])
    assert info.value.code == 2 and "unknown section 'nope'" in capsys.readouterr().err


def test_the_graph_section_s_floors_and_the_app_find_the_same_cost(tmp_path) -> None:
    """Section graph on a 12x12 grid graph: the floor's Dijkstra, the app's parse and UCS run
    and its command find one cost (untimed)."""
    path = tmp_path / "g.graph"
    graphs.write_grid_graph(path, side=12)
    _, _, _, _, floor_cost = graphs.floors(path)
    _, _, app_cost = graphs.app_in_process(path)
    _, _, output = graphs.app_command(path)
    assert floor_cost == app_cost == json.loads(output)["cost"] > 0


def test_the_fallback_sections_probe_compiles() -> None:
    """The probe each engine runs in a process of its own is Python (untimed, not run)."""
    compile(fallback.PROBE, "probe", "exec")
    assert {key for _, key in fallback.CASES} == {"bfs", "dfs", "astar", "ucs", "edit"}


def test_the_compare_section_drives_compare_mode_to_the_end() -> None:
    """The compare section's ``end`` on the tutorial (untimed): both runs at their ends."""
    from tui_search.tui.app import SearchApp

    _, steps = asyncio.run(jump._jump_once(SearchApp, load_map(TUTORIAL), compare="bfs,dfs"))
    assert steps == [22, 7]


@pytest.mark.parametrize("key", ["bfs", "dfs", "astar", "ucs"])
def test_the_c_floor_takes_the_engines_steps(key: str) -> None:
    """The core section's floor (benchmarks/floor.c) runs the searches the rows time: as many
    steps as the engine records, on the tutorial and on arena under MovingAI's corner rule."""
    scen = load_scenario(MOVINGAI / "arena.map.scen", 3)
    for grid, sem in ((load_map(TUTORIAL), Semantics()),
                      (load_map(ARENA_MAP, start=scen.start, goal=scen.goal), core.NEVER)):
        for g in (grid, walled_in(grid)) if key == "dfs" else (grid,):
            assert core.floor_search(g, key, sem)() == core.recorded(g, key, sem).recorded


@pytest.mark.parametrize("key", ["astar", "ucs"])
def test_the_c_floor_weighs_terrain_as_the_engine_does(key: str) -> None:
    """The terrain section's floor row: with random costs 1-9 (and with costs from 0.5, so
    the heuristic is scaled by the lowest), the floor takes as many steps as the engine (arena's
    row 60: some 2,000 steps, which terrain changes)."""
    scen = load_scenario(MOVINGAI / "arena.map.scen", 60)
    for grid, sem in ((load_map(TUTORIAL), Semantics()),
                      (load_map(ARENA_MAP, start=scen.start, goal=scen.goal), core.NEVER)):
        costed = terrain.with_random_costs(grid)
        halved = costed.copy()
        assert costed.costs is not None
        halved.costs = array("d", (c / 2 for c in costed.costs))
        for g in (costed, halved):
            assert core.floor_search(g, key, sem)() == core.recorded(g, key, sem).recorded


def test_the_bare_baselines_find_the_engines_path_lengths() -> None:
    grid = load_map(TUTORIAL)
    for algorithm, bare in (("bfs", bare_bfs), ("dfs", bare_dfs)):
        run = Run(grid, algorithm)
        run.advance()
        assert bare_path_len(grid, bare(grid)) == len(run.path()) - 1 == 7


def test_the_visit_on_expand_floor_finds_the_engines_paths_and_pushes_more() -> None:
    grid = load_map(TUTORIAL)
    for algorithm, lifo in (("bfs", False), ("dfs", True)):
        run = Run(grid, algorithm, Semantics(visit="expand"))
        run.advance()
        parent = bare_search_visit_on_expand(grid, lifo)
        assert bare_path_len(grid, parent) == len(run.path()) - 1
        nodes = list(recording_of(run).rec.gen_node)
        assert len(nodes) > len(set(nodes))  # what the floor stands for: cells pushed again


def test_the_recorded_floors_record_what_the_engine_records() -> None:
    """The floors of the recorded DFS rows keep the same arrays as the engine's record, on
    maps where the goal is found and walled in (a full traversal), and on a start that is
    the goal (default choices; visit on expand has another layout there)."""
    tutorial, arena = load_map(TUTORIAL), load_map(ARENA_MAP)
    scen = load_scenario(ARENA_MAP.with_suffix(".map.scen"), 60)
    arena.start, arena.goal = scen.start, scen.goal
    maps = [tutorial, open_grid(40), arena]
    maps += [walled_in(g) for g in maps]
    same = tutorial.copy()
    same.goal = same.start
    for grid in maps + [same]:
        for floor, sem in ((bare_dfs_recorded, Semantics()),
                           (bare_dfs_visit_on_expand_recorded, Semantics(visit="expand"))):
            if grid is same and sem.visit == "expand":
                continue
            run = Run(grid, "dfs", sem)
            run.advance()
            rec, bare = recording_of(run).rec, floor(grid)
            assert (bare.gen_node, bare.step_end, bare.step_exp, bare.discarded,
                    bare.goal_gen) == (rec.gen_node, rec.step_end, rec.step_exp,
                                       rec.discarded, rec.goal_gen)
    assert len(bare_dfs_visit_on_expand_recorded(walled_in(arena)).discarded) > 0


def test_walled_in_leaves_no_path_and_the_full_traversal_reaches_every_cell() -> None:
    grid = load_map(TUTORIAL)
    walled = walled_in(grid)
    assert walled.goal == grid.goal and walled.is_free(walled.goal)
    for bare in (bare_bfs, bare_dfs):
        assert bare_path_len(walled, bare(walled)) == -1
    run = Run(walled, "dfs")
    run.advance()
    events = len(recording_of(run).rec.gen_node)
    assert not run.found and events == walled.free_count() - 1  # not the goal


def test_the_choices_section_times_every_combination_on_both_frontiers() -> None:
    """Each contender runs once on the tutorial map (untimed): the rows' callables work."""
    grid = load_map(TUTORIAL)
    fns = choices.contenders(grid, walled_in(grid))
    assert {f"run {a} {c}{w}" for a, w in (("bfs", ""), ("dfs", " walled"))
            for c in choices.COMBINATIONS} <= set(fns)
    for fn in fns.values():
        fn()
    choices.check_answers("tutorial", grid, walled_in(grid))


def test_the_harness_and_the_table(capsys, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(harness.gc, "collect", lambda: 0)  # ~0.1 s a call, and not tested here
    samples = interleaved({"a": lambda: None, "b": lambda: sum(range(10))}, repeats=2)
    assert [len(xs) for xs in samples.values()] == [2, 2]
    assert paired([2.0, 4.0], [1.0, 1.0]) == 3.0 and fmt_ratio(0.0712) == "0.071"
    print_table([Row("engine", "what", "1 ms", "base", 0.5, "≤ 1", True)])
    out = capsys.readouterr().out
    assert "what" in out and "pass" in out
    assert out.rstrip().endswith("1 pass, 0 fail, 0 reported only")
    below = Row("choices", "slow", "2 s", "base", 3.5, "≤ 3", False, floor=3.2)
    assert below.verdict == "FAIL, target below the floor (3.20)"
    assert Row("choices", "slow", "2 s", "base", 3.5, "≤ 3", False, floor=2.0).verdict == "FAIL"
    print_table([below])
    assert "1 fail (1 with the target below its floor)" in capsys.readouterr().out


def test_the_trivial_app_answers_n_and_p() -> None:
    async def press() -> str:
        app = TrivialApp()
        async with app.run_test(size=(40, 10)) as pilot:
            await pilot.press("n", "n", "p", "n")
            return app.query_one(Lines).render_line(5).text

    assert asyncio.run(press()).rstrip() == "line 5: pressed 2 times"


def test_the_press_harness_counts_the_lines_each_press_draws() -> None:
    """A key that refreshes one line draws one line afresh; ``f`` with ``first=7``, seven."""
    for app, key, lines in ((TrivialApp(), "n", 1), (TrivialApp(7), "f", 7)):
        walls, _, _, drawn = asyncio.run(step._presses(app, [key] * 3, warmup=1))
        assert len(walls) == 3 and drawn == lines


def test_the_bare_heapq_searches_find_the_engines_cheapest_costs() -> None:
    """The informed section's floor: the bare A* and Dijkstra find what the recorded runs
    find, under no corner cutting."""
    from benchmarks.informed import NEVER, bare_best_first

    grid = load_map(ARENA_MAP)
    for row in (5, 60, 129):
        scen = load_scenario(ARENA_MAP.with_suffix(".map.scen"), row)
        grid.start, grid.goal = scen.start, scen.goal
        for key, astar in (("astar", True), ("ucs", False)):
            cost = Run(grid, key, NEVER).outcome().cost
            assert abs(bare_best_first(grid, astar) - cost) < 1e-9
            assert abs(cost - scen.optimal_length) < 1e-4 * cost


def test_the_optima_command_checks_rows_and_counts_them(capsys) -> None:
    from benchmarks import optima

    code = optima.main(["--maps", str(ARENA_MAP.parent), "--only", "arena", "--every", "40",
                        "--jobs", "1", "--searches", "ucs,astar:octile"])
    out = capsys.readouterr().out
    assert code == 0
    assert "arena.map.scen: 4 of 130 rows x 2 searches: 8 optimal, 0 missed" in out


def test_the_optima_command_resumes_from_its_log(tmp_path, capsys) -> None:
    """With --log, a second run checks only the rows the first did not (a killed run's batches
    are kept), and counts them all; a log of other searches is not taken for these."""
    from benchmarks import optima

    log = tmp_path / "optima.jsonl"
    common = ["--maps", str(ARENA_MAP.parent), "--only", "arena", "--jobs", "1",
              "--searches", "ucs", "--log", str(log)]
    assert optima.main(common + ["--every", "65"]) == 0  # rows 0 and 65
    capsys.readouterr()
    lines = log.read_text().splitlines()
    assert [json.loads(line)["rows"] for line in lines] == [[0, 65]]
    log.write_text(log.read_text() + '{"scen": "arena.map.scen", "rows": [1')  # cut by a kill
    assert optima.main(common + ["--every", "13"]) == 0  # 10 rows: 0 and 65 from the log
    out = capsys.readouterr().out
    assert "10 of 130 rows x 1 searches: 10 optimal, 0 missed" in out
    assert "2 rows from the log" in out
    entries = [json.loads(line) for line in log.read_text().splitlines()[2:]]
    assert sorted(r for e in entries for r in e["rows"]) == [13, 26, 39, 52, 78, 91, 104, 117]
    assert optima.main(common[:-3] + ["astar:zero", "--log", str(log), "--every", "65"]) == 0
    assert "2 rows from the log" not in capsys.readouterr().out


def test_the_class_load_floor_is_measured_on_the_fork_server() -> None:
    """class_load's floor (untimed): apps forked, one alone then two together, each one's CPU
    to its first frame read."""
    from benchmarks.class_load import floor_cpu

    (cpu,) = floor_cpu(1)
    assert 0 < cpu < 60
    together = floor_cpu(1, at_once=2)
    assert len(together) == 2 and all(0 < c < 60 for c in together)


def test_the_startup_floors_count_the_screens_widgets() -> None:
    """The start-up floors are the trivial app with as many bordered widgets as the app's first
    screen (counted, not written down: the count follows the app), and that app starts."""
    from benchmarks.startup import screen_widgets

    one = screen_widgets([str(TUTORIAL)])
    two = screen_widgets([str(TUTORIAL), "--compare", "bfs,dfs"])
    assert 1 < one < two  # a second pane adds its widgets

    async def count() -> int:
        app = TrivialApp(widgets=one)
        async with app.run_test() as pilot:
            await pilot.pause()
            return len(app.query(Lines))

    assert asyncio.run(count()) == one


def test_the_big_map_section_s_readers_and_app_run_on_small_files(tmp_path) -> None:
    """Each reader's script of the big_map section on its heaviest file of 2 KB, and the app's
    first frame on the tutorial (untimed): each runs to its end."""
    import subprocess
    import sys
    from pathlib import Path

    from benchmarks import big_map

    root = Path(__file__).resolve().parents[1]
    for name, imports, call, _, heaviest in big_map.READERS:
        path = tmp_path / "heavy"
        path.write_text(heaviest(2000))
        script = big_map._READ_WITH.format(imports=imports, call=call)
        done = subprocess.run([sys.executable, "-c", script, str(path)], cwd=root,
                              capture_output=True, text=True, timeout=60)
        assert done.returncode == 0 and done.stderr == "", (name, done.stderr)
    done = subprocess.run([sys.executable, "-c", big_map._APP_FRAME, str(TUTORIAL)], cwd=root,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr


def test_the_diagnose_section_s_traces_are_each_diagnosed_as_the_search_they_are() -> None:
    """Section diagnose times the diagnosis of the app's own traces under students' choices
    (its 6x6 rows): each is matched all through, so the time is of a diagnosis that finds it."""
    from benchmarks import diagnose as section
    from tui_search.engine.maps.load import parse_map_text
    from tui_search.engine.traces.diagnose import diagnose

    grid = parse_map_text("\n".join(section.ROWS) + "\n", "6x6")
    for what, key, sem, nodes_only in section.SMALL:
        trace = section.app_trace(grid, key, sem, nodes_only)
        assert all(t.listed != nodes_only for t in trace.steps), what
        assert diagnose(trace, grid).matches, what

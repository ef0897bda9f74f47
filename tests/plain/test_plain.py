"""Plain mode (``--plain``): a command a line in, plain sentences out, on the app's session.

The scripted session is the issue's test: BFS on the tutorial's map, ``n`` four times, gives
the tutorial's own narration word for word.  The rest drive the mode in-process, line by line,
and read what it says: the map in words, the cursor, edits, the quiz, the exercises, the
settings, saving, and quitting without losing edits.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.export.test_exports import TUTORIAL_WORDS
from tests.helpers import ROOT, TUTORIAL
from tui_search.engine.maps.load import load_map
from tui_search.plain.commands import COMMANDS
from tui_search.plain.mode import run_plain
from tui_search.tui.model.session import Session

#: The tutorial's words for the start: "We begin with the START node and add it to the queue."
START_WORDS = "We begin with the START node and add it to the queue."


def plain(*lines: str, path: Path = TUTORIAL, **session: object) -> list[str]:
    """What plain mode says to ``lines`` on the map at ``path`` (a Session's keywords)."""
    said: list[str] = []
    assert run_plain(Session(load_map(path), path, **session), list(lines), said.append) == 0
    return said


def test_a_scripted_session_tells_bfs_in_the_tutorial_s_own_words() -> None:
    out = subprocess.run([sys.executable, "-m", "tui_search", str(TUTORIAL), "--plain"],
                         input="n\nn\nn\nn\nq\n", capture_output=True, text=True, timeout=300,
                         check=False, cwd=ROOT)
    assert (out.returncode, out.stderr) == (0, "")
    steps = [line for line in out.stdout.splitlines() if line.startswith("Step ")]
    assert steps == [f"Step 0: {START_WORDS}",
                     *(f"Step {k}: {words}" for k, words in enumerate(TUTORIAL_WORDS, 1))]
    assert "New in the tree: (1,2) to (2,2) by E, (1,2) to (2,1) by NE." in out.stdout
    assert "Queue, front first: (0,3), (1,3), (2,2), (2,1)." in out.stdout


def test_plain_mode_imports_no_textual_nor_rich_beyond_its_cell_widths() -> None:
    probe = ("import sys\nfrom tui_search.cli.main import main\n"
             "main([sys.argv[1], '--plain'])\n"
             "print(sorted(m for m in sys.modules if m.split('.')[0] in ('textual', 'rich') "
             "and not m.startswith(('rich.cells', 'rich._'))) or None)\n")
    out = subprocess.run([sys.executable, "-c", probe, str(TUTORIAL)], input="q\n",
                         capture_output=True, text=True, timeout=300, check=False, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines()[-1] == "['rich']"  # the package, for rich.cells only


def test_it_starts_by_saying_where_it_is_and_how_to_go_on() -> None:
    said = plain()
    assert said[0] == ("tui-search, plain mode: BFS on tutorial.txt, a map 6 wide and 6 high. "
                       "The cursor is on (0,0). Type a command and press enter: n for the "
                       "next step, help for every command, q to quit.")
    assert said[1:] == [f"Step 0: {START_WORDS}", "Queue, front first: (0,0)."]


def test_the_map_a_row_a_column_a_cell_and_around_in_words() -> None:
    said = plain("n 4", "row 2", "column 1", "cell 1,2", "cell 9,9", "around", "map")
    assert "Row 2: expanded, being expanded, on the queue, obstacle, obstacle, goal." in said
    assert "Column 1: obstacle, obstacle, being expanded, on the queue, free, free." in said
    assert "(1,2): being expanded (step 4), depth 2, reached by SE from (0,1)." in said
    assert "(9,9) is off the map." in said
    assert ("Around (0,0), start (cursor): N (0,-1) off the map, NE (1,-1) off the map, E (1,0) "
            "obstacle, SE (1,1) obstacle, S (0,1) expanded, SW (-1,1) off the map, W (-1,0) "
            "off the map, NW (-1,-1) off the map.") in [s.replace("start:", "start (cursor):")
                                                         for s in said]
    head = next(s for s in said if s.startswith("Map tutorial.txt"))
    assert head == ("Map tutorial.txt: 6 columns by 6 rows, x from 0 at the left, y from 0 at "
                    "the top; start (0,0), goal (5,2); 11 obstacles; the cursor on (0,0).")
    assert "Row 5: 6 free." in said  # a run of cells alike, said once


def test_stepping_back_to_the_start_and_to_the_end() -> None:
    said = plain("p", "end", "n", "home")
    assert said[3] == "Already at step 0."
    assert "Step 22: Goal (5,2) found from (5,1)." in said
    assert ("Path: 7 moves, cost 8.66, from (0,0) to (5,2): S, SE, NE, NE, E, SE, S. Expanded "
            "22, generated 24, the largest queue 8.") in said
    assert "Already at the last step: home or p goes back." in said
    assert said[-2:] == [f"Step 0: {START_WORDS}", "Queue, front first: (0,0)."]


def test_the_cursor_moves_and_an_edit_starts_the_searches_again() -> None:
    said = plain("l", "right", "j", "o", "up", "up", "undo", "q", "q")
    assert said[3:5] == ["(1,0): obstacle.", "(2,0): never reached."]
    assert "(2,1): never reached." in said
    assert "An obstacle at (2,1). The searches start again from step 0." in said
    assert "(2,-1) is off the map: the cursor stays on (2,0)." in said
    assert "Undone. The searches start again from step 0." in said
    assert said[-1] == "Queue, front first: (0,0)."  # undone: nothing to save, q leaves


def test_quitting_with_unsaved_edits_asks_first() -> None:
    said = plain("go 2,0", "o", "q", "n", "q", "q")
    asked = ("The map has unsaved edits: save (or save as FILE) keeps them; q again leaves "
             "without saving.")
    assert said.count(asked) == 2  # another command between: asked again


def test_the_quiz_asks_and_keeps_the_score() -> None:
    said = plain("i", "answer 0,0", "answer 0,2", "i")
    assert ("Quiz on: which node comes off the queue next? Type answer X,Y (answer alone: the "
            "cursor's cell). i ends the quiz.") in said
    assert "Queue, in cell order (the quiz hides which comes next): (0,0)." in said
    assert "Right: (0,0) came off next. Score 1 of 1." in said
    assert "Not quite: you said (0,2): (0,1) came off next. Score 1 of 2." in said
    assert said[-1] == "Quiz off."


def test_the_exercises_are_checked_again_after_each_edit() -> None:
    said = plain("x", "go 0,5", "g")
    assert said[3].startswith("Exercise 1: Change the location of the target")
    assert said[4] == "Not solved yet: BFS expanded 22 nodes, DFS 7; both paths have 7 moves."
    assert "Goal at (0,5). The searches start again from step 0." in said
    assert "Solved: BFS expanded 9 nodes, DFS 18; BFS's path has 5 moves, DFS's 8." in said


def test_the_searches_and_compare_as_the_keys_choose_them() -> None:
    said = plain("2", "c", "end")
    assert "Now DFS on tutorial.txt, from step 0." in said
    assert f"Step 0: {START_WORDS.replace('queue', 'stack')}" in said
    assert "Now DFS and BFS on tutorial.txt, from step 0." in said or (
        "Now BFS and DFS on tutorial.txt, from step 0." in said)
    assert any(s.startswith("BFS step 22: ") for s in said)
    assert any(s.startswith("DFS step 7: ") for s in said)


def test_a_compared_search_that_ended_says_so() -> None:
    said = plain("n 8", compare="bfs,dfs")
    assert "DFS is done at step 7." in said and "BFS step 8: " in "\n".join(said)


def test_the_settings_said_and_set() -> None:
    said = plain(",", "set order N,W,S,E", "set order N,Q", "set corners sideways",
                 "set tree-search on", "set visit expand", "set compare bfs,ucs",
                 "set colour red")
    assert said[3] == "Settings (the tutorial's):"
    assert "order N,NW,W,SW,S,SE,E,NE: the moves tried from a cell, in the order their " \
           "successors are added." in said
    assert "order is now N,W,S,E: the searches start again from step 0." in said
    assert "Not changed: unknown direction 'Q' (use N, NE, E, SE, S, SW, W, NW)." in said
    assert "Not changed: corners 'sideways': use always, one, never." in said
    assert ("Not changed: tree search has no visited set: set tree-search off first."
            in said)
    assert "c now compares bfs,ucs." in said
    assert "No setting 'colour': set takes order, corners, visit, goal-test, tree-search, " \
           "heuristic, compare." in said


def test_the_visit_rule_is_refused_where_it_does_not_apply() -> None:
    said = plain("set visit expand", algorithm="astar")
    assert said[-1] == "Not changed: the visit rule does not apply to A*."


def test_save_as_writes_a_new_file_and_never_replaces_one(tmp_path: Path) -> None:
    mine = tmp_path / "mine.txt"
    mine.write_text("x")
    new = tmp_path / "new.txt"
    said = plain("go 2,0", "o", f"save as {mine}", f"save as {new}", "q")
    assert f"{mine} exists: save as another name (plain mode never replaces a file but the " \
           "map's own)." in said
    assert f"Saved {new}." in said and mine.read_text() == "x"
    assert load_map(new).is_blocked((2, 0))
    assert said[-1] == f"Saved {new}."  # saved: q leaves at once


def test_save_writes_the_map_s_own_file_changing_only_the_cell_edited(tmp_path: Path) -> None:
    own = tmp_path / "tutorial.txt"
    shutil.copy(TUTORIAL, own)
    before = own.read_text().splitlines()
    plain("go 2,0", "o", "save", path=own)
    after = own.read_text().splitlines()
    changed = [(a, b) for a, b in zip(before, after, strict=True) if a != b]
    assert changed == [("S#...#", "S##..#")]


def test_a_map_with_no_file_asks_for_a_name() -> None:
    said: list[str] = []
    run_plain(Session(load_map(TUTORIAL), None), ["save"], said.append)
    assert said[-1] == "The map has no file yet: save as FILE names one."


@pytest.mark.parametrize(("line", "reply"), [
    ("xyzzy", "Unknown command 'xyzzy': help lists them."),
    ("t", "Themes are colours: plain mode has none."),
    ("n two", "'two' is not a number of steps."),
    ("row x", "row takes a number, counted from 0."),
    ("go 1", "expected a cell as X,Y (column,row counted from 0), got '1'."),
    ("answer", "The quiz is off: i starts it."),
    ("exercise 7", "exercise takes 1, 2 or off (x cycles them)."),
])
def test_a_line_it_cannot_do_is_one_line_saying_why(line: str, reply: str) -> None:
    assert plain(line)[-1] == reply


def test_help_lists_every_command() -> None:
    said = plain("help")
    assert said[3] == "Commands, one a line (then press enter):"
    assert said[4:] == [f"{c.usage}: {c.says}." for c in COMMANDS]


def test_the_tree_the_frontier_the_code_and_the_status() -> None:
    said = "\n".join(plain("n 4", "tree", "frontier", "v", "status"))
    assert "Search tree, 8 nodes:\nSTART (0,0), expanded, 1 child\n  S (0,1), expanded, 2 " \
           "children\n    S (0,2), expanded, 2 children" in said
    assert "      SE (1,2), being expanded, 2 children" not in said  # its depth is 2
    assert "    SE (1,2), being expanded, 2 children" in said
    assert "Line 5, ran:   node ← take off the front of the queue (pop front)" in said
    assert "Line 11:     goal test: if s is the goal, return its path" in said
    assert "step 4/22, expanded 4, generated 8, queue 4 (peak 4)." in said


def test_the_terrain_brush_paints_the_cursor_s_cell() -> None:
    said = plain("b 7", "b 5", "go 2,0", "m", "cell")
    assert said[3] == "brush takes a cost (2, 3, 5, 9, 1: 1 is plain floor) or off."
    assert "Terrain brush: cost 5 (m paints it at the cursor)." in said
    assert "Painted (2,0). The searches start again from step 0." in said
    assert said[-2:] == ["(2,0) costs 5: never reached.",
                         "The input ended: the map's unsaved edits are not saved."]


def test_open_and_generate_another_map_asking_first_with_unsaved_edits() -> None:
    other = "maps/exercise2-dfs-longer.txt"
    said = plain("go 2,0", "o", f"open {other}", f"open {other}", "generate maze 11x7 3",
                 "generate maze 11x7 3")
    assert ("The map has unsaved edits: save (or save as FILE) keeps them; open again opens "
            "the other map without saving.") in said
    assert any(s.startswith("tui-search, plain mode: BFS on exercise2-dfs-longer.txt, a map")
               for s in said)
    assert said[-3].startswith("tui-search, plain mode: BFS on maze") and "11 wide and 7 high" \
        in said[-3]
    assert plain("open maps/nowhere.txt")[-1].startswith("Not opened: maps/nowhere.txt")
    assert plain("generate blob")[-1].startswith("Not generated: ")

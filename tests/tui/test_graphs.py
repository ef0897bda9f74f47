"""Graphs in the app (issue 37), driven by Pilot: Romania opens and A* finds the book's route,
the cursor goes node to node, s/g/o edit the graph with undo, compare mode on a teaching
graph, the settings a graph has, and a 100,000-node graph that answers keys while ``end``
runs."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import Input, RadioSet

from tests.tui.graph_app import grid_graph
from tests.tui.test_app import settle, sync, wait_until
from tui_search.engine.maps.graph import Graph
from tui_search.engine.maps.graph_file import built_in_graph, load_graph
from tui_search.engine.run.recorded import Run
from tui_search.engine.search.state import State
from tui_search.tui.app import SearchApp
from tui_search.tui.widgets.graph_view import GraphView
from tui_search.tui.widgets.stats import Stats

GRAPHS = Path(__file__).resolve().parents[2] / "maps" / "graphs"
DFS_BACKTRACKS = GRAPHS / "dfs-backtracks.graph"
SIZE = (120, 40)


def graph_app(graph: Graph | None = None, **kwargs: object) -> SearchApp:
    """The app on ``graph`` (Romania by default), as ``tui-search romania`` opens it."""
    return SearchApp(graph or built_in_graph("romania"), **kwargs)  # type: ignore[arg-type]


def status_text(app: SearchApp) -> str:
    """The status lines under the panes: the counts and the narration (the result in it)."""
    stats = app.query_one("#stats", Stats)
    return f"{stats.status_text} {stats.narration_text}"


def view_of(app: SearchApp) -> GraphView:
    return app.query_one(GraphView)


@sync
async def test_romania_opens_as_a_graph_with_its_cities_and_the_start_under_the_cursor() -> None:
    app = graph_app()
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        view = view_of(app)
        assert app.session.graph is not None and app.session.cursor == "Arad"
        assert view.graph.names[view.cursor] == "Arad"
        assert view.has_focus
        drawn = "\n".join(view.render_line(y).text for y in range(view.size.height))
        for city in ("Arad", "Bucharest", "Sibiu", "Fagaras", "Giurgiu"):
            assert city in drawn
        assert "romania.graph" in view.border_title


@sync
async def test_a_star_stepped_to_the_end_shows_the_books_route_at_418() -> None:
    app = graph_app(algorithm="astar")
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        run = app.session.run
        assert run is not None
        while not run.at_end:
            await pilot.press("n")
        await wait_until(pilot, lambda: "418" in status_text(app))
        status = status_text(app)
        assert "Arad → Sibiu → Rimnicu → Pitesti → Bucharest, cost 418" in status
        assert run.path() == ["Arad", "Sibiu", "Rimnicu", "Pitesti", "Bucharest"]
        view = view_of(app)
        names = view.graph.index
        assert int(run.now.cell_state("Pitesti")) == view.code_of(names["Pitesti"])


@sync
async def test_arrows_go_to_the_nearest_node_that_way_and_tab_to_the_next() -> None:
    app = graph_app()
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        await pilot.press("right")  # from Arad, east: Sibiu (Zerind is north, Timisoara south)
        await wait_until(pilot, lambda: app.session.cursor == "Sibiu")
        await pilot.press("down")  # from Sibiu, south: Rimnicu
        await wait_until(pilot, lambda: app.session.cursor == "Rimnicu")
        await pilot.press("tab")  # the next node by number
        graph = app.session.graph
        assert graph is not None
        following = graph.names[(graph.index["Rimnicu"] + 1) % len(graph)]
        await wait_until(pilot, lambda: app.session.cursor == following)


@sync
async def test_a_click_on_a_node_puts_the_cursor_there() -> None:
    app = graph_app()
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        await settle(pilot)
        view = view_of(app)
        x, y = view.screen_offset(view.graph.index["Craiova"])
        region = view.content_region
        await pilot.click(offset=(region.x + x, region.y + y))
        await wait_until(pilot, lambda: app.session.cursor == "Craiova")


@sync
async def test_s_g_and_o_edit_the_graph_and_ctrl_z_undoes_them() -> None:
    app = graph_app(algorithm="ucs")
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        graph = app.session.graph
        assert graph is not None
        await pilot.press("right")  # Sibiu
        await wait_until(pilot, lambda: app.session.cursor == "Sibiu")
        await pilot.press("o")  # Sibiu closed: the roads round it
        await wait_until(pilot, lambda: "Sibiu" in graph.closed)
        run = app.session.run
        assert run is not None
        run.goto(10_000)
        assert "Sibiu" not in (run.path() or [])
        assert run.path_cost() > 418
        assert "modified" in view_of(app).border_title
        await pilot.press("s")  # the start on a closed node: refused
        assert graph.start == "Arad"
        await pilot.press("o")  # open again
        await wait_until(pilot, lambda: "Sibiu" not in graph.closed)
        await pilot.press("s")  # Sibiu the start
        await wait_until(pilot, lambda: graph.start == "Sibiu")
        await pilot.press("left")  # Arad
        await wait_until(pilot, lambda: app.session.cursor == "Arad")
        await pilot.press("g")  # Arad the goal
        await wait_until(pilot, lambda: graph.goals == ("Arad",))
        run = app.session.run
        assert run is not None and run.board.start == "Sibiu"
        run.goto(10_000)
        assert run.path() == ["Sibiu", "Arad"]
        for _ in range(4):  # goal, start, open, close: undone, newest first
            await pilot.press("ctrl+z")
        await wait_until(pilot, lambda: (graph.start, graph.goals, graph.closed)
                         == ("Arad", ("Bucharest",), frozenset()))
        assert "modified" not in view_of(app).border_title
        await pilot.press("ctrl+y")  # Sibiu closed again
        await wait_until(pilot, lambda: graph.closed == {"Sibiu"})
        assert app.session.cursor == "Sibiu"


@sync
async def test_compare_bfs_and_dfs_on_the_teaching_graph_in_lockstep() -> None:
    """dfs-backtracks: BFS expands S and B and finds G; DFS goes down A (E, then C and D
    behind it) before it backs up to B, whose road leads to G."""
    app = graph_app(load_graph(DFS_BACKTRACKS), path=DFS_BACKTRACKS, compare="bfs,dfs")
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: len(app.query(GraphView)) == 2)
        await pilot.press("end")
        await wait_until(pilot, app.session.at_end)
        bfs, dfs = app.session.runs
        assert bfs.path() == ["S", "B", "G"]
        assert dfs.path() == ["S", "B", "G"]
        def expanded(run: Run) -> list[State]:
            return [run.nodes.cell(run.steps.expanded_event(k)) for k in range(1, run.k + 1)]

        assert expanded(bfs) == ["S", "B"]
        assert expanded(dfs) == ["S", "A", "E", "C", "D", "B"]
        assert "BFS" in app.main.panes[0].label and "DFS" in app.main.panes[1].label
        for view in app.query(GraphView):  # both panes draw the path
            assert view.code_of(view.graph.index["G"]) != 0


@sync
async def test_the_settings_of_a_graph_offer_its_orders_and_estimates_not_moves() -> None:
    app = graph_app(algorithm="astar")
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        await pilot.press("comma")
        await wait_until(pilot, lambda: len(app.screen.query("#heuristic")) == 1)
        screen = app.screen
        # no moves to type (the one input is A*'s weight) and no corners
        assert [i.id for i in screen.query(Input)] == ["weight"] and not screen.query("#corners")
        order = screen.query_one("#order", RadioSet)
        assert [b.id for b in order.query("PickButton")] == ["order-file", "order-name"]
        heuristic = screen.query_one("#heuristic", RadioSet)
        assert [b.id for b in heuristic.query("PickButton")] == [
            "heuristic-table", "heuristic-euclidean", "heuristic-zero"]
        await pilot.click("#order-name")
        await pilot.click("#heuristic-zero")
        await pilot.click("#apply")
        await wait_until(pilot, lambda: app.screen is app.main)
        semantics = app.session.semantics
        assert semantics.order == ("name",) and semantics.heuristic == "zero"
        run = app.session.run
        assert run is not None
        run.goto(10_000)
        assert run.path_cost() == 418  # A* with h = 0 is UCS: still the cheapest


@sync
async def test_a_hundred_thousand_nodes_draw_as_points_and_answer_keys_while_end_runs() -> None:
    graph = grid_graph(316)
    app = graph_app(graph, algorithm="bfs")  # (recorded by the reference loop: not instant)
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        view = view_of(app)
        assert view.canvas is not None and view.canvas.overview
        assert any("\u2800" < ch <= "\u28ff" for y in range(5, 30)
                   for ch in view.render_line(y).text)
        handled: list[bool] = []  # was the end still being computed when "+" was handled?
        faster = app.main.action_faster

        def noted_faster() -> None:
            handled.append(app.session.seeking)
            faster()

        app.main.action_faster = noted_faster  # type: ignore[method-assign]
        speed = app.session.speed_index
        # ``end``'s action called, not pressed: a press returns once the app looks idle, and
        # the app is busy until the end is reached (in slices, keys answered in between)
        app.main.action_last()
        assert app.session.seeking
        await pilot.press("plus")  # a key while the end is computed: handled then
        await wait_until(pilot, lambda: app.session.speed_index == speed + 1)
        assert handled == [True]
        await wait_until(pilot, app.session.at_end, seconds=300)
        run = app.session.run
        assert run is not None and run.found
        assert run.path_cost() == 2 * 315


@sync
async def test_the_quiz_on_a_graph_asks_and_answers_in_node_names() -> None:
    app = graph_app(algorithm="astar")
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        await pilot.press("i")
        await wait_until(pilot, lambda: app.session.quiz.on)
        assert "which node comes off the priority queue next" in app.session.note
        await pilot.press("enter")  # the cursor on Arad: the start comes off first
        await wait_until(pilot, lambda: app.session.quiz.asked == 1)
        assert app.session.note.startswith("Right: Arad was")
        await pilot.press("up")  # Zerind (Sibiu is next: f 393)
        await wait_until(pilot, lambda: app.session.cursor == "Zerind")
        await pilot.press("enter")
        await wait_until(pilot, lambda: app.session.quiz.asked == 2)
        assert app.session.note.startswith("Not quite: Sibiu came off")
        assert "not Zerind" in app.session.note


@sync
async def test_the_code_panel_help_and_every_theme_show_a_graph() -> None:
    """v shows the pseudocode of a step on a graph; ? lists the graph's marks in its legend;
    each theme (the colour-blind one too) fills the start, goal, frontier, expanded, current
    and path chips in colours of their own."""
    from tui_search.tui.view.cell_codes import COMPONENTS
    from tui_search.tui.view.themes import THEMES

    app = graph_app(algorithm="astar")
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        await pilot.press("n", "n", "v")
        await wait_until(pilot, lambda: any(p.code_shown for p in app.main.panes))
        await pilot.press("question_mark")
        await wait_until(pilot, lambda: app.screen is not app.main)
        legend = " ".join(str(line) for line in app.screen.query_one("Legend").render().split())
        assert "closed" in legend and "frontier" in legend
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is app.main)
        for theme in THEMES:
            app.theme = theme
            await settle(pilot)
            looks = view_of(app).looks()
            fills = {name: looks.chip[code].bgcolor
                     for code, name in enumerate(COMPONENTS) if name not in ("free", "wall")}
            assert len(set(fills.values())) == len(fills), (theme, fills)


@sync
async def test_brackets_zoom_the_graph_and_z_shows_all_of_it() -> None:
    app = graph_app()
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        view = view_of(app)
        whole = view.virtual_size
        await pilot.press("right_square_bracket")
        await wait_until(pilot, lambda: view.level == 1)
        assert view.virtual_size.width > whole.width and not view.whole
        assert "part of the graph" in view.border_subtitle
        await pilot.press("z")
        await wait_until(pilot, lambda: view.level == 0)
        assert view.whole and view.virtual_size == whole


@sync
async def test_an_exercise_on_a_graph_is_solved_by_closing_a_city() -> None:
    """``--exercise`` with a graph file: the app opens on its graph; closing Fagaras (o)
    makes greedy's road A*'s, and the challenge panel says solved."""
    from tui_search.cli.main import build_app
    from tui_search.cli.parse import parse_options
    from tui_search.tui.widgets.challenge import ChallengePanel

    exercise = Path(__file__).parents[1] / "data" / "exercises" / "romania-greedy.toml"
    app = build_app(parse_options(["--exercise", str(exercise)]))
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: view_of(app).tiles is not None)
        panel = app.query_one(ChallengePanel)
        await wait_until(pilot, lambda: panel.verdict is not None)
        assert panel.verdict is not None and not panel.verdict.solved
        assert "Greedy on Romania" in str(panel.border_title)
        app.session.cursor = "Fagaras"
        await pilot.press("o")
        await wait_until(pilot, lambda: panel.verdict is not None and panel.verdict.solved)
        assert "both paths cost 418.00" in panel.text


@sync
async def test_a_table_that_says_too_much_is_said_under_a_star() -> None:
    """The app checks a graph's table against its roads: one that overestimates somewhere is
    said in the status line, naming the node and the figures."""
    from tui_search.engine.maps.graph_file import parse_graph
    from tui_search.engine.search.choices import Semantics

    graph = parse_graph("node A 0 0\nnode B 1 0\nnode C 2 0\nedge A B 2\nedge B C 3\n"
                        "start A\ngoal C\nh A 5\nh B 9\nh C 0\n", "over.graph")
    app = graph_app(graph, algorithm="astar",
                    semantics=Semantics(order=("file",), heuristic="table"))
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: "not admissible: h(B) = 9" in status_text(app))
        await pilot.press("1")  # BFS: no estimate, nothing to say
        await wait_until(pilot, lambda: "not admissible" not in status_text(app))


@sync
async def test_a_graph_s_trace_is_replayed_beside_its_search(tmp_path: Path) -> None:
    """``tui-search romania --replay FILE``: the trace (node names) in a pane of its own beside
    the search the diagnosis finds, stepped in lockstep."""
    from tui_search.cli.main import build_app, main
    from tui_search.cli.parse import parse_options

    trace = tmp_path / "dfs.jsonl"
    assert main(["romania", "-a", "dfs", "--headless", "--trace", str(trace)]) == 0
    app = build_app(parse_options(["romania", "--replay", str(trace)]))
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: len(app.session.runs) == 2)
        assert app.session.labels == ["your trace", "DFS"]
        for _ in range(4):
            await pilot.press("n")
        await wait_until(pilot, lambda: all(run.k == 4 for run in app.session.runs))
        assert "matches DFS (order file" in status_text(app)


@sync
async def test_a_table_that_drops_too_fast_along_a_road_is_said_too() -> None:
    """An admissible table that is not consistent: A* still finds the cheapest path, and the
    status line says the table may make it expand a node again, naming the road."""
    from tui_search.engine.maps.graph_file import parse_graph
    from tui_search.engine.search.choices import Semantics

    graph = parse_graph("node A 0 0\nnode B 1 0\nnode C 2 0\nedge A B 1\nedge B C 10\n"
                        "start A\ngoal C\nh A 11\nh B 2\nh C 0\n", "drop.graph")
    app = graph_app(graph, algorithm="astar",
                    semantics=Semantics(order=("file",), heuristic="table"))
    async with app.run_test(size=SIZE) as pilot:
        await wait_until(pilot, lambda: "not consistent: h(A) = 11" in status_text(app))
        run = app.session.run
        assert run is not None and run.admissible

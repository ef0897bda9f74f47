"""The graph's drawing without Textual (tui_search/tui/view/graph_layout/): the places and the
layered layout, the fit into a box of cells, names and costs that never cover one another, the
braille roads, the overview of a big graph, and the nodes found by cell, point and direction."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from tests.tui.graph_app import grid_graph
from tui_search.engine.maps.graph import Edge, Graph
from tui_search.engine.maps.graph_file import built_in_graph, load_graph
from tui_search.tui.view.graph_layout.canvas import Canvas
from tui_search.tui.view.graph_layout.labels import shown, unique_lengths
from tui_search.tui.view.graph_layout.picking import nearest, node_at, tab_next, toward
from tui_search.tui.view.graph_layout.places import Placement, layered
from tui_search.tui.view.graph_layout.raster import (
    ARROW,
    COST,
    DOTS,
    MARK,
    NAME,
    ROAD,
    Tile,
    Tiles,
    road_dots,
)
from tui_search.tui.widgets.graph_lines import MARKS  # noqa: F401 -- the glyphs exist

ROMANIA = built_in_graph("romania")
DFS = load_graph("maps/graphs/dfs-backtracks.graph")


def drawing(graph: Graph, width: int, height: int, level: int = 0) -> tuple[Canvas, Tiles]:
    """What the graph view draws ``graph`` from in a ``width`` x ``height`` box."""
    names = [shown(name) for name in graph.names]
    canvas = Canvas(Placement(graph), width, height, level, max(map(len, names)))
    costs = any(cost != 1 for cost in graph.data.road_cost)
    return canvas, Tiles(canvas, names, unique_lengths(names), costs)


def every_tile(tiles: Tiles) -> list[Tile]:
    tw, th = tiles.canvas.tile_size
    return [tiles.at(tx, ty) for ty in range(math.ceil(tiles.canvas.rows / th))
            for tx in range(math.ceil(tiles.canvas.cols / tw))]


def placed_names(tiles: Tiles) -> dict[int, tuple[int, int, str]]:
    return {v: placed for tile in every_tile(tiles) for v, placed in tile.names.items()}


def items(tiles: Tiles, kind: int) -> list[tuple[int, int, str, object]]:
    """Every item of ``kind``: (column, row, text, what)."""
    canvas = tiles.canvas
    return [(col, row, text, what) for row in range(canvas.rows)
            for col, text, k, what in tiles.row_items(row, 0, canvas.cols) if k == kind]


def check_apart(canvas: Canvas, tiles: Tiles) -> None:
    """No two texts (names, costs) share a cell or touch on a row, and none covers a mark."""
    marks = {canvas.cell(v) for v in range(len(canvas.fx))}
    cells: dict[tuple[int, int], object] = {}
    for kind in (NAME, COST):
        for col, row, text, what in items(tiles, kind):
            key = (kind, what)
            for c in range(col, col + len(text)):
                assert (c, row) not in marks
                assert cells.get((c, row), key) == key, f"{text!r} over another text"
                cells[(c, row)] = key
            for c in (col - 1, col + len(text)):
                assert cells.get((c, row), key) == key or (c, row) in marks, "texts touch"


# -- places ----------------------------------------------------------------------------------
def test_a_graph_with_places_keeps_them() -> None:
    p = Placement(ROMANIA)
    assert p.given and (p.xs[ROMANIA.index["Arad"]], p.ys[ROMANIA.index["Arad"]]) == (91, 492)


def test_the_layered_layout_puts_the_start_on_top_and_the_files_order_across() -> None:
    """dfs-backtracks has no places: S on top, then B left of A (``edge S B`` comes first),
    then G under B and C, E under A, then D under C."""
    xs, ys = layered(DFS)
    at = {name: (xs[i], ys[i]) for i, name in enumerate(DFS.names)}
    assert at["S"][1] == 0 and at["A"][1] == at["B"][1] == -1
    assert at["G"][1] == at["C"][1] == at["E"][1] == -2 and at["D"][1] == -3
    assert at["B"][0] < at["A"][0] and at["G"][0] < at["C"][0] < at["E"][0]
    assert at["D"][0] == at["C"][0]
    assert layered(DFS) == (xs, ys)  # deterministic


@st.composite
def graphs(draw: st.DrawFn, places: bool = False) -> Graph:
    n = draw(st.integers(1, 30))
    pairs = draw(st.lists(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)),
                          max_size=60))
    edges = [Edge(a, b, draw(st.sampled_from([1.0, 2.5, 75.0])), draw(st.booleans()))
             for a, b in pairs]
    names = [f"n{i}" for i in range(n)]
    spots = None
    if places:
        spots = draw(st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)),
                              min_size=n, max_size=n, unique=True))
    return Graph.of(names, edges, places=[(float(x), float(y)) for x, y in spots or []]
                    if spots else None, start=names[draw(st.integers(0, n - 1))])


@given(graphs())
def test_the_layered_layout_gives_every_node_a_place_of_its_own(graph: Graph) -> None:
    xs, ys = layered(graph)
    assert len(set(zip(xs, ys, strict=True))) == len(graph)
    assert ys[graph.index[graph.start]] == 0
    assert layered(graph) == (xs, ys)


# -- names -----------------------------------------------------------------------------------
def test_names_are_drawn_one_printable_cell_a_character() -> None:
    assert shown("Arad") == "Arad"
    assert shown("a\x1b[31mb") == "a?[31mb" and shown("北京") == "??"


@given(st.lists(st.text(alphabet="abAB", min_size=1, max_size=6), unique=True, max_size=12))
def test_unique_prefixes_tell_every_name_apart_and_are_the_shortest(names: list[str]) -> None:
    need = unique_lengths(names)
    cut = [name[:k] for name, k in zip(names, need, strict=True)]
    assert len(set(cut)) == len(names)
    for i, (name, k) in enumerate(zip(names, need, strict=True)):
        if k < len(name):
            assert not any(o.startswith(name[:k]) for j, o in enumerate(names) if j != i)
        if k > 1:  # one shorter would be another name's prefix (or the name's end)
            assert any(o.startswith(name[: k - 1]) for j, o in enumerate(names) if j != i)


def test_romania_at_80x24_names_every_city_readably() -> None:
    """Every city named, by at least three letters of its name, no two texts touching."""
    canvas, tiles = drawing(ROMANIA, 78, 22)  # the box inside a border at 80x24
    assert not canvas.overview
    names = placed_names(tiles)
    assert sorted(names) == list(range(20))
    for v, (_, _, text) in names.items():
        word = text.strip()
        assert ROMANIA.names[v].startswith(word) and len(word) >= 3
    check_apart(canvas, tiles)


def test_romania_in_bigger_boxes_has_full_names_and_every_cost() -> None:
    for width, height in ((118, 38), (198, 58)):
        canvas, tiles = drawing(ROMANIA, width, height)
        assert {v: t.strip() for v, (_, _, t) in placed_names(tiles).items()} == dict(
            enumerate(ROMANIA.names))
        assert sorted(what for _, _, _, what in items(tiles, COST)) == list(range(23))
        check_apart(canvas, tiles)


@given(st.integers(12, 120), st.integers(6, 50))
def test_romania_in_any_box_never_covers_a_mark_or_a_text(width: int, height: int) -> None:
    canvas, tiles = drawing(ROMANIA, width, height)
    assert canvas.cols >= width and canvas.rows >= height
    if not canvas.overview:
        check_apart(canvas, tiles)
        for _, _, text in placed_names(tiles).values():
            assert text.strip() in {name[: len(text.strip())] for name in ROMANIA.names}


def test_a_name_beside_its_mark_is_joined_to_it_by_a_blank() -> None:
    canvas, tiles = drawing(ROMANIA, 118, 38)
    for v, (col, row, text) in placed_names(tiles).items():
        mc, mr = canvas.cell(v)
        if row == mr:
            assert (col, text[0]) == (mc + 1, " ") or (col + len(text), text[-1]) == (mc, " ")


# -- the fit ---------------------------------------------------------------------------------
def test_places_keep_their_proportions_a_row_being_two_columns_tall() -> None:
    canvas, _ = drawing(ROMANIA, 118, 38)
    assert canvas.kx == 2 * canvas.ky
    p = canvas.placement
    for v in range(len(ROMANIA)):
        assert 0 <= canvas.fx[v] < 118 and 0 <= canvas.fy[v] < 38
        assert math.isclose(canvas.fx[v], canvas.ox + (p.xs[v] - p.x0) * canvas.kx)


def test_each_zoom_level_is_bigger_and_the_last_is_bounded() -> None:
    sizes = []
    canvas, _ = drawing(ROMANIA, 78, 22)
    for level in range(canvas.levels):
        c, _ = drawing(ROMANIA, 78, 22, level)
        sizes.append((c.cols, c.rows))
    assert sizes[0] == (78, 22) and sizes == sorted(sizes) and len(set(sizes)) == len(sizes)
    assert drawing(ROMANIA, 78, 22, 99)[0].level == canvas.levels - 1


def test_a_laid_out_graph_is_spread_but_not_past_a_readable_spacing() -> None:
    canvas, tiles = drawing(DFS, 198, 58)
    rows = sorted({canvas.cell(v)[1] for v in range(len(DFS))})
    assert [b - a for a, b in zip(rows, rows[1:], strict=False)] == [6, 6, 6]
    assert len(placed_names(tiles)) == len(DFS)


# -- roads -----------------------------------------------------------------------------------
@given(st.integers(-40, 40), st.integers(-40, 40), st.integers(-40, 40), st.integers(-40, 40))
def test_a_road_is_a_line_of_touching_dots_and_clipping_keeps_its_dots(
        ax: int, ay: int, bx: int, by: int) -> None:
    whole = list(road_dots(ax, ay, bx, by, (-100, -100, 100, 100)))
    assert whole[0] == (ax, ay) and whole[-1] == (bx, by)
    for (x1, y1), (x2, y2) in zip(whole, whole[1:], strict=False):
        assert max(abs(x1 - x2), abs(y1 - y2)) == 1
    box = (-7, -5, 9, 13)
    inside = [(x, y) for x, y in whole if -7 <= x < 9 and -5 <= y < 13]
    assert list(road_dots(ax, ay, bx, by, box)) == inside


def test_roads_are_braille_and_an_arc_has_its_arrow() -> None:
    graph = Graph.of(["A", "B"], [Edge(0, 1, 3.0, directed=True)],
                     places=[(0.0, 0.0), (10.0, 0.0)], start="A")
    canvas, tiles = drawing(graph, 60, 10)
    roads = items(tiles, ROAD)
    assert roads and all("\u2800" < ch <= "\u28ff" for _, _, text, _ in roads for ch in text)
    (col, row, text, what), = items(tiles, ARROW)
    assert text == "→" and what == 0 and row == canvas.cell(1)[1]
    assert col < canvas.cell(1)[0]
    assert [t for _, _, t, _ in items(tiles, COST)] == ["3"]


# -- a big graph -----------------------------------------------------------------------------
def test_a_big_graph_is_an_overview_of_dots_that_holds_every_node() -> None:
    graph = grid_graph(120)
    canvas, tiles = drawing(graph, 100, 30)
    assert canvas.overview and not canvas.roads_drawn
    held = [v for _, _, _, what in items(tiles, DOTS) for v in what]  # type: ignore[attr-defined]
    assert sorted(held) == list(range(len(graph)))
    deepest, tiles = drawing(graph, 100, 30, canvas.levels - 1)
    assert not deepest.overview and deepest.tile_size != (deepest.cols, deepest.rows)
    start = tiles.row_items(deepest.cell(0)[1], 0, 200)
    assert any(kind == MARK and what == 0 for _, _, kind, what in start)


# -- finding nodes ---------------------------------------------------------------------------
def test_a_mark_or_a_letter_of_a_name_is_its_node() -> None:
    canvas, tiles = drawing(ROMANIA, 118, 38)
    for v, (col, row, text) in placed_names(tiles).items():
        assert node_at(tiles, *canvas.cell(v)) == v
        assert node_at(tiles, col + len(text) // 2, row) == v
    assert node_at(tiles, 0, 0) is None and node_at(tiles, -5, 3) is None


def seen(canvas: Canvas, a: int, b: int) -> tuple[float, float]:
    return canvas.fx[b] - canvas.fx[a], 2 * (canvas.fy[b] - canvas.fy[a])


def brute_toward(canvas: Canvas, node: int, direction: str) -> int | None:
    """The rule, looked for among every node: the nearest within 45 degrees, else 90."""
    ux, uy = {"left": (-1, 0), "right": (1, 0), "up": (0, -1), "down": (0, 1)}[direction]
    cone, half = [], []
    for v in range(len(canvas.fx)):
        dx, dy = seen(canvas, node, v)
        along, across = dx * ux + dy * uy, abs(dx * uy - dy * ux)
        if v != node and along > 0:
            (cone if across <= along else half).append((math.hypot(dx, dy), v))
    best = min(cone or half, default=None)
    return None if best is None else best[1]


def test_from_bucharest_left_is_pitesti_by_the_rule() -> None:
    """Pitesti is 27 degrees above left of Bucharest, Giurgiu 66 below: only Pitesti is in
    the cone, and the nearest there."""
    canvas, _ = drawing(ROMANIA, 118, 38)
    i = ROMANIA.index
    assert toward(canvas, i["Bucharest"], "left") == i["Pitesti"]
    assert toward(canvas, i["Bucharest"], "down") == i["Giurgiu"]
    assert toward(canvas, i["Arad"], "left") is None
    for v in range(20):
        for way in ("left", "right", "up", "down"):
            assert toward(canvas, v, way) == brute_toward(canvas, v, way)


@given(graphs(places=True), st.sampled_from(["left", "right", "up", "down"]), st.data())
def test_the_nearest_node_that_way_is_the_rules_on_any_graph(graph: Graph, way: str,
                                                             data: st.DataObject) -> None:
    canvas, _ = drawing(graph, 80, 24)
    node = data.draw(st.integers(0, len(graph) - 1))
    assert toward(canvas, node, way) == brute_toward(canvas, node, way)
    col, row = data.draw(st.floats(0, 80)), data.draw(st.floats(0, 24))
    best = min((math.hypot(canvas.fx[v] - col, 2 * (canvas.fy[v] - row)), v)
               for v in range(len(graph)))
    assert nearest(canvas, col, row) == best[1]


def test_the_nearest_node_that_way_on_a_big_graph_is_a_neighbour() -> None:
    graph = grid_graph(100)
    canvas, _ = drawing(graph, 100, 30)
    middle = 50 * 100 + 50
    assert toward(canvas, middle, "left") == middle - 1
    assert toward(canvas, middle, "down") == middle + 100
    assert toward(canvas, 0, "up") is None


def test_tab_goes_by_number_round_the_end() -> None:
    assert [tab_next(3, v) for v in range(3)] == [1, 2, 0]
    assert [tab_next(3, v, -1) for v in range(3)] == [2, 0, 1]

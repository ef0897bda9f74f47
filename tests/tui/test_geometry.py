"""The map's one cell geometry (Textual-free): sizes, cell <-> screen, scrolling by whole
cells, and the fits the app picks by default and for the overview."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from tui_search.tui.view.geometry import MAX_LEVEL, Geometry

maps = st.tuples(st.integers(1, 600), st.integers(1, 600))


def test_the_default_is_the_largest_square_looking_cell_that_fits() -> None:
    g = Geometry.fit(6, 6, 100, 40)  # 6 columns of 16 characters: 96; 6 rows of 8 lines: 48
    assert (g.level, g.cell_width, g.cell_height, g.size) == (6, 12, 6, (72, 36))
    assert Geometry.fit(6, 6, 11, 40).level == 1  # too narrow for 4x2: the smallest
    assert Geometry.fit(512, 512, 90, 40).size == (1024, 512)  # does not fit: it scrolls
    assert Geometry.fit(1, 1, 10_000, 10_000).level == MAX_LEVEL


@given(maps, st.integers(1, 300), st.integers(1, 100))
def test_a_fit_fits_and_the_next_size_up_does_not(m, width, height) -> None:
    g = Geometry.fit(*m, width, height)
    w, h = g.size
    if g.level > 1 or (w <= width and h <= height):
        assert w <= width and h <= height
        bigger = g.zoomed(1)
        assert bigger.level == MAX_LEVEL == g.level or (
            bigger.size[0] > width or bigger.size[1] > height)


@given(maps, st.integers(1, 300), st.integers(1, 100))
def test_the_overview_shows_every_column_and_row_with_the_smallest_block(m, width,
                                                                         height) -> None:
    g = Geometry.overview_fit(*m, width, height)
    assert g.overview and g.size[0] <= width and g.size[1] <= height
    covered = {g.cell_at(x, y) for x in range(g.size[0]) for y in range(g.size[1])}
    assert None not in covered
    # every map row is drawn by some line's halves, every column by some character
    rows = set()
    for line in range(g.size[1]):
        upper, lower = g.line_rows(line)
        rows.update(upper, lower)
    assert rows == set(range(m[1]))
    assert set(g.visible_columns(0, g.size[0])) == set(range(m[0]))
    if g.block > 1:
        smaller = Geometry(*m, 1, g.block - 1)
        assert smaller.size[0] > width or smaller.size[1] > height


def test_a_512_map_in_the_overview_of_a_140x45_terminal() -> None:
    """The map area of a 140x45 terminal is about 90x38: a block of 7 cells a character."""
    g = Geometry.overview_fit(512, 512, 90, 38)
    assert g.block == 7 and g.size == (74, 37)


@given(maps, st.integers(1, MAX_LEVEL), st.data())
def test_cell_and_screen_agree_at_every_size(m, level, data) -> None:
    g = Geometry(*m, level)
    cell = (data.draw(st.integers(0, m[0] - 1)), data.draw(st.integers(0, m[1] - 1)))
    x, y, w, h = g.cell_region(cell)
    dx, dy = data.draw(st.integers(0, w - 1)), data.draw(st.integers(0, h - 1))
    assert g.cell_at(x + dx, y + dy) == cell
    assert list(g.lines_of(cell)) == list(range(y, y + h))
    assert g.line_rows(y + dy)[0] == range(cell[1], cell[1] + 1)
    assert g.cell_at(-1, 0) is None and g.cell_at(*g.size) is None


@given(maps, st.integers(1, MAX_LEVEL), st.integers(0, 5000), st.integers(0, 5000),
       st.integers(1, 200), st.integers(1, 60))
def test_scrolling_starts_at_whole_cells_and_reaches_the_last(m, level, x, y, vw, vh) -> None:
    g = Geometry(*m, level)
    sx, sy = g.snap(x, y)
    assert sx % g.cell_width == 0 and sy % g.cell_height == 0 and sx <= x and sy <= y
    room_w, room_h = g.scroll_room(vw, vh)
    if room_w > vw:
        assert (room_w - vw) % g.cell_width == 0 and room_w - g.size[0] < g.cell_width
    if room_h > vh:
        assert (room_h - vh) % g.cell_height == 0


@given(maps, st.integers(1, MAX_LEVEL), st.data(), st.integers(24, 200), st.integers(12, 60))
def test_follow_puts_the_cell_in_view(m, level, data, vw, vh) -> None:
    g = Geometry(*m, level)
    cell = (data.draw(st.integers(0, m[0] - 1)), data.draw(st.integers(0, m[1] - 1)))
    scroll = (data.draw(st.integers(0, 3000)), data.draw(st.integers(0, 3000)))
    sx, sy = g.follow(cell, scroll, (vw, vh))
    x, y, w, h = g.cell_region(cell)
    if w <= vw and h <= vh:
        assert sx <= x and x + w <= sx + vw and sy <= y and y + h <= sy + vh


def test_zoom_steps_through_the_sizes_and_leaves_the_overview() -> None:
    g = Geometry(10, 10, 3)
    assert [g.zoomed(1).level, g.zoomed(-1).level, g.zoomed(-5).level] == [4, 2, 1]
    assert Geometry(10, 10, MAX_LEVEL).zoomed(1).level == MAX_LEVEL
    assert not Geometry.overview_fit(10, 10, 5, 5).zoomed(1).overview

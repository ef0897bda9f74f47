"""The exercise files' ``solved`` language: precedence, errors, every field, and printing back."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tui_search.engine.course.condition import (
    FIELDS,
    MAX_NESTING,
    MAX_OPERATORS,
    BinOp,
    Compare,
    ConditionError,
    Name,
    Neg,
    Node,
    Not,
    Num,
    evaluate,
    names,
    parse_condition,
    unparse,
)

SEARCHES = ("bfs", "dfs", "astar_manhattan")


def parse(text: str) -> Node:
    return parse_condition(text, SEARCHES)


def value(text: str, **figures: float | bool | None) -> float | bool:
    return evaluate(parse(text), {k.replace("__", "."): v for k, v in figures.items()})


@pytest.mark.parametrize(("text", "tree"), [
    ("1 + 2 * 3", BinOp("+", Num(1), BinOp("*", Num(2), Num(3)))),
    ("1 - 2 - 3", BinOp("-", BinOp("-", Num(1), Num(2)), Num(3))),
    ("8 / 4 / 2", BinOp("/", BinOp("/", Num(8), Num(4)), Num(2))),
    ("-2 * 3", BinOp("*", Neg(Num(2)), Num(3))),
    ("(1 + 2) * 3", BinOp("*", BinOp("+", Num(1), Num(2)), Num(3))),
    ("1 < 2 + 3", Compare(Num(1), ("<",), (BinOp("+", Num(2), Num(3)),))),
    ("1 < 2 <= 3", Compare(Num(1), ("<", "<="), (Num(2), Num(3)))),
    ("not 1 < 2", Not(Compare(Num(1), ("<",), (Num(2),)))),
    ("not not 1", Not(Not(Num(1)))),
    ("1 or 2 and 3", BinOp("or", Num(1), BinOp("and", Num(2), Num(3)))),
    ("not 1 and 2", BinOp("and", Not(Num(1)), Num(2))),
    ("(1 or 2) and 3", BinOp("and", BinOp("or", Num(1), Num(2)), Num(3))),
    ("bfs.cost > astar_manhattan.cost",
     Compare(Name("bfs", "cost"), (">",), (Name("astar_manhattan", "cost"),))),
])
def test_python_s_precedence(text: str, tree: Node) -> None:
    assert parse(text) == tree


def test_it_evaluates_as_python_would() -> None:
    for text in ("1 + 2 * 3 == 7", "7 / 2 == 3.5", "1 < 2 < 3", "not 3 < 2 < 5",
                 "1 or 0 and 0", "-(2 - 5) == 3", "2 * -3 == -6", "1 != 2"):
        assert value(text) is True, text
    for text in ("1 < 3 < 2", "(1 or 0) and 0", "1 == 2", "2 != 2"):
        assert value(text) is False, text


@pytest.mark.parametrize("field", FIELDS)
def test_every_field_is_read_from_the_figures(field: str) -> None:
    tree = parse(f"bfs.{field} == dfs.{field} + 1")
    assert names(tree) == [f"bfs.{field}", f"dfs.{field}"]
    assert evaluate(tree, {f"bfs.{field}": 5, f"dfs.{field}": 4}) is True
    assert evaluate(tree, {f"bfs.{field}": 5, f"dfs.{field}": 5}) is False


def test_an_undefined_figure_fails_every_comparison() -> None:
    """A search with no path has no moves or cost: comparisons with them are false."""
    for op in ("<", "<=", ">", ">=", "==", "!="):
        assert value(f"dfs.moves {op} bfs.moves", dfs__moves=None, bfs__moves=7) is False
    assert value("bfs.moves / 0 > 1", bfs__moves=3) is False  # division by zero: undefined
    assert value("bfs.found and not dfs.found", bfs__found=True, dfs__found=False) is True
    # used bare, an undefined figure is false too, never true as NaN would be in Python
    assert value("dfs.moves and 1", dfs__moves=None) is False
    assert value("dfs.moves or 0", dfs__moves=None) is False
    assert value("not dfs.moves", dfs__moves=None) is True


def test_a_number_too_large_to_print_back_is_refused() -> None:
    with pytest.raises(ConditionError, match="too large"):
        parse("bfs.expanded < 1e999")


@pytest.mark.parametrize(("text", "message", "offset"), [
    ("", "the condition is empty", 0),
    ("bfs.expanded <", ("expected a number, a name like bfs.expanded, 'not' or '(', "
     "not the end"), 14),
    ("bfs.expanded < < 3", "expected a number", 15),
    ("(1 + 2", "'(' is never closed", 0),
    ("(1 + 2 3", "expected ')', not '3'", 7),
    ("1 + 2)", "expected 'and', 'or', an operator or the end, not ')'", 5),
    ("bfs.expanded = 3", "unexpected '='", 13),
    ("ucs.cost < 3", "'ucs' is not one of the exercise's searches (bfs, dfs, astar_manhattan)",
     0),
    ("1 < bfs.steps", "'bfs.steps': unknown field 'steps'", 8),
    ("bfs < 2", "'bfs': name a search's field, as in bfs.expanded", 0),
    ("astar:manhattan.cost", "unexpected ':'", 5),
    ("1 and or 2", "expected a number", 6),
    ("(" * 200 + "1" + ")" * 200, "nested too deeply (at most 50", 50),
    ("not " * 2000 + "bfs.found", "the condition is too long (at most 200 operators)", 800),
    ("-" * 2000 + "1 < 2", "the condition is too long", 200),
    ("-" * 60 + "1 < 2", "nested too deeply", 50),
    ("not " * 51 + "bfs.found", "nested too deeply", 200),
    (" + ".join(["1"] * 1200) + " > 0", "the condition is too long", 200 * 4 + 2),
])
def test_errors_say_what_and_where(text: str, message: str, offset: int) -> None:
    with pytest.raises(ConditionError) as caught:
        parse(text)
    assert caught.value.message.startswith(message) and caught.value.offset == offset


def test_the_longest_and_deepest_conditions_parse_print_and_evaluate() -> None:
    """Within the limits nothing needs more than 500 frames: room is left for the stack
    under it (an app's)."""
    import inspect
    import sys

    chain = " + ".join(["bfs.expanded"] * (MAX_OPERATORS - 1)) + " > 0"
    deep = "(" * MAX_NESTING + "bfs.expanded" + ")" * MAX_NESTING + " > 0"
    negs = "-" * (MAX_NESTING - 1) + "bfs.expanded == -1"

    def run(depth: int) -> None:
        if depth:
            return run(depth - 1)
        for text in (chain, deep, negs, "not " * MAX_NESTING + "bfs.found"):
            tree = parse(text)
            assert parse(unparse(tree)) == tree
            assert evaluate(tree, {"bfs.expanded": 1, "bfs.found": True}) in (True, False)
            assert names(tree)
        return None

    run(sys.getrecursionlimit() - 500 - len(inspect.stack(0)))  # 500 frames left


# -- printed back, parsed again: the same tree ------------------------------------------
_leaves = st.one_of(
    st.integers(0, 10**6).map(lambda n: Num(float(n))),
    st.floats(0, 1e6, allow_nan=False, allow_infinity=False).map(Num),
    st.builds(Name, st.sampled_from(SEARCHES), st.sampled_from(FIELDS)),
)


def _extend(inner: st.SearchStrategy[Node]) -> st.SearchStrategy[Node]:
    ops = st.sampled_from(("+", "-", "*", "/", "and", "or"))
    comparisons = st.lists(st.sampled_from(("<", "<=", ">", ">=", "==", "!=")),
                           min_size=1, max_size=3)
    return st.one_of(
        st.builds(BinOp, ops, inner, inner),
        st.builds(Neg, inner),
        st.builds(Not, inner),
        comparisons.flatmap(lambda cs: st.builds(
            Compare, inner, st.just(tuple(cs)), st.tuples(*[inner] * len(cs)))),
    )


@given(st.recursive(_leaves, _extend, max_leaves=12))
def test_a_tree_printed_back_parses_to_the_same_tree(tree: Node) -> None:
    assert parse(unparse(tree)) == tree


@given(st.recursive(_leaves, _extend, max_leaves=12))
def test_a_parsed_expression_printed_back_means_the_same(tree: Node) -> None:
    figures = {f"{s}.{f}": float(i + 1) for i, (s, f) in enumerate(
        (s, f) for s in SEARCHES for f in FIELDS)}
    a, b = evaluate(tree, figures), evaluate(parse(unparse(tree)), figures)
    assert a == b or (math.isnan(a) and math.isnan(b))

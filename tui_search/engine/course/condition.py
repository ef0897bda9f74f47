"""An exercise's ``solved`` condition: a small expression language, parsed here (never
``eval``), printed back and evaluated on the searches' figures.

    greedy.found and astar.found and greedy.cost > astar.cost

Names are ``SEARCH.FIELD`` (:data:`FIELDS`); numbers; ``+ - * /`` (true division); the
comparisons ``< <= > >= == !=`` (chained as in Python: ``a < b < c``); ``and``, ``or`` and
``not``; parentheses.  The precedence is Python's: ``or`` < ``and`` < ``not`` < comparisons <
``+ -`` < ``* /`` < unary ``-``.

A condition is at most :data:`MAX_OPERATORS` operators long and nests at most
:data:`MAX_NESTING` parentheses and unary operators deep: the parser, :func:`unparse`,
:func:`evaluate` and :func:`names` recurse, and this keeps them well within Python's recursion
limit (a longer condition is a :class:`ConditionError`, never a RecursionError).

A figure a search does not have (the moves or cost of a search that found no path) and a
division by zero are *undefined* (NaN): every comparison with them is false.

Plain Python, no UI.
"""

from __future__ import annotations

import math
import re
from collections.abc import Collection, Iterator, Mapping
from typing import NamedTuple

#: The fields of a search a condition may name.
FIELDS = ("found", "moves", "cost", "expanded", "generated", "max_frontier")
COMPARISONS = ("<=", ">=", "==", "!=", "<", ">")
#: The most operators (``+ - * / not and or`` and comparisons) a condition may have: a tree of
#: that depth takes some 2 frames a level to print back.
MAX_OPERATORS = 200
#: The most parentheses and unary operators (``not``, ``-``, ``+``) open at once: the parser
#: takes some 8 frames a parenthesis.
MAX_NESTING = 50


class ConditionError(ValueError):
    """A condition that does not parse: the message and where, counted from 0 in the text."""

    def __init__(self, message: str, offset: int) -> None:
        super().__init__(message, offset)
        self.message = message
        self.offset = offset


class Num(NamedTuple):
    value: float


class Name(NamedTuple):
    search: str
    field: str

    @property
    def key(self) -> str:
        return f"{self.search}.{self.field}"


class Neg(NamedTuple):
    operand: Node


class Not(NamedTuple):
    operand: Node


class BinOp(NamedTuple):
    op: str  # + - * / and or
    left: Node
    right: Node


class Compare(NamedTuple):
    first: Node
    ops: tuple[str, ...]
    rest: tuple[Node, ...]


Node = Num | Name | Neg | Not | BinOp | Compare

# -- tokens ------------------------------------------------------------------------------
_TOKEN = re.compile(r"""
    (?P<space>\s+)
  | (?P<number>(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)
  | (?P<name>[A-Za-z_][A-Za-z_0-9]*(?:\.[A-Za-z_][A-Za-z_0-9]*)*)
  | (?P<op><=|>=|==|!=|<|>|[-+*/()])
""", re.VERBOSE)
_KEYWORDS = ("and", "or", "not")


class _Token(NamedTuple):
    kind: str  # number, name, op, keyword, end
    text: str
    offset: int


def _tokens(text: str) -> Iterator[_Token]:
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            raise ConditionError(f"unexpected {text[pos]!r}", pos)
        kind = m.lastgroup or ""
        if kind != "space":
            if kind == "name" and m.group() in _KEYWORDS:
                kind = "keyword"
            yield _Token(kind, m.group(), pos)
        pos = m.end()
    yield _Token("end", "", len(text))


# -- the parser --------------------------------------------------------------------------
class _Parser:
    def __init__(self, text: str, searches: Collection[str]) -> None:
        self.tokens = list(_tokens(text))
        self.i = 0
        self.searches = searches
        self.depth = 0  # the parentheses and unary operators open
        operators = [t for t in self.tokens if t.kind == "keyword"
                     or (t.kind == "op" and t.text not in "()")]
        if len(operators) > MAX_OPERATORS:
            raise ConditionError(f"the condition is too long (at most {MAX_OPERATORS} "
                                 "operators)", operators[MAX_OPERATORS].offset)

    def nested(self, tok: _Token) -> None:
        """One more parenthesis or unary operator open, ``tok``: too deep is an error."""
        self.depth += 1
        if self.depth > MAX_NESTING:
            raise ConditionError(f"nested too deeply (at most {MAX_NESTING} parentheses and "
                                 "unary operators inside each other)", tok.offset)

    @property
    def tok(self) -> _Token:
        return self.tokens[self.i]

    def take(self, *texts: str) -> _Token | None:
        tok = self.tok
        if tok.kind in ("op", "keyword") and tok.text in texts:
            self.i += 1
            return tok
        return None

    def expected(self, what: str) -> ConditionError:
        tok = self.tok
        got = "the end" if tok.kind == "end" else repr(tok.text)
        return ConditionError(f"expected {what}, not {got}", tok.offset)

    def parse(self) -> Node:
        if self.tok.kind == "end":
            raise ConditionError("the condition is empty", 0)
        node = self.or_expr()
        if self.tok.kind != "end":
            raise self.expected("'and', 'or', an operator or the end")
        return node

    def or_expr(self) -> Node:
        node = self.and_expr()
        while self.take("or"):
            node = BinOp("or", node, self.and_expr())
        return node

    def and_expr(self) -> Node:
        node = self.not_expr()
        while self.take("and"):
            node = BinOp("and", node, self.not_expr())
        return node

    def not_expr(self) -> Node:
        if (tok := self.take("not")) is not None:
            self.nested(tok)
            node = Not(self.not_expr())
            self.depth -= 1
            return node
        return self.comparison()

    def comparison(self) -> Node:
        first = self.sum()
        ops: list[str] = []
        rest: list[Node] = []
        while (tok := self.take(*COMPARISONS)) is not None:
            ops.append(tok.text)
            rest.append(self.sum())
        return Compare(first, tuple(ops), tuple(rest)) if ops else first

    def sum(self) -> Node:
        node = self.term()
        while (tok := self.take("+", "-")) is not None:
            node = BinOp(tok.text, node, self.term())
        return node

    def term(self) -> Node:
        node = self.unary()
        while (tok := self.take("*", "/")) is not None:
            node = BinOp(tok.text, node, self.unary())
        return node

    def unary(self) -> Node:
        if (tok := self.take("-", "+")) is not None:
            self.nested(tok)
            node = self.unary()
            self.depth -= 1
            return Neg(node) if tok.text == "-" else node
        return self.atom()

    def atom(self) -> Node:
        tok = self.tok
        if (opening := self.take("(")) is not None:
            self.nested(opening)
            node = self.or_expr()
            self.depth -= 1
            if not self.take(")"):
                if self.tok.kind == "end":
                    raise ConditionError("'(' is never closed", opening.offset)
                raise self.expected("')'")
            return node
        if tok.kind == "number":
            value = float(tok.text)
            if math.isinf(value):  # it would print back as "inf", which is no number here
                raise ConditionError(f"the number {tok.text} is too large", tok.offset)
            self.i += 1
            return Num(value)
        if tok.kind == "name":
            self.i += 1
            return self.name(tok)
        raise self.expected("a number, a name like bfs.expanded, 'not' or '('")

    def name(self, tok: _Token) -> Name:
        search, dot, field = tok.text.partition(".")
        if not dot or "." in field:
            raise ConditionError(f"{tok.text!r}: name a search's field, as in "
                                 f"{search}.expanded", tok.offset)
        if search not in self.searches:
            known = ", ".join(self.searches)
            raise ConditionError(f"{search!r} is not one of the exercise's searches "
                                 f"({known})", tok.offset)
        if field not in FIELDS:
            raise ConditionError(f"{tok.text!r}: unknown field {field!r} (use "
                                 f"{', '.join(FIELDS)})", tok.offset + len(search) + 1)
        return Name(search, field)


def parse_condition(text: str, searches: Collection[str]) -> Node:
    """The condition's tree; ``searches``, the names it may use (``astar_manhattan`` for
    ``astar:manhattan``).  :class:`ConditionError` for anything else."""
    return _Parser(text, searches).parse()


# -- printing ----------------------------------------------------------------------------
_PRECEDENCE = {"or": 1, "and": 2, "not": 3, "compare": 4, "+": 5, "-": 5, "*": 6, "/": 6,
               "neg": 7, "atom": 8}


def _level(node: Node) -> int:
    if isinstance(node, BinOp):
        return _PRECEDENCE[node.op]
    if isinstance(node, Compare):
        return _PRECEDENCE["compare"]
    if isinstance(node, Not):
        return _PRECEDENCE["not"]
    if isinstance(node, Neg):
        return _PRECEDENCE["neg"]
    return _PRECEDENCE["atom"]


def _wrapped(node: Node, above: int) -> str:
    """``node`` printed, in parentheses when it binds less tightly than ``above``."""
    text = unparse(node)
    return f"({text})" if _level(node) < above else text


def unparse(node: Node) -> str:
    """The condition printed back, with only the parentheses it needs."""
    if isinstance(node, Num):
        return repr(node.value)
    if isinstance(node, Name):
        return node.key
    if isinstance(node, Neg):
        return "-" + _wrapped(node.operand, _PRECEDENCE["neg"])
    if isinstance(node, Not):
        return "not " + _wrapped(node.operand, _PRECEDENCE["not"])
    if isinstance(node, Compare):
        above = _PRECEDENCE["compare"] + 1  # (a < b) < c is not the chain a < b < c
        parts = [_wrapped(node.first, above)]
        for op, operand in zip(node.ops, node.rest, strict=True):
            parts += [op, _wrapped(operand, above)]
        return " ".join(parts)
    level = _PRECEDENCE[node.op]  # left to right: the right operand binds more tightly
    return f"{_wrapped(node.left, level)} {node.op} {_wrapped(node.right, level + 1)}"


# -- evaluating --------------------------------------------------------------------------
Value = float | bool
_NAN = float("nan")


def names(node: Node) -> list[str]:
    """The ``SEARCH.FIELD`` names the condition uses, in order of first appearance."""
    found: list[str] = []

    def walk(n: Node) -> None:
        if isinstance(n, Name):
            if n.key not in found:
                found.append(n.key)
        elif isinstance(n, (Neg, Not)):
            walk(n.operand)
        elif isinstance(n, BinOp):
            walk(n.left)
            walk(n.right)
        elif isinstance(n, Compare):
            for operand in (n.first, *n.rest):
                walk(operand)

    walk(node)
    return found


def _compare(op: str, a: float, b: float) -> bool:
    if op == "<":
        return a < b
    if op == "<=":
        return a <= b
    if op == ">":
        return a > b
    if op == ">=":
        return a >= b
    if op == "==":
        return a == b
    return not math.isnan(a) and not math.isnan(b) and a != b  # undefined: false too


def _truth(value: Value) -> bool:
    """A value as a condition: an undefined figure (no path's moves, a division by 0) is
    false, as every comparison with it is."""
    return bool(value) and not (isinstance(value, float) and math.isnan(value))


def evaluate(node: Node, figures: Mapping[str, Value | None]) -> Value:
    """The condition's value on ``figures`` (``bfs.expanded`` -> 22; None: undefined)."""
    if isinstance(node, Num):
        return node.value
    if isinstance(node, Name):
        value = figures[node.key]
        return _NAN if value is None else value
    if isinstance(node, Neg):
        return -float(evaluate(node.operand, figures))
    if isinstance(node, Not):
        return not _truth(evaluate(node.operand, figures))
    if isinstance(node, Compare):
        left = float(evaluate(node.first, figures))
        for op, operand in zip(node.ops, node.rest, strict=True):
            right = float(evaluate(operand, figures))
            if not _compare(op, left, right):
                return False
            left = right
        return True
    if node.op == "and":
        return _truth(evaluate(node.left, figures)) and _truth(evaluate(node.right, figures))
    if node.op == "or":
        return _truth(evaluate(node.left, figures)) or _truth(evaluate(node.right, figures))
    a, b = float(evaluate(node.left, figures)), float(evaluate(node.right, figures))
    if node.op == "+":
        return a + b
    if node.op == "-":
        return a - b
    if node.op == "*":
        return a * b
    return a / b if b != 0 else _NAN


__all__ = ["FIELDS", "BinOp", "Compare", "ConditionError", "Name", "Neg", "Node", "Not",
           "Num", "evaluate", "names", "parse_condition", "unparse"]

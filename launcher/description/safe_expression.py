"""A small expression language for `$(eval …)`: Python syntax, evaluated by walking its AST.

Allowed: literals, tuples/lists, arithmetic, comparisons, `and`/`or`/`not`, `x if c else y`,
indexing and slicing, the `math` names (bare or as `math.x`), a few builtins (abs, min, max,
round, int, float, str, bool, len) and plain string methods. Anything else — attribute access
other than those, lambdas, comprehensions, imports, dunder names — is rejected. Nothing is ever
handed to Python's `eval` or `exec`.
"""

from __future__ import annotations

import ast
import math
import operator
from typing import Any


class ExpressionError(Exception):
    """The expression is not allowed, or failed to evaluate."""


_MATH = {n: getattr(math, n) for n in dir(math) if not n.startswith("_")}
_BUILTINS = {"abs": abs, "min": min, "max": max, "round": round, "int": int,
             "float": float, "str": str, "bool": bool, "len": len}
_NAMES: dict[str, Any] = {**_MATH, **_BUILTINS, "True": True, "False": False, "None": None,
                          "true": True, "false": False}
_STR_METHODS = {"upper", "lower", "strip", "lstrip", "rstrip", "split", "replace", "startswith",
                "endswith", "join", "title", "capitalize", "count", "find", "zfill"}
_BINOPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
           ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
           ast.Pow: operator.pow}
_CMPOPS = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt,
           ast.LtE: operator.le, ast.Gt: operator.gt, ast.GtE: operator.ge,
           ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b}
_MAX_SIZE = 1_000_000  # bound on strings/lists an expression may build


def evaluate(expression: str) -> Any:
    try:
        tree = ast.parse(expression.strip(), mode="eval")
    except SyntaxError as exc:
        raise ExpressionError(f"invalid expression: {exc.msg} (column {exc.offset})") from None
    try:
        return _Evaluator().visit(tree.body)
    except ExpressionError:
        raise
    except (ArithmeticError, ValueError, TypeError, IndexError, KeyError) as exc:
        raise ExpressionError(f"{type(exc).__name__}: {exc}") from None


class _Evaluator(ast.NodeVisitor):
    def generic_visit(self, node: ast.AST) -> Any:
        raise ExpressionError(f"'{type(node).__name__}' is not allowed in $(eval)")

    def visit_Constant(self, node: ast.Constant) -> Any:
        if not isinstance(node.value, str | int | float | bool | type(None)):
            raise ExpressionError(f"the literal {node.value!r} is not allowed")
        return node.value

    def visit_Name(self, node: ast.Name) -> Any:
        if node.id not in _NAMES:
            raise ExpressionError(f"unknown name '{node.id}'")
        return _NAMES[node.id]

    def visit_Tuple(self, node: ast.Tuple) -> tuple:
        return tuple(self.visit(e) for e in node.elts)

    def visit_List(self, node: ast.List) -> list:
        return [self.visit(e) for e in node.elts]

    def visit_UnaryOp(self, node: ast.UnaryOp) -> Any:
        value = self.visit(node.operand)
        ops = {ast.USub: operator.neg, ast.UAdd: operator.pos, ast.Not: operator.not_}
        if type(node.op) not in ops:
            raise ExpressionError("'~' is not allowed in $(eval)")
        return ops[type(node.op)](value)

    def visit_BinOp(self, node: ast.BinOp) -> Any:
        if type(node.op) not in _BINOPS:
            raise ExpressionError(f"the operator '{type(node.op).__name__}' is not allowed")
        left, right = self.visit(node.left), self.visit(node.right)
        if isinstance(node.op, ast.Pow) and isinstance(right, int | float) and abs(right) > 1000:
            raise ExpressionError("exponent too large")
        if isinstance(node.op, ast.Mult):
            _check_size(left, right)
        return _BINOPS[type(node.op)](left, right)

    def visit_BoolOp(self, node: ast.BoolOp) -> Any:
        value: Any = None
        for expr in node.values:
            value = self.visit(expr)
            if isinstance(node.op, ast.And) and not value:
                return value
            if isinstance(node.op, ast.Or) and value:
                return value
        return value

    def visit_Compare(self, node: ast.Compare) -> bool:
        left = self.visit(node.left)
        for op, comparator in zip(node.ops, node.comparators, strict=True):
            if type(op) not in _CMPOPS:
                raise ExpressionError(f"the comparison '{type(op).__name__}' is not allowed")
            right = self.visit(comparator)
            if not _CMPOPS[type(op)](left, right):
                return False
            left = right
        return True

    def visit_IfExp(self, node: ast.IfExp) -> Any:
        return self.visit(node.body) if self.visit(node.test) else self.visit(node.orelse)

    def visit_Subscript(self, node: ast.Subscript) -> Any:
        return self.visit(node.value)[self.visit(node.slice)]

    def visit_Slice(self, node: ast.Slice) -> slice:
        parts = (node.lower, node.upper, node.step)
        return slice(*(None if p is None else self.visit(p) for p in parts))

    def visit_Attribute(self, node: ast.Attribute) -> Any:
        if isinstance(node.value, ast.Name) and node.value.id == "math":
            if node.attr not in _MATH:
                raise ExpressionError(f"math has no name '{node.attr}'")
            return _MATH[node.attr]
        raise ExpressionError(f"attribute access '.{node.attr}' is not allowed")

    def visit_Call(self, node: ast.Call) -> Any:
        if node.keywords:
            raise ExpressionError("keyword arguments are not allowed in $(eval)")
        args = [self.visit(a) for a in node.args]
        func = node.func
        if isinstance(func, ast.Attribute) and not (
            isinstance(func.value, ast.Name) and func.value.id == "math"
        ):
            target = self.visit(func.value)
            if not isinstance(target, str) or func.attr not in _STR_METHODS:
                raise ExpressionError(f"calling '.{func.attr}()' is not allowed")
            return getattr(target, func.attr)(*args)
        function = self.visit(func)
        if not callable(function):
            raise ExpressionError(f"'{ast.unparse(func)}' is not a function")
        return function(*args)


def _check_size(left: Any, right: Any) -> None:
    for seq, count in ((left, right), (right, left)):
        sized = isinstance(seq, str | list | tuple) and isinstance(count, int)
        if sized and len(seq) * count > _MAX_SIZE:
            raise ExpressionError("the result would be too large")

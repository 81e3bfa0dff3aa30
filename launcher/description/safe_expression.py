"""A small expression language for `$(eval …)`: Python syntax, evaluated by walking its AST.

Allowed: literals, tuples/lists, arithmetic, comparisons, `and`/`or`/`not`, `x if c else y`,
indexing and slicing, the `math` names (bare or as `math.x`), a few builtins (abs, min, max,
round, int, float, str, bool, len) and plain string methods. Anything else — attribute access
other than those, lambdas, comprehensions, imports, dunder names — is rejected. Nothing is ever
handed to Python's `eval` or `exec`.

Nothing an expression says can hang or starve the launcher: before an operation runs, the size
of what it would make is estimated, and integers past MAX_INT_BITS bits, strings and lists past
MAX_SIZE items, and formatting widths past MAX_WIDTH are refused (`math.factorial(10**8)`,
`10**10**6`, `'%0999999999d' % 1`, `'x'.zfill(10**9)`). Every limit is far beyond what a launch
file needs.
"""

from __future__ import annotations

import ast
import math
import operator
import re
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
MAX_SIZE = 1_000_000  # items in a string or list an expression may build
MAX_INT_BITS = 100_000  # bits of an integer (about 30,000 digits)
MAX_WIDTH = 10_000  # a width or precision in %-formatting
MAX_EXPRESSION = 100_000  # characters of the expression itself
_FORMAT_SPEC = re.compile(r"%(?:\([^)]*\))?[-#0 +]*(\*|\d*)(?:\.(\*|\d*))?[hlL]?[a-zA-Z%]")


class Fields(dict):
    """A message's fields, which an expression reads as attributes (`m.linear.x`)."""


def fields_of(data: Any) -> Any:
    """Plain data (a message as dicts and lists) with its maps readable as attributes."""
    if isinstance(data, dict):
        return Fields((k, fields_of(v)) for k, v in data.items())
    if isinstance(data, list):
        return [fields_of(v) for v in data]
    return data


def _parse(expression: str) -> ast.expr:
    if len(expression) > MAX_EXPRESSION:
        raise ExpressionError(f"the expression is {len(expression)} characters long; the limit "
                              f"is {MAX_EXPRESSION}")
    try:
        return ast.parse(expression.strip(), mode="eval").body
    except SyntaxError as exc:
        raise ExpressionError(f"invalid expression: {exc.msg} (column {exc.offset})") from None
    except (RecursionError, MemoryError):
        raise ExpressionError("the expression is nested too deeply") from None


def check_expression(expression: str, names: tuple[str, ...] = ()) -> None:
    """Refuse, before anything runs, an expression that does not parse or names an unknown
    name (`names`: the ones the caller will give)."""
    for node in ast.walk(_parse(expression)):
        if isinstance(node, ast.Name) and node.id not in _NAMES and node.id not in names:
            known = ", ".join(names) if names else "none"
            raise ExpressionError(f"unknown name '{node.id}' (the names given: {known})")


def evaluate(expression: str, names: dict[str, Any] | None = None) -> Any:
    """The value of `expression`; `names` are more names it may read (a message as Fields)."""
    body = _parse(expression)
    try:
        return _Evaluator(names or {}).visit(body)
    except ExpressionError:
        raise
    except RecursionError:
        raise ExpressionError("the expression is nested too deeply") from None
    except (ArithmeticError, ValueError, TypeError, IndexError, KeyError) as exc:
        raise ExpressionError(f"{type(exc).__name__}: {exc}") from None


class _Evaluator(ast.NodeVisitor):
    def __init__(self, names: dict[str, Any]) -> None:
        self.names = names

    def visit(self, node: ast.AST) -> Any:
        return _checked(super().visit(node))

    def generic_visit(self, node: ast.AST) -> Any:
        raise ExpressionError(f"'{type(node).__name__}' is not allowed in $(eval)")

    def visit_Constant(self, node: ast.Constant) -> Any:
        if not isinstance(node.value, str | int | float | bool | type(None)):
            raise ExpressionError(f"the literal {node.value!r} is not allowed")
        return node.value

    def visit_Name(self, node: ast.Name) -> Any:
        if node.id in self.names and node.id not in _NAMES:  # the language's names come first
            return self.names[node.id]
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
        if isinstance(node.op, ast.Pow):
            _check_power(left, right)
        elif isinstance(node.op, ast.Mult):
            _check_size(left, right)
        elif isinstance(node.op, ast.Mod) and isinstance(left, str):
            _check_format(left, right)
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
        target = self.visit(node.value)
        if isinstance(target, Fields):
            if node.attr not in target:
                raise ExpressionError(f"no field '{node.attr}'; fields: {', '.join(target)}")
            return target[node.attr]
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
            _check_method(target, func.attr, args)
            return getattr(target, func.attr)(*args)
        function = self.visit(func)
        if not callable(function):
            raise ExpressionError(f"'{ast.unparse(func)}' is not a function")
        _check_call(function, args)
        return function(*args)


def _too_large(what: str) -> ExpressionError:
    return ExpressionError(f"{what} would be too large (limits: integers of {MAX_INT_BITS} "
                           f"bits, strings and lists of {MAX_SIZE:,} items)")


def _checked(value: Any) -> Any:
    """Every value an expression makes stays within the limits."""
    if isinstance(value, int) and not isinstance(value, bool) and \
            value.bit_length() > MAX_INT_BITS:
        raise _too_large("the integer")
    if isinstance(value, str | list | tuple) and len(value) > MAX_SIZE:
        raise _too_large("the result")
    return value


def _bits(value: Any) -> float:
    """log2 of |value| for a number (0 for 0 and for what is not a number)."""
    if isinstance(value, bool) or not isinstance(value, int | float) or value == 0:
        return 0.0
    if isinstance(value, int):
        return math.log2(abs(value))  # exact enough for any size of integer
    return math.log2(abs(value)) if math.isfinite(value) else 0.0


def _check_power(base: Any, exponent: Any) -> None:
    if isinstance(base, int) and isinstance(exponent, int) and exponent > 0 and \
            abs(base) > 1 and _bits(base) * exponent > MAX_INT_BITS:
        shown = str(base) if _bits(base) < 64 else f"(an integer of {base.bit_length()} bits)"
        raise _too_large(f"{shown} ** {exponent}")


def _check_size(left: Any, right: Any) -> None:
    for seq, count in ((left, right), (right, left)):
        sized = isinstance(seq, str | list | tuple) and isinstance(count, int)
        if sized and len(seq) * count > MAX_SIZE:
            raise _too_large("the result")


def _check_format(template: str, values: Any) -> None:
    """%-formatting: no width or precision past MAX_WIDTH, and no `*` (a width from the
    values)."""
    for match in _FORMAT_SPEC.finditer(template):
        for number in match.groups():
            if number == "*":
                raise ExpressionError("'*' widths are not allowed in $(eval) formatting")
            if number and int(number) > MAX_WIDTH:
                raise ExpressionError(f"the width {number} is past the limit of {MAX_WIDTH}")


def _check_method(target: str, name: str, args: list[Any]) -> None:
    size = len(target)
    if name == "zfill" and args and isinstance(args[0], int):
        size = max(size, args[0])
    elif name == "replace" and len(args) >= 2 and all(isinstance(a, str) for a in args[:2]):
        old, new = args[0], args[1]
        count = size + 1 if not old else target.count(old)
        if len(args) > 2 and isinstance(args[2], int) and args[2] >= 0:
            count = min(count, args[2])
        size += count * max(0, len(new) - len(old))
    elif name == "join" and args and isinstance(args[0], list | tuple):
        parts = args[0]
        size = sum(len(p) for p in parts if isinstance(p, str)) + size * max(0, len(parts) - 1)
    if size > MAX_SIZE:
        raise _too_large("the string")


def _check_call(function: Any, args: list[Any]) -> None:
    """Math functions whose result (or work) grows past the limits with their arguments."""
    ints = [a for a in args if isinstance(a, int) and not isinstance(a, bool)]
    if function is math.factorial and ints:
        n = ints[0]
        if n > 0 and math.lgamma(n + 1) / math.log(2) > MAX_INT_BITS:
            raise _too_large(f"factorial({n})")
    elif function in (math.comb, math.perm) and len(ints) >= 1:
        n = ints[0]
        if n > 0 and math.lgamma(n + 1) / math.log(2) > MAX_INT_BITS and \
                not (len(ints) == 2 and (ints[1] <= 2 or ints[1] >= n - 2)):
            raise _too_large(f"{function.__name__}({', '.join(map(str, ints))})")
    elif function is math.prod and args and isinstance(args[0], list | tuple):
        if sum(_bits(v) for v in args[0]) > MAX_INT_BITS:
            raise _too_large("the product")
    elif function is math.lcm and sum(_bits(v) for v in ints) > MAX_INT_BITS:
        raise _too_large("the least common multiple")
    elif function is round and len(ints) == 2 and abs(ints[1]) > MAX_WIDTH:
        raise ExpressionError(f"round(): {ints[1]} digits is past the limit of {MAX_WIDTH}")

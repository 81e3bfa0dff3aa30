"""Boolean logic on text: `not`, `and`, `or`, `any`, `all`, `equals`, `not-equals`, `if`.

Operands must read as true/false/1/0. `equals` compares as booleans when both sides are
booleans, as numbers when both are numbers, else as text. Results are `true`/`false`.
"""

from __future__ import annotations

from typing import ClassVar

from launcher.description.condition import evaluate_condition_text
from launcher.description.substitution import (
    Substitution,
    Text_,
    describe_text,
    perform_text,
    substitution,
)
from launcher.errors import Location, SubstitutionError
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


def _bool(sub: Substitution, context: LaunchContext, text: Text_) -> bool:
    try:
        return evaluate_condition_text(perform_text(context, text), f"$({sub.names[0]})")
    except SubstitutionError as exc:
        raise exc.at(sub.where) from None


def _text(value: bool) -> str:
    return "true" if value else "false"


@substitution("not")
@dataclass(frozen=True)
class NotSubstitution(Substitution):
    """`true` when VALUE is false, else `false`."""

    value: Text_

    def perform(self, context: LaunchContext) -> str:
        return _text(not _bool(self, context, self.value))


@dataclass(frozen=True)
class _Connective(Substitution):
    """Two truths joined (`and`, `or`)."""

    left: Text_
    right: Text_


@substitution("and")
@dataclass(frozen=True)
class AndSubstitution(_Connective):
    """`true` when both are true."""

    def perform(self, context: LaunchContext) -> str:
        return _text(_bool(self, context, self.left) and _bool(self, context, self.right))


@substitution("or")
@dataclass(frozen=True)
class OrSubstitution(_Connective):
    """`true` when either is true."""

    def perform(self, context: LaunchContext) -> str:
        return _text(_bool(self, context, self.left) or _bool(self, context, self.right))


@dataclass(frozen=True)
class _Variadic(Substitution):
    values: tuple[Text_, ...] = ()

    @classmethod
    def from_args(cls, args: list[Text_], where: Location | None) -> Substitution:
        return cls(tuple(args), where=where)

    def describe(self) -> str:
        return f"$({self.names[0]} {' '.join(describe_text(v) for v in self.values)})"


@substitution("any")
@dataclass(frozen=True)
class AnySubstitution(_Variadic):
    """`true` when any of the values is true (as many as given)."""

    def perform(self, context: LaunchContext) -> str:
        return _text(any(_bool(self, context, v) for v in self.values))


@substitution("all")
@dataclass(frozen=True)
class AllSubstitution(_Variadic):
    """`true` when every value is true (as many as given)."""

    def perform(self, context: LaunchContext) -> str:
        return _text(all(_bool(self, context, v) for v in self.values))


def _typed(text: str) -> object:
    low = text.strip().lower()
    if low in ("true", "false"):
        return low == "true"
    try:
        return float(text)
    except ValueError:
        return text


def texts_equal(left: str, right: str) -> bool:
    a, b = _typed(left), _typed(right)
    if type(a) is type(b):
        return a == b
    return left == right


@substitution("equals")
@dataclass(frozen=True)
class EqualsSubstitution(Substitution):
    """`true` when the two are equal: as booleans when both are, as numbers when both are,
    else as text."""

    left: Text_
    right: Text_
    _negated: ClassVar[bool] = False  # (not-equals)

    def perform(self, context: LaunchContext) -> str:
        equal = texts_equal(perform_text(context, self.left), perform_text(context, self.right))
        return _text(equal != self._negated)


@substitution("not-equals")
@dataclass(frozen=True)
class NotEqualsSubstitution(EqualsSubstitution):
    """The opposite of `equals` (launch's is an EqualsSubstitution too)."""

    _negated = True


@substitution("if")
@dataclass(frozen=True)
class IfElseSubstitution(Substitution):
    """`$(if COND THEN [ELSE])`: THEN when COND is true, else ELSE (or empty)."""

    condition: Text_
    if_value: Text_
    else_value: Text_ | None = None

    def perform(self, context: LaunchContext) -> str:
        if _bool(self, context, self.condition):
            return perform_text(context, self.if_value)
        return "" if self.else_value is None else perform_text(context, self.else_value)

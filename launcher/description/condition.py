"""Conditions on actions, as launch has them: `if` / `unless` text (true, false, 1 or 0 in any
case), a launch configuration's value, or any predicate of the context.

`Condition` is launch.Condition (a user's own subclass overrides `evaluate`); the frontends'
`if=` / `unless=` build TextCondition.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.description.fields import Kind, attr
from launcher.description.substitution import Text_, describe_text, perform_text, to_text
from launcher.errors import Location, SubstitutionError
from launcher.runtime.context import LaunchContext


def evaluate_condition_text(text: str, what: str = "condition") -> bool:
    low = text.strip().lower()
    if low in ("true", "1"):
        return True
    if low in ("false", "0"):
        return False
    raise SubstitutionError(f"{what}: expected true, false, 1 or 0, got '{text}'")


class Condition:
    """launch.Condition: holds when `predicate(context)` is true (never without one)."""

    where: Location | None = None

    def __init__(self, *, predicate: Callable[[LaunchContext], bool] | None = None) -> None:
        self._predicate = predicate

    def evaluate(self, context: LaunchContext) -> bool:
        return False if self._predicate is None else bool(self._predicate(context))

    def describe(self) -> str:
        return repr(self)


class TextCondition(Condition):
    """`if=` / `unless=`: the text, substitutions done, must be true, false, 1 or 0."""

    def __init__(self, text: Text_, negate: bool = False, where: Location | None = None) -> None:
        super().__init__()
        self.text, self.negate, self.where = text, negate, where

    def evaluate(self, context: LaunchContext) -> bool:
        what = "unless" if self.negate else "if"
        try:
            value = evaluate_condition_text(perform_text(context, self.text), what)
        except SubstitutionError as exc:
            raise exc.at(self.where) from None
        return value != self.negate

    def describe(self) -> str:
        return f"{'unless' if self.negate else 'if'}={describe_text(self.text)}"


class IfCondition(TextCondition):
    """launch.conditions.IfCondition(predicate_expression)."""

    def __init__(self, predicate_expression: Any) -> None:
        super().__init__(to_text(predicate_expression))


class UnlessCondition(TextCondition):
    """launch.conditions.UnlessCondition(predicate_expression)."""

    def __init__(self, predicate_expression: Any) -> None:
        super().__init__(to_text(predicate_expression), negate=True)


class LaunchConfigurationEquals(Condition):
    """launch.conditions.LaunchConfigurationEquals: the configuration's value is the expected
    text (None: the configuration is not set). launch deprecates it for EqualsSubstitution."""

    negate = False

    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        super().__init__()
        self.name = launch_configuration_name
        self.expected = None if expected_value is None else to_text(expected_value)

    def evaluate(self, context: LaunchContext) -> bool:
        value = context.configurations.get(self.name)
        expected = None if self.expected is None else perform_text(context, self.expected)
        return (value == expected) != self.negate


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    negate = True


def if_attr(**spec: Any) -> Any:
    """The declared `only_if` field of an entry, which `entry_applies` reads: roslaunch's if=
    on a node's child, unless `spec` spells or documents it otherwise."""
    return attr(Kind.TEXT, **{"doc": "roslaunch's if= on a node's child: the entry holds only "
                                     "when true.", **spec})


def unless_attr(**spec: Any) -> Any:
    """The declared `only_unless` field of an entry: roslaunch's unless= on a node's child."""
    return attr(Kind.TEXT, **{"doc": "roslaunch's unless= on a node's child.", **spec})


def entry_applies(context: LaunchContext, entry: object) -> bool:
    """Whether a node's entry (env, remap, param; a composable node) holds: roslaunch takes
    if= and unless= on a node's children too, launch_ros on a composable node (`only_if`,
    `only_unless`)."""
    for field, negate in (("only_if", False), ("only_unless", True)):
        text = getattr(entry, field, None)
        if text is not None and not TextCondition(text, negate).evaluate(context):
            return False
    return True

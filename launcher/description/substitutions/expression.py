"""`$(eval EXPR)`: a restricted expression (see safe_expression), never Python's eval.

As in roslaunch, the expression may read the launch's arguments: `arg('x')`, or `x` itself
when no other name is spelled so (their values are text, as roslaunch gives them)."""

from __future__ import annotations

from collections.abc import Callable

from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@substitution("eval")
@dataclass(frozen=True)
class PythonExpression(Substitution):
    """The value of an expression as text (`True`/`False` for booleans, as ROS 2 gives)."""

    expression: Text_

    def perform(self, context: LaunchContext) -> str:
        from launcher.description.safe_expression import ExpressionError, evaluate  # (ast)

        text = perform_text(context, self.expression)
        try:
            return str(evaluate(text, _arguments(context, str)))
        except ExpressionError as exc:
            raise self.fail(f"$(eval '{text}'): {exc}") from None


def _arguments(context: LaunchContext, typed: Callable[[str], object]) -> dict[str, object]:
    """The launch's arguments for an expression, each `typed`: by bare name (those spelled
    as names), and as `arg('x')`."""
    def arg(name: str) -> object:
        from launcher.description.safe_expression import ExpressionError

        if name not in context.configurations:
            raise ExpressionError(f"arg('{name}'): no launch argument '{name}'")
        return typed(context.configurations[name])

    return {**{k: typed(v) for k, v in context.configurations.items()
               if isinstance(v, str) and k.isidentifier()}, "arg": arg}


@substitution("roslaunch_eval")
@dataclass(frozen=True)
class RoslaunchExpression(Substitution):
    """roslaunch's `$(eval EXPRESSION)` (a ROS 1 file's; the frontend names it so): the
    names roslaunch's eval gives are there, the launch's arguments typed as roslaunch types
    an untyped value (by bare name, or `arg('x')`), `anon()`, `dirname()`, `env()`,
    `optenv()`, `find()`, true/false and math's names, in the same restricted expression."""

    expression: Text_

    def perform(self, context: LaunchContext) -> str:
        from launcher.description.parameters import roslaunch_value
        from launcher.description.safe_expression import ExpressionError, evaluate
        from launcher.description.substitution import Text
        from launcher.description.substitutions.configuration import AnonName
        from launcher.description.substitutions.environment import RoslaunchEnvironmentVariable
        from launcher.description.substitutions.files import ThisLaunchFileDir
        from launcher.description.substitutions.packages import FindPackageShare

        text = perform_text(context, self.expression)
        if "__" in text:  # as roslaunch refuses it
            raise self.fail(f"$(eval {text}): an expression may not hold '__'")

        def run(substitution: Substitution) -> str:
            return substitution.perform(context)

        names: dict[str, object] = {
            **_arguments(context, lambda value: roslaunch_value(value, "auto", "")),
            "true": True, "false": False, "True": True, "False": False,
            "anon": lambda name: run(AnonName((Text(name),))),
            "dirname": lambda: run(ThisLaunchFileDir()),
            "env": lambda name: run(RoslaunchEnvironmentVariable((Text(name),))),
            "optenv": lambda name, default="": run(RoslaunchEnvironmentVariable(
                (Text(name),), (Text(default),))),
            "find": lambda package: run(FindPackageShare((Text(package),))),
        }
        try:
            return str(evaluate(text, names))
        except (ExpressionError, TypeError) as exc:  # (TypeError: a call's arguments)
            raise self.fail(f"$(eval {text}): {exc}") from None

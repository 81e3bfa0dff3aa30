"""`$(eval EXPR)`: a restricted expression (see safe_expression), never Python's eval.

As in roslaunch, the expression may read the launch's arguments: `arg('x')`, or `x` itself
when no other name is spelled so (their values are text, as roslaunch gives them)."""

from __future__ import annotations

from launcher.description.safe_expression import ExpressionError, evaluate
from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@substitution("eval")
@dataclass(frozen=True)
class PythonExpression(Substitution):
    """The value of an expression as text (`True`/`False` for booleans, as ROS 2 gives)."""

    expression: Text_

    def perform(self, context: LaunchContext) -> str:
        text = perform_text(context, self.expression)
        arguments = {k: v for k, v in context.configurations.items()
                     if isinstance(v, str) and k.isidentifier()}

        def arg(name: str) -> str:
            if name not in context.configurations:
                raise ExpressionError(f"arg('{name}'): no launch argument '{name}'")
            return context.configurations[name]

        try:
            return str(evaluate(text, {**arguments, "arg": arg}))
        except ExpressionError as exc:
            raise self.fail(f"$(eval '{text}'): {exc}") from None

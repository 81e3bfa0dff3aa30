"""`$(eval EXPR)`: a restricted expression (see safe_expression), never Python's eval."""

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
        try:
            return str(evaluate(text))
        except ExpressionError as exc:
            raise self.fail(f"$(eval '{text}'): {exc}") from None

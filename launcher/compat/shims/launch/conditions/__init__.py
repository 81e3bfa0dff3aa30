"""launch.conditions (launcher.api)."""

from launcher.api import (
    IfCondition,
    LaunchConfigurationEquals,
    LaunchConfigurationNotEquals,
    UnlessCondition,
)
from launcher.description.condition import evaluate_condition_text


class InvalidConditionExpressionError(ValueError):
    """A condition's text that is not one of the valid ones (true, false, 1, 0)."""

    def __init__(self, expression: str, unexpanded_expression: object,
                 valid_expressions: object) -> None:
        super().__init__(f"invalid condition expression '{expression}' (from "
                         f"{unexpanded_expression}): expected one of {valid_expressions}")


def evaluate_condition_expression(context: object, expression: object) -> bool:
    """The text's truth (true, false, 1 or 0, any case), substitutions done."""
    from launcher.description.substitution import perform_text, to_text
    from launcher.errors import SubstitutionError

    text = perform_text(context, to_text(expression))  # type: ignore[arg-type]
    try:
        return evaluate_condition_text(text)
    except SubstitutionError:
        raise InvalidConditionExpressionError(text, expression,
                                              ["true", "false", "1", "0"]) from None


__all__ = ["IfCondition", "InvalidConditionExpressionError", "LaunchConfigurationEquals",
           "LaunchConfigurationNotEquals", "UnlessCondition", "evaluate_condition_expression"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)

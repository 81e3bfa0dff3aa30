"""rospy.impl.validators: checks of API parameters."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class ParameterInvalid(Exception):
    """A parameter's value is not valid."""

    def __init__(self, message: str) -> None:
        Exception.__init__(self, message)


def non_empty(param_name: str) -> Callable[[Any, str], Any]:
    """A validator of values that are not empty."""
    def validator(param_value: Any, caller_id: str) -> Any:
        if not param_value:
            raise ParameterInvalid(f"ERROR: parameter [{param_name}] must be specified and "
                                   "non-empty")
        return param_value
    return validator

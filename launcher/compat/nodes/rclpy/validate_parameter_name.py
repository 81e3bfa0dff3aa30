"""rclpy.validate_parameter_name."""

from __future__ import annotations

from typing import Literal

from rclpy.exceptions import InvalidParameterException


def validate_parameter_name(name: str) -> Literal[True]:
    """True when `name` is a valid parameter name (any non-empty one, as rclpy checks);
    else InvalidParameterException."""
    if not name:
        raise InvalidParameterException(name)
    return True

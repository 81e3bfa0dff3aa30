"""rclpy.validate_full_topic_name."""

from __future__ import annotations

from typing import Literal

from rclpy import name_rules
from rclpy.exceptions import InvalidServiceNameException, InvalidTopicNameException


def validate_full_topic_name(name: str, *, is_service: bool = False) -> Literal[True]:
    """True when `name` is a valid fully qualified (expanded) topic or service name; else
    InvalidTopicNameException (InvalidServiceNameException when `is_service`)."""
    fault = name_rules.full_topic_name(name)
    if fault is None:
        return True
    if is_service:
        raise InvalidServiceNameException(name, *fault)
    raise InvalidTopicNameException(name, *fault)

"""rclpy.validate_topic_name."""

from __future__ import annotations

from typing import Literal

from rclpy import name_rules
from rclpy.exceptions import InvalidServiceNameException, InvalidTopicNameException

TOPIC_SEPARATOR_STRING = "/"


def validate_topic_name(name: str, *, is_service: bool = False) -> Literal[True]:
    """True when `name` is a valid topic or service name before expansion (relative, `~`,
    substitutions allowed); else InvalidTopicNameException (InvalidServiceNameException when
    `is_service`)."""
    fault = name_rules.topic_name(name)
    if fault is None:
        return True
    if is_service:
        raise InvalidServiceNameException(name, *fault)
    raise InvalidTopicNameException(name, *fault)

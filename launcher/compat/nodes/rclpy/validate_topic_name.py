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
    return topic_verdict(name, name_rules.topic_name(name), is_service)


def topic_verdict(name: str, fault: tuple[str, int] | None,
                  is_service: bool) -> Literal[True]:
    """True without a fault; else the topic's (or service's) name exception for it."""
    if fault is None:
        return True
    if is_service:
        raise InvalidServiceNameException(name, *fault)
    raise InvalidTopicNameException(name, *fault)

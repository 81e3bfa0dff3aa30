"""rclpy.validate_full_topic_name."""

from __future__ import annotations

from typing import Literal

from rclpy import name_rules
from rclpy.exceptions import (  # noqa: F401 - as rclpy's module offers them
    InvalidServiceNameException,
    InvalidTopicNameException,
)
from rclpy.validate_topic_name import topic_verdict


def validate_full_topic_name(name: str, *, is_service: bool = False) -> Literal[True]:
    """True when `name` is a valid fully qualified (expanded) topic or service name; else
    InvalidTopicNameException (InvalidServiceNameException when `is_service`)."""
    return topic_verdict(name, name_rules.full_topic_name(name), is_service)

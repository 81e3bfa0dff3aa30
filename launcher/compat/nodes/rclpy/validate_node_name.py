"""rclpy.validate_node_name."""

from __future__ import annotations

from typing import Literal

from rclpy import name_rules
from rclpy.exceptions import InvalidNodeNameException


def validate_node_name(node_name: str) -> Literal[True]:
    """True when `node_name` is a valid node name; else InvalidNodeNameException."""
    fault = name_rules.node_name(node_name)
    if fault is None:
        return True
    raise InvalidNodeNameException(node_name, *fault)

"""rclpy.validate_namespace."""

from __future__ import annotations

from typing import Literal

from rclpy import name_rules
from rclpy.exceptions import InvalidNamespaceException


def validate_namespace(namespace: str) -> Literal[True]:
    """True when `namespace` is valid: absolute and non-empty (unlike the Node constructor,
    which takes "" and relative ones); else InvalidNamespaceException."""
    fault = name_rules.full_topic_name(namespace, "namespace")
    if fault is None:
        return True
    raise InvalidNamespaceException(namespace, *fault)

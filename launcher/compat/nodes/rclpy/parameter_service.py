"""rclpy.parameter_service.ParameterService: a node's parameter services
(`~/list_parameters`, `~/get_parameters`, `~/set_parameters`, `~/describe_parameters`).

launcher's bus node serves them itself when the node starts with start_parameter_services
(the default), answering through the rclpy node's checks; a ParameterService made for a node
that started without them starts them then.
"""

from __future__ import annotations

from typing import Any

from launcher.bus.parameters import serve
from rclpy.exceptions import (  # noqa: F401 - as rclpy's module offers them
    ParameterNotDeclaredException,
    ParameterUninitializedException,
)
from rclpy.parameter import Parameter  # noqa: F401
from rclpy.validate_topic_name import TOPIC_SEPARATOR_STRING  # noqa: F401

SERVICES = ("list_parameters", "get_parameters", "set_parameters", "describe_parameters")


class ParameterService:
    """The parameter services of `node` (started now if the node has none)."""

    def __init__(self, node: Any) -> None:
        self._node = node
        if not self.serving(node):
            serve(node.handle)

    @staticmethod
    def serving(node: Any) -> bool:
        """Whether `node` answers its parameter services already."""
        mine = {name for name, _ in node.get_service_names_and_types_by_node(
            node.get_name(), node.get_namespace())}
        base = node.get_fully_qualified_name().rstrip("/")
        return all(f"{base}/{name}" in mine for name in SERVICES)

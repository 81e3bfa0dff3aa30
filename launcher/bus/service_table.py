"""A table of services on a node: each row a service's name, its type in one interface
package, and the callback that answers it (the sim's world services, ROS's
simulation_interfaces, gazebo_ros's API)."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from launcher.bus.node import Node
from launcher.bus.services import Service

Row = tuple[str, str, Callable[[Any, Any], Any]]  # (name, type, callback)


def create_services(node: Node, package: str, rows: Iterable[Row],
                    namespace: str = "~") -> list[Service]:
    """Each row's service on `node`: `<package>/srv/<type>` at `<namespace>/<name>`."""
    return [node.create_service(f"{package}/srv/{type_name}", f"{namespace}/{name}", callback)
            for name, type_name, callback in rows]

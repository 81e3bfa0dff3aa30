"""A node's announcements of its parameter changes on `/parameter_events`
(rcl_interfaces/msg/ParameterEvent), as rcl makes them: what was declared (`new_parameters`),
set (`changed_parameters`) and undeclared (`deleted_parameters`), stamped with the node's
clock and named by its full name. ParameterEventHandler listens to them.

launcher's node starts announcing at its first change after start (its publisher is made
then, to keep node start light): what it declares while starting is not announced.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from rcl_interfaces.msg import ParameterEvent

from rclpy.publisher import Publisher
from rclpy.qos import qos_profile_parameter_events, to_launcher

TOPIC = "/parameter_events"


class ParameterEvents:
    """The publisher of one node's parameter events."""

    def __init__(self, node: Any) -> None:
        self._node = node
        # on the bus node itself: rcl's publisher, not one of the node's `publishers`
        bus = node.handle.create_publisher("rcl_interfaces/msg/ParameterEvent", TOPIC,
                                           to_launcher(qos_profile_parameter_events))
        self._publisher = Publisher(bus, ParameterEvent, TOPIC, qos_profile_parameter_events,
                                    None)

    def announce(self, *, new: Iterable[Any] = (), changed: Iterable[Any] = (),
                 deleted: Iterable[Any] = ()) -> None:
        """Publish one event with these rclpy Parameters."""
        event = ParameterEvent(
            stamp=self._node.get_clock().now().to_msg(),
            node=self._node.get_fully_qualified_name(),
            new_parameters=[p.to_parameter_msg() for p in new],
            changed_parameters=[p.to_parameter_msg() for p in changed],
            deleted_parameters=[p.to_parameter_msg() for p in deleted])
        self._publisher.publish(event)

"""What the world and its plugins use of the bus: the `Transport` protocol, and the one that
speaks over a real node (`BusTransport`, with fast message construction). Unit tests hand the
world a recording stand-in that satisfies the same protocol.

The sim's topics and services are on the simulator's own side (keys.SIM), apart from the ROS
graph as gz-transport is from ROS; `ros=True` puts one on the ROS graph instead, as gazebo_ros's
classic plugins do."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, Protocol, runtime_checkable

from launcher.bus import keys
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.bus.types import registry
from launcher.bus.wire import split_time


@runtime_checkable
class Transport(Protocol):
    logger: Any

    def publisher(self, type_name: str, topic: str, qos: Any = 10, ros: bool = False) -> Any: ...

    def subscribe(self, type_name: str, topic: str, callback: Callable[[Any], None],
                  ros: bool = False) -> Any: ...

    def message(self, type_name: str, **fields: Any) -> Any: ...

    def header(self, seconds: float, frame_id: str) -> Any: ...

    def vector(self, x: float, y: float, z: float) -> Any: ...

    def pose(self, x: float, y: float, z: float, quat: Sequence[float]) -> Any: ...


class BusTransport:
    """What the world and its plugins use of the bus, with fast message construction."""

    def __init__(self, node: Node) -> None:
        self.node = node
        self.logger = node.get_logger()
        self._classes: dict[str, type] = {}

    def cls(self, type_name: str) -> type:
        found = self._classes.get(type_name)
        if found is None:
            found = self._classes[type_name] = registry().message_class(type_name)
        return found

    def message(self, type_name: str, **fields: Any) -> Any:
        return self.cls(type_name)(**fields)

    def publisher(self, type_name: str, topic: str, qos: QoS | int = 10,
                  ros: bool = False) -> Any:
        return self.node.create_publisher(type_name, topic, qos, space=keys.ROS if ros else None)

    def subscribe(self, type_name: str, topic: str, callback: Any, ros: bool = False) -> Any:
        return self.node.create_subscription(type_name, topic, callback,
                                             space=keys.ROS if ros else None)

    def time(self, seconds: float) -> Any:
        sec, nanosec = split_time(seconds)
        return self.cls("builtin_interfaces/msg/Time")(sec=sec, nanosec=nanosec)

    def header(self, seconds: float, frame_id: str) -> Any:
        return self.cls("std_msgs/msg/Header")(stamp=self.time(seconds), frame_id=frame_id)

    def vector(self, x: float, y: float, z: float) -> Any:
        return self.cls("geometry_msgs/msg/Vector3")(x=float(x), y=float(y), z=float(z))

    def pose(self, x: float, y: float, z: float, quat: Sequence[float]) -> Any:
        """`quat` in ROS order (x, y, z, w)."""
        point = self.cls("geometry_msgs/msg/Point")(x=float(x), y=float(y), z=float(z))
        q = self.cls("geometry_msgs/msg/Quaternion")(x=float(quat[0]), y=float(quat[1]),
                                                     z=float(quat[2]), w=float(quat[3]))
        return self.cls("geometry_msgs/msg/Pose")(position=point, orientation=q)

"""rclpy.topic_endpoint_info: what the graph says of one publisher or subscription."""

from __future__ import annotations

from collections.abc import Callable
from enum import IntEnum
from typing import Any

from rclpy.properties import stored
from rclpy.qos import QoSHistoryPolicy, QoSPresetProfiles, QoSProfile
from rclpy.type_hash import TypeHash, TypeHashDictionary  # noqa: F401 - as rclpy offers it


class TopicEndpointTypeEnum(IntEnum):
    INVALID = 0
    PUBLISHER = 1
    SUBSCRIPTION = 2


def _made(kind: type) -> Callable[[Any], Any]:
    """A `kind` as it is, or made of its fields' dictionary (as rclpy's C layer gives it)."""
    return lambda value: value if isinstance(value, kind) else kind(**value)


class TopicEndpointInfo:
    """A topic endpoint: its node, type, kind, gid and QoS profile."""

    __slots__ = ("_node_name", "_node_namespace", "_topic_type", "_topic_type_hash",
                 "_endpoint_type", "_endpoint_gid", "_qos_profile")

    def __init__(self, node_name: str = "", node_namespace: str = "", topic_type: str = "",
                 topic_type_hash: TypeHash = TypeHash(),  # noqa: B008 - rclpy's default
                 endpoint_type: TopicEndpointTypeEnum = TopicEndpointTypeEnum.INVALID,
                 endpoint_gid: list[int] = [],  # noqa: B006 - rclpy's default (copied)
                 qos_profile: QoSProfile = QoSPresetProfiles.UNKNOWN.value) -> None:
        self._node_name, self._node_namespace, self._topic_type = \
            node_name, node_namespace, topic_type
        self.topic_type_hash = topic_type_hash
        self.endpoint_type = endpoint_type
        self.endpoint_gid = list(endpoint_gid)
        self.qos_profile = qos_profile

    node_name = stored("_node_name", "The endpoint's node's name.")
    node_namespace = stored("_node_namespace", "The endpoint's node's namespace.")
    topic_type = stored("_topic_type", "The topic's type name (`std_msgs/msg/String`).")
    topic_type_hash = stored("_topic_type_hash", "The topic type's hash.", _made(TypeHash))
    endpoint_type = stored("_endpoint_type", "PUBLISHER or SUBSCRIPTION.",
                           TopicEndpointTypeEnum)
    endpoint_gid = stored("_endpoint_gid", "The endpoint's global id, as bytes' values.", list)
    qos_profile = stored("_qos_profile", "The endpoint's QoS profile.", _made(QoSProfile))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, TopicEndpointInfo) and all(
            getattr(self, s) == getattr(other, s) for s in self.__slots__)

    __hash__ = None  # type: ignore[assignment]

    def __str__(self) -> str:
        qos = self.qos_profile
        depth = qos.history.name if qos.history != QoSHistoryPolicy.KEEP_LAST else \
            f"{qos.history.name} ({qos.depth})"
        return "\n".join([
            f"Node name: {self.node_name}", f"Node namespace: {self.node_namespace}",
            f"Topic type: {self.topic_type}", f"Topic type hash: {self.topic_type_hash}",
            f"Endpoint type: {self.endpoint_type.name}",
            f"GID: {'.'.join(format(x, '02x') for x in self.endpoint_gid)}", "QoS profile:",
            f"  Reliability: {qos.reliability.name}", f"  History (Depth): {depth}",
            f"  Durability: {qos.durability.name}", f"  Lifespan: {qos.lifespan}",
            f"  Deadline: {qos.deadline}", f"  Liveliness: {qos.liveliness.name}",
            f"  Liveliness lease duration: {qos.liveliness_lease_duration}"])

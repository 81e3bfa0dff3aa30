"""rclpy.topic_endpoint_info: what the graph says of one publisher or subscription."""

from __future__ import annotations

from enum import IntEnum
from typing import Any

from rclpy.qos import QoSHistoryPolicy, QoSPresetProfiles, QoSProfile
from rclpy.type_hash import TypeHash, TypeHashDictionary


class TopicEndpointTypeEnum(IntEnum):
    INVALID = 0
    PUBLISHER = 1
    SUBSCRIPTION = 2


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

    node_name = property(lambda self: self._node_name,
                         lambda self, value: setattr(self, "_node_name", value),
                         doc="The endpoint's node's name.")
    node_namespace = property(lambda self: self._node_namespace,
                              lambda self, value: setattr(self, "_node_namespace", value),
                              doc="The endpoint's node's namespace.")
    topic_type = property(lambda self: self._topic_type,
                          lambda self, value: setattr(self, "_topic_type", value),
                          doc="The topic's type name (`std_msgs/msg/String`).")
    endpoint_gid = property(lambda self: self._endpoint_gid,
                            lambda self, value: setattr(self, "_endpoint_gid", list(value)),
                            doc="The endpoint's global id, as bytes' values.")

    @property
    def topic_type_hash(self) -> TypeHash:
        """The topic type's hash."""
        return self._topic_type_hash

    @topic_type_hash.setter
    def topic_type_hash(self, value: TypeHash | TypeHashDictionary) -> None:
        self._topic_type_hash = value if isinstance(value, TypeHash) else TypeHash(**value)

    @property
    def endpoint_type(self) -> TopicEndpointTypeEnum:
        """PUBLISHER or SUBSCRIPTION."""
        return self._endpoint_type

    @endpoint_type.setter
    def endpoint_type(self, value: Any) -> None:
        self._endpoint_type = TopicEndpointTypeEnum(value)

    @property
    def qos_profile(self) -> QoSProfile:
        """The endpoint's QoS profile."""
        return self._qos_profile

    @qos_profile.setter
    def qos_profile(self, value: QoSProfile | dict[str, Any]) -> None:
        self._qos_profile = value if isinstance(value, QoSProfile) else QoSProfile(**value)

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

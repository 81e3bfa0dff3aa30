"""rclpy.qos: profiles and policies, mapped onto launcher's QoS (depth, reliable, transient
local). Deadline, lifespan and liveliness are kept on the profile but not enforced."""

from __future__ import annotations

from enum import IntEnum
from typing import Any

from launcher.bus.qos import KEEP_ALL_DEPTH, PROFILES, QoS


class HistoryPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4
    BEST_AVAILABLE = 5


# the old names
QoSHistoryPolicy = HistoryPolicy
QoSReliabilityPolicy = ReliabilityPolicy
QoSDurabilityPolicy = DurabilityPolicy
QoSLivelinessPolicy = LivelinessPolicy

class InvalidQoSProfileException(Exception):
    def __init__(self, *args: Any) -> None:
        Exception.__init__(self, "Invalid QoSProfile", *args)


class QoSProfile:
    __slots__ = ("history", "depth", "reliability", "durability", "lifespan", "deadline",
                 "liveliness", "liveliness_lease_duration",
                 "avoid_ros_namespace_conventions")

    def __init__(self, **kwargs: Any) -> None:
        unknown = [k for k in kwargs if k not in self.__slots__]
        if unknown:
            raise TypeError(f"Invalid arguments passed to constructor: {', '.join(unknown)}")
        if "history" not in kwargs and "depth" not in kwargs:
            raise InvalidQoSProfileException("History and/or depth settings are required.")
        self.history = HistoryPolicy(kwargs.get("history", HistoryPolicy.KEEP_LAST))
        self.depth = int(kwargs.get("depth", 0))
        if self.history == HistoryPolicy.KEEP_LAST and self.depth == 0 and "depth" in kwargs:
            pass
        self.reliability = ReliabilityPolicy(kwargs.get("reliability",
                                                        ReliabilityPolicy.RELIABLE))
        self.durability = DurabilityPolicy(kwargs.get("durability", DurabilityPolicy.VOLATILE))
        self.liveliness = LivelinessPolicy(kwargs.get("liveliness",
                                                      LivelinessPolicy.SYSTEM_DEFAULT))
        from rclpy.duration import Duration

        self.lifespan = kwargs.get("lifespan", Duration())
        self.deadline = kwargs.get("deadline", Duration())
        self.liveliness_lease_duration = kwargs.get("liveliness_lease_duration", Duration())
        self.avoid_ros_namespace_conventions = bool(
            kwargs.get("avoid_ros_namespace_conventions", False))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, QoSProfile) and all(
            getattr(self, s) == getattr(other, s) for s in self.__slots__)

    def __repr__(self) -> str:
        return (f"QoSProfile(history={self.history.name}, depth={self.depth}, "
                f"reliability={self.reliability.name}, durability={self.durability.name})")

    def to_launcher(self) -> QoS:
        """The profile in launcher's bus terms."""
        depth = KEEP_ALL_DEPTH if self.history == HistoryPolicy.KEEP_ALL else max(self.depth, 1)
        return QoS(depth=depth, reliable=self.reliability != ReliabilityPolicy.BEST_EFFORT,
                   transient_local=self.durability == DurabilityPolicy.TRANSIENT_LOCAL)


def to_launcher(qos: Any) -> QoS:
    """What create_publisher/create_subscription take: a depth or a QoSProfile."""
    if isinstance(qos, QoSProfile):
        return qos.to_launcher()
    if isinstance(qos, bool) or not isinstance(qos, int):
        raise TypeError(f"Expected QoSProfile or int, but received {type(qos)!r}")
    if qos < 0:
        raise ValueError("history depth must be greater than or equal to zero")
    return QoS(depth=max(qos, 1))


def _named(name: str, history: HistoryPolicy = HistoryPolicy.KEEP_LAST) -> QoSProfile:
    """rclpy's profile of that name, from the bus's vocabulary (launcher/bus/qos.py)."""
    qos = PROFILES[name]
    return QoSProfile(
        history=history, depth=qos.depth,
        reliability=ReliabilityPolicy.RELIABLE if qos.reliable else ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if qos.transient_local else
        DurabilityPolicy.VOLATILE)


qos_profile_system_default = _named("system_default", HistoryPolicy.SYSTEM_DEFAULT)
qos_profile_sensor_data = _named("sensor_data")
qos_profile_services_default = _named("services_default")
qos_profile_parameters = _named("parameters")
qos_profile_parameter_events = _named("parameter_events")
qos_profile_action_status_default = _named("action_status_default")
qos_profile_unknown = QoSProfile(history=HistoryPolicy.UNKNOWN, depth=0)
qos_profile_rosout_default = _named("rosout_default")

class QoSPresetProfiles(IntEnum):
    SYSTEM_DEFAULT = 0
    SENSOR_DATA = 1
    SERVICES_DEFAULT = 2
    PARAMETERS = 3
    PARAMETER_EVENTS = 4
    ACTION_STATUS_DEFAULT = 5

    @property
    def value(self) -> QoSProfile:  # type: ignore[override]
        """The preset's QoSProfile."""
        return _PRESETS[self.name]

    @classmethod
    def get_from_short_key(cls, name: str) -> QoSProfile:
        """The preset profile of a short name (`sensor_data`, …)."""
        return _PRESETS[name.upper()]


_PRESETS = {"SYSTEM_DEFAULT": qos_profile_system_default,
            "SENSOR_DATA": qos_profile_sensor_data,
            "SERVICES_DEFAULT": qos_profile_services_default,
            "PARAMETERS": qos_profile_parameters,
            "PARAMETER_EVENTS": qos_profile_parameter_events,
            "ACTION_STATUS_DEFAULT": qos_profile_action_status_default}

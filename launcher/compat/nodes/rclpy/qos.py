"""rclpy.qos: profiles and policies, mapped onto launcher's QoS (depth, reliable, transient
local). Deadline, lifespan and liveliness are kept on the profile (and checked by
qos_check_compatible) but not enforced on the bus."""

from __future__ import annotations

from enum import Enum, IntEnum
from typing import Any

from launcher.bus.qos import KEEP_ALL_DEPTH, PROFILES, QoS
from rclpy import qos_compatibility
from rclpy.duration import Duration


class QoSPolicyKind(IntEnum):
    """The kinds of QoS policies a Publisher or Subscription can set (rmw's values)."""

    INVALID = 1 << 0
    DURABILITY = 1 << 1
    DEADLINE = 1 << 2
    LIVELINESS = 1 << 3
    RELIABILITY = 1 << 4
    HISTORY = 1 << 5
    LIFESPAN = 1 << 6
    DEPTH = 1 << 7
    LIVELINESS_LEASE_DURATION = 1 << 8
    AVOID_ROS_NAMESPACE_CONVENTIONS = 1 << 9


def qos_policy_name_from_kind(policy_kind: QoSPolicyKind | int) -> str:
    """The name of a QoSPolicyKind."""
    return QoSPolicyKind(policy_kind).name


class InvalidQoSProfileException(Exception):
    """Raised when constructing a QoSProfile with invalid arguments."""

    def __init__(self, message: str) -> None:
        Exception.__init__(self, f"Invalid QoSProfile: {message}")


class QoSPolicyEnum(IntEnum):
    """Base of the policy enums, with their short (lower case) names."""

    @classmethod
    def short_keys(cls) -> list[str]:
        """The members' names, lower case."""
        return [k.lower() for k in cls.__members__ if not k.startswith("RMW")]

    @classmethod
    def get_from_short_key(cls, name: str) -> int:
        """The value of a member by its short name, case-insensitive."""
        return cls[name.upper()].value

    @property
    def short_key(self) -> str:
        """This member's name, lower case."""
        return self.name.lower()


class HistoryPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(QoSPolicyEnum):
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

# rmw's "match the majority of endpoints" durations (RMW_QOS_*_BEST_AVAILABLE)
DeadlineBestAvailable = Duration(nanoseconds=2**63 - 2)
LivelinessLeaseDurationeBestAvailable = Duration(nanoseconds=2**63 - 2)


class QoSProfile:
    """Quality of service policies. History or depth is required; the rest default to rmw's
    default profile (reliable, volatile, depth 10)."""

    __slots__ = ("history", "depth", "reliability", "durability", "lifespan", "deadline",
                 "liveliness", "liveliness_lease_duration",
                 "avoid_ros_namespace_conventions")

    def __init__(self, history: HistoryPolicy | int | None = None, depth: int | None = None,
                 reliability: ReliabilityPolicy | int | None = None,
                 durability: DurabilityPolicy | int | None = None,
                 lifespan: Duration | None = None, deadline: Duration | None = None,
                 liveliness: LivelinessPolicy | int | None = None,
                 liveliness_lease_duration: Duration | None = None,
                 avoid_ros_namespace_conventions: bool | None = None) -> None:
        if history is None:
            if depth is None:
                raise InvalidQoSProfileException("History and/or depth settings are required.")
            history = HistoryPolicy.KEEP_LAST
        self.history = HistoryPolicy(history)
        if self.history == HistoryPolicy.KEEP_LAST and depth is None:
            raise InvalidQoSProfileException("History set to KEEP_LAST without a depth setting.")
        self.depth = 10 if depth is None else int(depth)
        self.reliability = ReliabilityPolicy(
            ReliabilityPolicy.RELIABLE if reliability is None else reliability)
        self.durability = DurabilityPolicy(
            DurabilityPolicy.VOLATILE if durability is None else durability)
        self.lifespan = lifespan or Duration()
        self.deadline = deadline or Duration()
        self.liveliness = LivelinessPolicy(
            LivelinessPolicy.SYSTEM_DEFAULT if liveliness is None else liveliness)
        self.liveliness_lease_duration = liveliness_lease_duration or Duration()
        self.avoid_ros_namespace_conventions = bool(avoid_ros_namespace_conventions)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, QoSProfile) and all(
            getattr(self, s) == getattr(other, s) for s in self.__slots__)

    __hash__ = None  # type: ignore[assignment] - mutable, as rclpy's

    def __str__(self) -> str:
        return "QoSProfile(" + ", ".join(f"{s}={getattr(self, s)}" for s in self.__slots__) + ")"

    def __repr__(self) -> str:
        return (f"QoSProfile(history={self.history.name}, depth={self.depth}, "
                f"reliability={self.reliability.name}, durability={self.durability.name})")

    def to_launcher(self) -> QoS:
        """The profile in launcher's bus terms."""
        if self.history == HistoryPolicy.KEEP_ALL:
            depth = KEEP_ALL_DEPTH
        elif self.history != HistoryPolicy.KEEP_LAST or self.depth == 0:
            depth = PROFILES["system_default"].depth
        else:
            depth = self.depth
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


def _named(name: str, **more: Any) -> QoSProfile:
    """rmw's profile of that name, from the bus's vocabulary (launcher/bus/qos.py)."""
    qos = PROFILES[name]
    return QoSProfile(
        history=HistoryPolicy.KEEP_LAST, depth=qos.depth,
        reliability=ReliabilityPolicy.RELIABLE if qos.reliable else ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if qos.transient_local else
        DurabilityPolicy.VOLATILE, **more)


qos_profile_unknown = QoSProfile(
    history=HistoryPolicy.UNKNOWN, depth=0, reliability=ReliabilityPolicy.UNKNOWN,
    durability=DurabilityPolicy.UNKNOWN, liveliness=LivelinessPolicy.UNKNOWN)
qos_profile_default = _named("default")
qos_profile_system_default = QoSProfile(
    history=HistoryPolicy.SYSTEM_DEFAULT, depth=0, reliability=ReliabilityPolicy.SYSTEM_DEFAULT,
    durability=DurabilityPolicy.SYSTEM_DEFAULT)
qos_profile_sensor_data = _named("sensor_data")
qos_profile_services_default = _named("services_default")
qos_profile_parameters = _named("parameters")
qos_profile_parameter_events = _named("parameter_events")
qos_profile_best_available = QoSProfile(
    history=HistoryPolicy.KEEP_LAST, depth=PROFILES["best_available"].depth,
    reliability=ReliabilityPolicy.BEST_AVAILABLE, durability=DurabilityPolicy.BEST_AVAILABLE,
    deadline=DeadlineBestAvailable, liveliness=LivelinessPolicy.BEST_AVAILABLE,
    liveliness_lease_duration=LivelinessLeaseDurationeBestAvailable)
qos_profile_action_status_default = _named("action_status_default")
qos_profile_rosout_default = _named("rosout_default", lifespan=Duration(seconds=10))


class QoSPresetProfiles(Enum):
    """The named profiles (equal ones are aliases: SERVICES_DEFAULT is DEFAULT, as rclpy's)."""

    UNKNOWN = qos_profile_unknown
    DEFAULT = qos_profile_default
    SYSTEM_DEFAULT = qos_profile_system_default
    SENSOR_DATA = qos_profile_sensor_data
    SERVICES_DEFAULT = qos_profile_services_default
    PARAMETERS = qos_profile_parameters
    PARAMETER_EVENTS = qos_profile_parameter_events
    ACTION_STATUS_DEFAULT = qos_profile_action_status_default
    BEST_AVAILABLE = qos_profile_best_available
    ROSOUT_DEFAULT = qos_profile_rosout_default

    @classmethod
    def short_keys(cls) -> list[str]:
        """The presets' names, lower case."""
        return [k.lower() for k in cls.__members__ if not k.startswith("RMW")]

    @classmethod
    def get_from_short_key(cls, name: str) -> QoSProfile:
        """The preset profile of a short name (`sensor_data`, …), case-insensitive."""
        return cls[name.upper()].value


class QoSCompatibility(IntEnum):
    """Whether a publisher's and a subscription's profiles match (rmw's values)."""

    OK = 0
    WARNING = 1
    ERROR = 2


def qos_check_compatible(publisher_qos: QoSProfile,
                         subscription_qos: QoSProfile) -> tuple[QoSCompatibility, str]:
    """Whether a publisher and a subscription with these profiles can communicate, and why
    not, by rmw's rules (WARNING where a system default or unknown policy leaves it open)."""
    level, reason = qos_compatibility.check(publisher_qos, subscription_qos)
    return QoSCompatibility(level), reason

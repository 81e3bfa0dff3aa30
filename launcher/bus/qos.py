"""Quality of service: reliability, durability (transient local = latched) and depth, and the
one vocabulary of it that every command, file and API uses: rclpy's named profiles and the
policy names `ros2 topic echo --qos-*`, rosbag2's override files and `topic info -v` speak."""

from __future__ import annotations

from launcher.bus import keys
from launcher.records import dataclass

KEEP_ALL_DEPTH = 1000  # keep_all as the bus keeps it: a queue far deeper than a reader lags

# the policies' names, as ROS 2's command-line tools and rosbag2's YAML write them
HISTORY = ("system_default", "keep_last", "keep_all")
RELIABILITY = ("system_default", "reliable", "best_effort")
DURABILITY = ("system_default", "volatile", "transient_local")


class QoSPolicyError(ValueError):
    """A policy name that is not one of the vocabulary's; the message lists the valid ones."""


@dataclass(frozen=True)
class QoS:
    depth: int = 10
    reliable: bool = True
    transient_local: bool = False  # late subscribers get the last `depth` messages

    def key(self) -> str:
        """The QoS part of a liveliness token, in rmw_zenoh's layout (keys.py)."""
        return keys.qos_key(self.reliable, self.transient_local, self.depth)

    @classmethod
    def from_key(cls, text: str) -> QoS | None:
        """The QoS another node announced (None if its token's QoS part is not one)."""
        found = keys.parse_qos_key(text)
        return None if found is None else cls(found[2], found[0], found[1])

    def with_policies(self, history: str | None = None, depth: int | None = None,
                      reliability: str | None = None, durability: str | None = None) -> QoS:
        """This QoS with the named policies given (None, or system_default: this one's)."""
        chosen_depth = self.depth if depth is None else depth
        if _named(history, HISTORY, "history") == "keep_all":  # depth is keep_last's alone
            chosen_depth = KEEP_ALL_DEPTH
        reliable, latched = self.reliable, self.transient_local
        if _named(reliability, RELIABILITY, "reliability") not in (None, "system_default"):
            reliable = reliability.lower() == "reliable"  # type: ignore[union-attr]
        if _named(durability, DURABILITY, "durability") not in (None, "system_default"):
            latched = durability.lower() == "transient_local"  # type: ignore[union-attr]
        return QoS(depth=chosen_depth, reliable=reliable, transient_local=latched)

    @property
    def reliability_name(self) -> str:
        return "RELIABLE" if self.reliable else "BEST_EFFORT"

    @property
    def durability_name(self) -> str:
        return "TRANSIENT_LOCAL" if self.transient_local else "VOLATILE"


def _named(value: str | None, names: tuple[str, ...], policy: str) -> str | None:
    if value is None:
        return None
    if value.lower() not in names:
        raise QoSPolicyError(f"{policy} is {', '.join(n for n in names)}; got '{value}'")
    return value.lower()


def qos_of(value: QoS | int | None) -> QoS:
    if isinstance(value, QoS):
        return value
    return QoS(depth=value or 10)


SENSOR_DATA = QoS(depth=5, reliable=False)
LATCHED = QoS(depth=1, transient_local=True)

# rclpy's named profiles (rclpy.qos.qos_profile_*), as the bus keeps QoS
PROFILES = {
    "system_default": QoS(depth=10),
    "default": QoS(depth=10),
    "sensor_data": SENSOR_DATA,
    "services_default": QoS(depth=10),
    "parameters": QoS(depth=1000),
    "parameter_events": QoS(depth=1000),
    "action_status_default": LATCHED,
    "rosout_default": QoS(depth=1000, transient_local=True),
    # matches any publisher: reliable and transient local take what each one offers
    "best_available": QoS(depth=10, transient_local=True),
}

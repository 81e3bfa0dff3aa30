"""Quality of service: reliability, durability (transient local = latched) and depth."""

from __future__ import annotations

from launcher.bus import keys
from launcher.records import dataclass


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


def qos_of(value: QoS | int | None) -> QoS:
    if isinstance(value, QoS):
        return value
    return QoS(depth=value or 10)


SENSOR_DATA = QoS(depth=5, reliable=False)
LATCHED = QoS(depth=1, transient_local=True)

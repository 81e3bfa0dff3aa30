"""Quality of service: reliability, durability (transient local = latched) and depth."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class QoS:
    depth: int = 10
    reliable: bool = True
    transient_local: bool = False  # late subscribers get the last `depth` messages

    def key(self) -> str:
        """rmw_zenoh's QoS text: reliability:durability:history,depth (1 = reliable,
        transient local, keep last; 2 = best effort, volatile)."""
        return f"{1 if self.reliable else 2}:{1 if self.transient_local else 2}:1,{self.depth}"


def qos_of(value: QoS | int | None) -> QoS:
    if isinstance(value, QoS):
        return value
    return QoS(depth=value or 10)


SENSOR_DATA = QoS(depth=5, reliable=False)
LATCHED = QoS(depth=1, transient_local=True)

"""Which sensor publishes which type on which topic, so that two sensors of different types on
one topic are caught where the second is declared (Gazebo lets both publish and every
subscriber of one type silently misses the other's messages)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass
class TopicClaims:
    owners: dict[str, tuple[str, Any]] = field(default_factory=dict)  # topic → (type, sensor)

    def claim(self, topic: str, type_name: str, sensor: Any) -> str:
        """Take `topic` for `sensor`; if another sensor publishes another type there, say
        which (and the topic stays the first one's)."""
        held = self.owners.get(topic)
        if held is None:
            self.owners[topic] = (type_name, sensor)
            return ""
        if held[0] == type_name:
            return ""
        other = held[1]
        return (f"{other.label} ({other.config.where}) publishes {gz_name(held[0])} on "
                f"{topic}, and this one would publish {gz_name(type_name)} there")

    def release(self, sensor: Any) -> None:
        for topic in [t for t, (_, owner) in self.owners.items() if owner is sensor]:
            del self.owners[topic]


def gz_name(type_name: str) -> str:
    return f"gz.msgs.{type_name.rsplit('/', 1)[-1]}"

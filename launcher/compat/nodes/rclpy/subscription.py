"""rclpy.subscription.Subscription over launcher's bus subscription."""

from __future__ import annotations

from typing import Any


class Subscription:
    def __init__(self, bus: Any, msg_type: Any, topic: str, callback: Any,
                 callback_group: Any, qos_profile: Any, raw: bool,
                 event_callbacks: Any = None) -> None:
        self._bus, self.msg_type, self.callback = bus, msg_type, callback
        self.callback_group, self._qos_profile, self.raw = callback_group, qos_profile, raw
        self.event_callbacks = event_callbacks

    @property
    def topic_name(self) -> str:
        """The topic's fully qualified name."""
        return self._bus.topic

    @property
    def qos_profile(self) -> Any:
        """The subscription's QoSProfile."""
        return self._qos_profile

    def destroy(self) -> None:
        """Take the subscription off the graph."""
        self._bus.destroy()

    @property
    def handle(self) -> Any:
        """The launcher bus subscription under this one."""
        return self._bus

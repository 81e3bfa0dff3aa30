"""rclpy.qos_event (rclpy.event_handler): event callback holders. Of the events, launcher
raises the matched ones (rclpy/matched.py); deadlines, liveliness and incompatible QoS are not
enforced on its bus, so those callbacks are kept and never called."""

from __future__ import annotations

from typing import Any


class SubscriptionEventCallbacks:
    def __init__(self, *, deadline: Any = None, incompatible_qos: Any = None,
                 liveliness: Any = None, message_lost: Any = None,
                 incompatible_type: Any = None, matched: Any = None,
                 use_default_callbacks: bool = True) -> None:
        self.deadline, self.incompatible_qos, self.liveliness = deadline, incompatible_qos, \
            liveliness
        self.message_lost, self.incompatible_type, self.matched = message_lost, \
            incompatible_type, matched
        self.use_default_callbacks = use_default_callbacks


class PublisherEventCallbacks:
    def __init__(self, *, deadline: Any = None, incompatible_qos: Any = None,
                 liveliness: Any = None, incompatible_type: Any = None, matched: Any = None,
                 use_default_callbacks: bool = True) -> None:
        self.deadline, self.incompatible_qos, self.liveliness = deadline, incompatible_qos, \
            liveliness
        self.incompatible_type, self.matched = incompatible_type, matched
        self.use_default_callbacks = use_default_callbacks


class QoSEventHandler:
    pass


EventHandler = QoSEventHandler

"""rclpy.subscription.Subscription over launcher's bus subscription."""

from __future__ import annotations

from typing import Any, TypedDict

from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.event_handler import SubscriptionEventCallbacks  # noqa: F401
from rclpy.exceptions import RCLError  # noqa: F401
from rclpy.properties import readonly
from rclpy.qos import QoSProfile  # noqa: F401
from rclpy.subscription_content_filter_options import ContentFilterOptions  # noqa: F401


class MessageInfo(TypedDict):
    """What a callback taking two arguments gets with each message."""

    source_timestamp: int
    received_timestamp: int
    publication_sequence_number: int | None
    reception_sequence_number: int | None


class Subscription:
    def __init__(self, subscription_impl: Any, msg_type: Any, topic: str, callback: Any,
                 callback_group: Any, qos_profile: Any, raw: bool,
                 event_callbacks: Any = None) -> None:
        """`subscription_impl`: launcher's bus subscription (Node.create_subscription makes
        both)."""
        self._bus, self.msg_type, self.callback = subscription_impl, msg_type, callback
        self.callback_group, self._qos_profile, self.raw = callback_group, qos_profile, raw
        self.event_callbacks = event_callbacks

    topic_name = readonly("_bus.topic", "The topic's fully qualified name.")
    qos_profile = readonly("_qos_profile", "The subscription's QoSProfile.")
    handle = readonly("_bus", "The launcher bus subscription under this one.")

    def destroy(self) -> None:
        """Take the subscription off the graph."""
        self._bus.destroy()

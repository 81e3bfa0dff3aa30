"""rclpy.event_handler: the newer name of rclpy.qos_event."""

from rclpy.qos_event import (  # noqa: F401
    EventHandler,
    PublisherEventCallbacks,
    QoSEventHandler,
    SubscriptionEventCallbacks,
)

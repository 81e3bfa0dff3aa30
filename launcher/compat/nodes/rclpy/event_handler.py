"""rclpy.event_handler: the newer name of rclpy.qos_event, with the matched events' infos."""

from rclpy.matched import QoSPublisherMatchedInfo, QoSSubscriptionMatchedInfo  # noqa: F401
from rclpy.qos_event import (  # noqa: F401
    EventHandler,
    PublisherEventCallbacks,
    QoSEventHandler,
    SubscriptionEventCallbacks,
)

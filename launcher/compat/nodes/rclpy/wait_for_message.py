"""rclpy.wait_for_message: the next message on a topic, waited for without spinning the
node (a subscription of its own that lives for the wait)."""

from __future__ import annotations

from typing import Any

from launcher.bus.subscription import FirstMessage
from rclpy.node import Node  # noqa: F401 - as rclpy's module offers it
from rclpy.qos import QoSProfile  # noqa: F401
from rclpy.signals import SignalHandlerGuardCondition  # noqa: F401
from rclpy.utilities import timeout_sec_to_nsec  # noqa: F401


def wait_for_message(msg_type: Any, node: Any, topic: str, *, qos_profile: Any = 1,
                     time_to_wait: float = -1) -> tuple[bool, Any]:
    """(True, the message), or (False, None) if none came within `time_to_wait` seconds
    (-1: for as long as it takes while the context is up)."""
    from launcher.compat import rosidl
    from rclpy.qos import to_launcher

    first = FirstMessage()
    type_name = rosidl.type_name_of(msg_type)
    subscription = node.handle.create_subscription(type_name, topic, first,
                                                   to_launcher(qos_profile), inline=True,
                                                   make=rosidl.make)
    try:
        if time_to_wait is None or time_to_wait < 0:
            while not first.wait(0.1):
                if not node.context.ok():
                    return False, None
        elif not first.wait(time_to_wait):
            return False, None
        return True, first.message
    finally:
        subscription.destroy()

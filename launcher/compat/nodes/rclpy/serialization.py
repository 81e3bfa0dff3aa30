"""rclpy.serialization: a message to and from its CDR bytes (with the encapsulation header,
as on the wire), by launcher's codec."""

from __future__ import annotations

from typing import Any

from launcher.bus.types import registry
from launcher.compat import rosidl
from rclpy.type_support import Msg, check_for_type_support  # noqa: F401 - rclpy's offers Msg


def serialize_message(message: Any) -> bytes:
    """The CDR bytes of a ROS message."""
    check_for_type_support(type(message))
    return registry().serialize(message, rosidl.type_name_of(type(message)))


def deserialize_message(serialized_message: bytes, message_type: Any) -> Any:
    """The message of type `message_type` in CDR bytes."""
    check_for_type_support(message_type)
    return registry().deserialize(serialized_message, rosidl.type_name_of(message_type),
                                  rosidl.make)

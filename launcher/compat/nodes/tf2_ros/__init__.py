"""tf2_ros over launcher's bus: Buffer, TransformListener, TransformBroadcaster,
StaticTransformBroadcaster and tf2's exceptions. A real tf2_ros that the user installed wins
in their shell (the import hook is asked last)."""

from tf2_ros.buffer import Buffer
from tf2_ros.buffer_core import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf2_ros.transform_broadcaster import TransformBroadcaster
from tf2_ros.transform_listener import TransformListener

__all__ = ["Buffer", "BufferCore", "ConnectivityException", "ExtrapolationException",
           "InvalidArgumentException", "LookupException", "StaticTransformBroadcaster",
           "TimeoutException", "TransformBroadcaster", "TransformException",
           "TransformListener"]

"""tf2_ros over launcher's bus: Buffer, TransformListener, TransformBroadcaster,
StaticTransformBroadcaster and tf2's exceptions. A real tf2_ros that the user installed wins
in their shell (the import hook is asked last)."""

from tf2_ros import buffer_core as _buffer_core
from tf2_ros.buffer import Buffer
from tf2_ros.buffer_core import *  # noqa: F403 (tf2_ros gives tf2's BufferCore and exceptions)
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf2_ros.transform_broadcaster import TransformBroadcaster
from tf2_ros.transform_listener import TransformListener

__all__ = ["Buffer", "StaticTransformBroadcaster", "TransformBroadcaster", "TransformListener",
           *_buffer_core.__all__]

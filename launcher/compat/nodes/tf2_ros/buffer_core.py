"""tf2's BufferCore and exceptions (launcher/bus/tf_tree.py: the tf tree the tools share)."""

from launcher.bus.tf_tree import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
    inverse,  # noqa: F401 (launcher's transform arithmetic, for Buffer and tf2_geometry_msgs)
    multiply,  # noqa: F401
)

__all__ = ["BufferCore", "ConnectivityException", "ExtrapolationException",
           "InvalidArgumentException", "LookupException", "TimeoutException",
           "TransformException"]

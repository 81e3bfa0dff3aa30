"""tf2's BufferCore and exceptions (launcher/bus/tf_tree.py: the tf tree the tools share)."""

from launcher.bus.tf_tree import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
    inverse,
    multiply,
)

__all__ = ["BufferCore", "ConnectivityException", "ExtrapolationException",
           "InvalidArgumentException", "LookupException", "TimeoutException",
           "TransformException", "inverse", "multiply"]

"""rclpy.utilities: the default context and its checks."""

from __future__ import annotations

import sys
from typing import Any

from rclpy.constants import S_TO_NS  # noqa: F401 - as rclpy's module offers it
from rclpy.context import (  # noqa: F401 - rclpy's module offers them
    Context,
    g_default_context,
    get_default_context,
)
from rclpy.signals import uninstall_signal_handlers


def ok(*, context: Context | None = None) -> bool:
    """Whether the default (or the given) context is initialized and not shut down."""
    return (context or g_default_context).ok()


def shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    """Shut the default (or the given) context down; the signal handlers are uninstalled
    when `uninstall_handlers`, or when it is None and the context is the default one."""
    (context or g_default_context).shutdown()
    _uninstall(context, uninstall_handlers)


def try_shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None
                 ) -> None:
    """Shut the default (or the given) context down if it is not already (signal handlers
    as shutdown() says)."""
    (context or g_default_context).try_shutdown()
    _uninstall(context, uninstall_handlers)


def _uninstall(context: Context | None, uninstall_handlers: bool | None) -> None:
    if uninstall_handlers or uninstall_handlers is None and \
            context in (None, g_default_context):
        uninstall_signal_handlers()


def remove_ros_args(args: list[str] | None = None) -> list[str]:
    """The program's own arguments: argv without the `--ros-args … [--]` parts."""
    from launcher.bus import ros_args

    words = sys.argv if args is None else list(args)
    if not words:
        return []
    return [words[0], *ros_args.parse(words[1:]).user_args]


def get_rmw_implementation_identifier() -> str:
    """The middleware's name: rmw_zenoh_cpp, whose layout
    launcher's graph keeps.
    """
    return "rmw_zenoh_cpp"


def timeout_sec_to_nsec(timeout_sec: float | None) -> int:
    """A timeout in seconds as nanoseconds (None or negative: -1, forever)."""
    if timeout_sec is None or timeout_sec < 0:
        return -1
    return int(float(timeout_sec) * 1e9)


def get_available_rmw_implementations() -> set[str]:
    """The middlewares there are: rmw_zenoh_cpp."""
    return {"rmw_zenoh_cpp"}


def check_for_type_support(message_type: Any) -> None:
    """NoTypeSupportImportedException unless `message_type` is a message
    class.
    """
    if not hasattr(message_type, "_TYPE"):
        from rclpy.exceptions import NoTypeSupportImportedException

        raise NoTypeSupportImportedException(f"{message_type!r} is not a message type")

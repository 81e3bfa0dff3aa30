"""rclpy.utilities: the default context and its checks."""

from __future__ import annotations

import sys
from typing import Any

from rclpy.context import Context

_default_context = Context()


def get_default_context(*, shutting_down: bool = False) -> Context:
    return _default_context


def ok(*, context: Context | None = None) -> bool:
    return (context or _default_context).ok()


def shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    (context or _default_context).shutdown()


def try_shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None
                 ) -> None:
    (context or _default_context).try_shutdown()


def remove_ros_args(args: list[str] | None = None) -> list[str]:
    """The program's own arguments: argv without the `--ros-args … [--]` parts."""
    from launcher.bus import ros_args

    words = sys.argv if args is None else list(args)
    if not words:
        return []
    return [words[0], *ros_args.parse(words[1:]).user_args]


def get_rmw_implementation_identifier() -> str:
    return "rmw_zenoh_cpp"


def timeout_sec_to_nsec(timeout_sec: float | None) -> int:
    if timeout_sec is None or timeout_sec < 0:
        return -1
    return int(float(timeout_sec) * 1e9)


def get_available_rmw_implementations() -> set[str]:
    return {"rmw_zenoh_cpp"}


def check_for_type_support(message_type: Any) -> None:
    if not hasattr(message_type, "_TYPE"):
        from rclpy.exceptions import NoTypeSupportImportedException

        raise NoTypeSupportImportedException(f"{message_type!r} is not a message type")

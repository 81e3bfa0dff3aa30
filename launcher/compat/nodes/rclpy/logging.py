"""rclpy.logging: named loggers with ROS 2's levels and line layout
(`[INFO] [1700000000.123456789] [name]: text`), on stderr as rcutils writes them (stdout
with RCUTILS_LOGGING_USE_STDOUT=1). A logger's level is its own once set; unset (0), it
follows its parent's (`a.b` follows `a`), then the default."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from rclpy.impl.logging_severity import LoggingSeverity
from rclpy.impl.rcutils_logger import RcutilsLogger, levels


def get_logger(name: str) -> RcutilsLogger:
    """The logger of that name."""
    if not name:
        raise ValueError("Logger name must not be empty.")
    return RcutilsLogger(name)


def initialize() -> None:
    """Start logging: launcher's loggers write from the first line on, so there is nothing
    to start (rclpy starts rcutils' here)."""


def shutdown() -> None:
    """Forget the levels set on loggers and the default level."""
    levels.reset()


def clear_config() -> None:
    """Clear the configuration of the logging system (logger levels)."""
    shutdown()
    initialize()


def get_logging_directory() -> Path:
    """Where ROS writes its log files: $ROS_LOG_DIR, else $ROS_HOME/log, else ~/.ros/log."""
    found = os.environ.get("ROS_LOG_DIR") or \
        os.path.join(os.environ.get("ROS_HOME") or os.path.join("~", ".ros"), "log")
    return Path(os.path.expanduser(found))


def set_logger_level(name: str, level: Any, detailed_error: bool = False) -> None:
    """Set a logger's level by its name (ValueError for a level that is none, with the
    valid ones when `detailed_error`)."""
    try:
        levels.set(name, level)
    except ValueError:
        if detailed_error:
            raise ValueError(f"invalid level {level!r}: valid ones are "
                             f"{', '.join(s.name for s in LoggingSeverity)}") from None
        raise


def get_logger_level(name: str) -> LoggingSeverity:
    """The level set for this logger itself (UNSET, 0, when none was)."""
    return levels.own.get(name, LoggingSeverity.UNSET)


def get_logger_effective_level(name: str) -> LoggingSeverity:
    """The level a logger logs at, by its name."""
    return levels.effective(name)


def get_logging_severity_from_string(log_severity: str) -> LoggingSeverity:
    """The LoggingSeverity of its name (`info`, `WARN`, …)."""
    return LoggingSeverity[log_severity.upper().replace("WARNING", "WARN")]


def set_default_level(level: Any) -> None:
    """The level loggers without one of their own log at."""
    levels.default = LoggingSeverity(level)

"""rclpy.impl.logging_severity.LoggingSeverity: rcutils' log levels."""

from enum import IntEnum


class LoggingSeverity(IntEnum):
    """rcutils' log levels (UNSET: follow the parent logger's)."""

    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50

"""rclpy.logging: named loggers with ROS 2's levels and line layout
(`[INFO] [1700000000.123456789] [name]: text`), on stderr as rcutils writes them (stdout
with RCUTILS_LOGGING_USE_STDOUT=1). A logger's level is its own once set; unset (0), it
follows its parent's (`a.b` follows `a`), then the default."""

from __future__ import annotations

import os
import sys
import time
from enum import IntEnum
from typing import Any


class LoggingSeverity(IntEnum):
    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


_levels: dict[str, LoggingSeverity] = {}
_default = LoggingSeverity.INFO


class RcutilsLogger:
    def __init__(self, name: str = "") -> None:
        self.name = name
        self._once: set[Any] = set()
        self._last: dict[Any, float] = {}
        self._skipped: set[Any] = set()

    def get_child(self, name: str) -> RcutilsLogger:
        """The logger `<name>.<child>`."""
        if not name:
            raise ValueError("Child logger name must not be empty.")
        return RcutilsLogger(f"{self.name}.{name}" if self.name else name)

    def set_level(self, level: Any) -> None:
        """Log `level` and above from now on."""
        _levels[self.name] = LoggingSeverity(level)

    def get_effective_level(self) -> LoggingSeverity:
        """The level this logger logs at (its own, else its parents')."""
        name = self.name
        while True:
            if name in _levels and _levels[name] != LoggingSeverity.UNSET:
                return _levels[name]
            if "." not in name:
                return _default
            name = name.rsplit(".", 1)[0]

    def is_enabled_for(self, severity: Any) -> bool:
        """Whether a message of `severity` would be logged."""
        return LoggingSeverity(severity) >= self.get_effective_level()

    def log(self, message: Any, severity: Any, **kwargs: Any) -> bool:
        """Log `message` at `severity` (`once`, `throttle_duration_sec`, `skip_first`
        as rclpy takes them); whether it was.
        """
        severity = LoggingSeverity(severity)
        if not self.is_enabled_for(severity):
            return False
        caller = sys._getframe(2)
        where = (caller.f_code.co_filename, caller.f_lineno)
        if kwargs.get("once"):
            if where in self._once:
                return False
            self._once.add(where)
        if kwargs.get("skip_first") and where not in self._skipped:
            self._skipped.add(where)
            return False
        throttle = kwargs.get("throttle_duration_sec")
        if throttle:
            now = time.monotonic()
            if now - self._last.get(where, -1e18) < throttle:
                return False
            self._last[where] = now
        condition = kwargs.get("condition")  # rclpy's `condition=` (a bool)
        if condition is not None and not condition:
            return False
        stream = sys.stdout if os.environ.get("RCUTILS_LOGGING_USE_STDOUT") == "1" else \
            sys.stderr
        stamp = time.time_ns()
        print(f"[{severity.name}] [{stamp // 1_000_000_000}.{stamp % 1_000_000_000:09d}] "
              f"[{self.name}]: {message}", file=stream, flush=True)
        return True

    def debug(self, message: Any, **kwargs: Any) -> bool:
        """Log at DEBUG."""
        return self.log(message, LoggingSeverity.DEBUG, **kwargs)

    def info(self, message: Any, **kwargs: Any) -> bool:
        """Log at INFO."""
        return self.log(message, LoggingSeverity.INFO, **kwargs)

    def warning(self, message: Any, **kwargs: Any) -> bool:
        """Log at WARN."""
        return self.log(message, LoggingSeverity.WARN, **kwargs)

    warn = warning

    def error(self, message: Any, **kwargs: Any) -> bool:
        """Log at ERROR."""
        return self.log(message, LoggingSeverity.ERROR, **kwargs)

    def fatal(self, message: Any, **kwargs: Any) -> bool:
        """Log at FATAL."""
        return self.log(message, LoggingSeverity.FATAL, **kwargs)


def get_logger(name: str) -> RcutilsLogger:
    """The logger of that name."""
    if not name:
        raise ValueError("Logger name must not be empty.")
    return RcutilsLogger(name)


def set_logger_level(name: str, level: Any) -> None:
    """Set a logger's level by its name."""
    _levels[name] = LoggingSeverity(level)


def get_logger_level(name: str) -> LoggingSeverity:
    """The level set for this logger itself (UNSET, 0, when none was)."""
    return _levels.get(name, LoggingSeverity.UNSET)


def get_logger_effective_level(name: str) -> LoggingSeverity:
    """The level a logger logs at, by its name."""
    return RcutilsLogger(name).get_effective_level()


def get_logging_severity_from_string(text: str) -> LoggingSeverity:
    """The LoggingSeverity of its name (`info`, `WARN`, …)."""
    return LoggingSeverity[text.upper().replace("WARNING", "WARN")]


def set_default_level(level: Any) -> None:
    """The level loggers without one of their own log at."""
    global _default
    _default = LoggingSeverity(level)

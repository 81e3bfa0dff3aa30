"""rospy's logging functions (rospy.core has them): printed as rospy prints them, DEBUG and
INFO on stdout, the rest on stderr; `_throttle` once a period per call site, `_once` once per
call site, `_throttle_identical` when the text changes or the period has passed."""

from __future__ import annotations

import sys
import time as _time
from collections.abc import Callable
from typing import Any

DEBUG, INFO, WARN, ERROR, FATAL = 1, 2, 4, 8, 16
LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}
threshold = [INFO]  # the lowest level printed (init_node's log_level)
clock: list[Callable[[], float]] = [_time.time]  # init_node: the node's time (sim time too)


def _now() -> float:
    return clock[0]()


class LoggingThrottle:
    """Whether a call site may log again: once per `period` seconds of ROS time."""

    last_logging_time_table: dict[Any, float] = {}

    def __call__(self, caller_id: Any, period: float) -> bool:
        now = _now()
        last = self.last_logging_time_table.get(caller_id)
        if last is None or now - last > period or last > now:  # (time moved backwards)
            self.last_logging_time_table[caller_id] = now
            return True
        return False


class LoggingIdentical:
    """Whether a call site's message differs from the one it logged last."""

    last_logging_msg_table: dict[Any, str] = {}

    def __call__(self, caller_id: Any, msg: str) -> bool:
        from hashlib import md5

        digest = md5(str(msg).encode()).hexdigest()
        if digest != self.last_logging_msg_table.get(caller_id):
            self.last_logging_msg_table[caller_id] = digest
            return True
        return False


class LoggingOnce:
    """Whether a call site logs for the first time."""

    called_caller_ids: set[Any] = set()

    def __call__(self, caller_id: Any) -> bool:
        if caller_id not in self.called_caller_ids:
            self.called_caller_ids.add(caller_id)
            return True
        return False


_logging_throttle, _logging_identical, _logging_once = \
    LoggingThrottle(), LoggingIdentical(), LoggingOnce()


def emit(level: int, message: Any, args: tuple, kwargs: dict) -> None:
    """Print one message (`args` fill it printf-style; `logger_name` names a child logger)."""
    if level < threshold[0]:
        return
    text = str(message) % args if args else str(message)
    child = kwargs.get("logger_name")
    where = f"[rosout.{child}]" if child else ""
    stream = sys.stderr if level >= WARN else sys.stdout
    print(f"[{LEVEL_NAMES[level]}] [{_time.time():.6f}]{where}: {text}", file=stream,
          flush=True)


def _site() -> tuple[Any, int]:
    frame = sys._getframe(2)  # the caller of the log function
    return frame.f_code, frame.f_lineno


def plain(level: int) -> Callable[..., None]:
    def log(msg: Any, *args: Any, **kwargs: Any) -> None:
        emit(level, msg, args, kwargs)
    return log


def throttled(level: int) -> Callable[..., None]:
    def log(period: float, msg: Any, *args: Any, **kwargs: Any) -> None:
        if _logging_throttle(_site(), period):
            emit(level, msg, args, kwargs)
    return log


def throttled_identical(level: int) -> Callable[..., None]:
    def log(period: float, msg: Any, *args: Any, **kwargs: Any) -> None:
        site = _site()
        elapsed = period is not None and _logging_throttle(site, period)
        if _logging_identical(site, msg) or elapsed:
            emit(level, msg, args, kwargs)
    return log


def once(level: int) -> Callable[..., None]:
    def log(msg: Any, *args: Any, **kwargs: Any) -> None:
        if _logging_once(_site()):
            emit(level, msg, args, kwargs)
    return log


def internal(method: str) -> Callable[..., None]:
    """rospy's own log (the Python logger `rospy.internal`), for rospydebug and the like."""
    def log(msg: Any, *args: Any, **kwargs: Any) -> None:
        import logging

        getattr(logging.getLogger("rospy.internal"), method)(msg, *args, **kwargs)
    return log

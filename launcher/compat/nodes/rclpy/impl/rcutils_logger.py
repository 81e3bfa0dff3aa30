"""rclpy.impl.rcutils_logger: RcutilsLogger, the logger a node's `get_logger()` gives, with
rcutils' levels (a logger's own once set; unset, its parent's, then the default) and its line
layout (`[INFO] [1700000000.123456789] [name]: text`) on stderr, or stdout with
RCUTILS_LOGGING_USE_STDOUT=1.

`once=`, `skip_first=` and `throttle_duration_sec=` are filters, as rclpy's: each call site
(CallerId) keeps a context of its own, and a site may not change its filters between calls.
launcher also takes `condition=` (a bool), checked after the filters.
"""

from __future__ import annotations

import os
import sys
import time
from types import FrameType
from typing import Any, ClassVar, NamedTuple, TypedDict

from launcher.bus.logging import write_line
from rclpy.impl.logging_severity import LoggingSeverity

HERE = os.path.dirname(os.path.abspath(__file__))
# Frames in these files are the logging machinery, not the caller whose site is counted.
INTERNAL = (os.path.join(HERE, "rcutils_logger.py"),
            os.path.join(os.path.dirname(HERE), "logging.py"))


class LevelTable:
    """The levels set on loggers by name, and the default: rcutils' one table."""

    def __init__(self) -> None:
        self.own: dict[str, LoggingSeverity] = {}
        self.default = LoggingSeverity.INFO

    def set(self, name: str, level: Any) -> None:
        """Give the logger `name` its own level."""
        self.own[name] = LoggingSeverity(level)

    def effective(self, name: str) -> LoggingSeverity:
        """The level `name` logs at: its own, else its nearest parent's, else the default."""
        while True:
            if self.own.get(name, LoggingSeverity.UNSET) != LoggingSeverity.UNSET:
                return self.own[name]
            if "." not in name:
                return self.default
            name = name.rsplit(".", 1)[0]

    def reset(self) -> None:
        """Forget every level set, and the default."""
        self.own.clear()
        self.default = LoggingSeverity.INFO


levels = LevelTable()


class _Site(NamedTuple):
    function_name: str
    file_path: str
    line_number: int
    last_index: int


class CallerId(_Site):
    """A logging call site: the function, file, line and bytecode offset of `frame`, or of
    the first frame outside the logging machinery."""

    def __new__(cls, frame: FrameType | None = None) -> CallerId:
        frame = frame or _outside(sys._getframe(1))
        return super().__new__(cls, frame.f_code.co_name,
                               os.path.abspath(frame.f_code.co_filename), frame.f_lineno,
                               frame.f_lasti)


def _outside(frame: FrameType | None) -> FrameType:
    while frame is not None and os.path.abspath(frame.f_code.co_filename) in INTERNAL:
        frame = frame.f_back
    if frame is None:
        raise ValueError("Cannot get frame info if frame is None")
    return frame


class RcutilsLoggerContext(TypedDict):
    """What a call site's context holds: its logger's name, its severity, its filters."""

    name: str
    severity: LoggingSeverity
    filters: list[str]


class OnceContext(RcutilsLoggerContext):
    has_been_logged_once: bool


class ThrottleContext(RcutilsLoggerContext):
    throttle_duration_sec: float
    throttle_time_source_type: Any
    throttle_last_logged: int


class SkipFirstContext(RcutilsLoggerContext):
    first_has_been_skipped: bool


class LoggingFilterArgs(TypedDict, total=False):
    once: bool
    throttle_duration_sec: float
    throttle_time_source_type: Any
    skip_first: bool


class LoggingFilterParams(TypedDict, total=False):
    once: bool | None
    throttle_duration_sec: float | None
    throttle_time_source_type: Any
    skip_first: bool | None


class LoggingArgs(LoggingFilterArgs, total=False):
    name: str


class LoggingFilter:
    """A filter: its parameters (None: required) and whether a call may log."""

    params: ClassVar[dict[str, Any]] = {}

    @classmethod
    def initialize_context(cls, context: Any, **kwargs: Any) -> None:
        """Store the filter's parameters in a new call site's context."""
        for name, default in cls.params.items():
            value = kwargs.get(name, default)
            if value is None:
                raise TypeError(f'Required parameter "{name}" was not specified for logging '
                                f'filter "{cls.__name__}"')
            context[name] = value

    @staticmethod
    def should_log(context: Any) -> bool:
        """Whether this call logs (and the context updated for the next)."""
        return True


class _FirstCall(LoggingFilter):
    """A filter that tells a call site's first call from the rest, by a flag its context
    keeps under `_key`: it logs the first call only (`_first`), or all but it."""

    _key: ClassVar[str]
    _first: ClassVar[bool]

    @classmethod
    def initialize_context(cls, context: Any, **kwargs: Any) -> None:
        """No call yet."""
        super().initialize_context(context, **kwargs)
        context[cls._key] = False

    @classmethod
    def should_log(cls, context: Any) -> bool:
        """Whether this call is the first, for Once; whether it is not, for SkipFirst."""
        first = not context[cls._key]
        context[cls._key] = True
        return first == cls._first


class Once(_FirstCall):
    """Log the first call only."""

    params: ClassVar[dict[str, Any]] = {"once": None}
    _key, _first = "has_been_logged_once", True


class SteadyClock:
    """rcutils' steady time, which Throttle measures by unless given a clock."""

    def now(self) -> Any:
        """Now, as a value with `.nanoseconds`."""
        return _Stamp(time.monotonic_ns())


class _Stamp(NamedTuple):
    nanoseconds: int


class Throttle(LoggingFilter):
    """Log a call only when `throttle_duration_sec` has passed since the last one logged."""

    params: ClassVar[dict[str, Any]] = {"throttle_duration_sec": None,
                                        "throttle_time_source_type": SteadyClock()}

    @classmethod
    def initialize_context(cls, context: Any, **kwargs: Any) -> None:
        """Never logged; the clock must have `now()`."""
        super().initialize_context(context, **kwargs)
        context["throttle_last_logged"] = None
        if not callable(getattr(context["throttle_time_source_type"], "now", None)):
            raise ValueError(f'Received throttle_time_source_type of '
                             f'"{context["throttle_time_source_type"]}" is not a clock instance')

    @staticmethod
    def should_log(context: Any) -> bool:
        """True when the interval has passed since the last logged call (or none was)."""
        now = context["throttle_time_source_type"].now().nanoseconds
        last = context["throttle_last_logged"]
        if last is not None and now < last + context["throttle_duration_sec"] * 1e9:
            return False
        context["throttle_last_logged"] = now
        return True


class SkipFirst(_FirstCall):
    """Log every call but the first."""

    params: ClassVar[dict[str, Any]] = {"skip_first": None}
    _key, _first = "first_has_been_skipped", False


FILTERS: dict[str, type[LoggingFilter]] = {"throttle": Throttle, "skip_first": SkipFirst,
                                           "once": Once}
EXTRA = ("condition",)  # launcher's own keyword, not a filter


def get_filters_from_kwargs(**kwargs: Any) -> list[str]:
    """The filters (`throttle`, `skip_first`, `once`, in that order) whose parameters are set
    in `kwargs`; TypeError for an unknown keyword or a filter missing a required one."""
    known = [name for filter_ in FILTERS.values() for name in filter_.params] + list(EXTRA)
    for name in kwargs:
        if name not in known:
            raise TypeError(f'parameter "{name}" is not one of the recognized logging options '
                            f'"{known}"')
    found = [key for key, filter_ in FILTERS.items()
             if any(kwargs.get(name) for name in filter_.params)]
    for key in found:
        for name, default in FILTERS[key].params.items():
            if name not in kwargs and default is None:
                raise TypeError(f'required parameter "{name}" not specified but is required '
                                f'for the the logging filter "{key}"')
    return found


class RcutilsLogger:
    """A named logger (`a.b` is a child of `a`)."""

    def __init__(self, name: str = "") -> None:
        self.name = name
        self.logger_sublogger_namepair: tuple[str, str] | None = None
        self.contexts: dict[CallerId, Any] = {}

    def get_child(self, name: str) -> RcutilsLogger:
        """The logger `<name>.<child>`."""
        if not name:
            raise ValueError("Child logger name must not be empty.")
        return RcutilsLogger(f"{self.name}.{name}" if self.name else name)

    def set_level(self, level: Any) -> None:
        """Log `level` and above from now on."""
        levels.set(self.name, level)

    def get_effective_level(self) -> LoggingSeverity:
        """The level this logger logs at (its own, else its parents')."""
        return levels.effective(self.name)

    def is_enabled_for(self, severity: Any) -> bool:
        """Whether a message of `severity` would be logged."""
        return LoggingSeverity(severity) >= self.get_effective_level()

    def log(self, message: Any, severity: Any, name: str | None = None, **kwargs: Any) -> bool:
        """Log `message` at `severity` under `name` (this logger's by default), through the
        filters `kwargs` name; whether it was logged."""
        if not self.is_enabled_for(severity):
            return False
        severity, name = LoggingSeverity(severity), name or self.name
        context = self._context(CallerId(), name, severity, kwargs)
        if not all(FILTERS[key].should_log(context) for key in context["filters"]):
            return False
        condition = kwargs.get("condition")
        if condition is not None and not condition:
            return False
        stream = sys.stdout if os.environ.get("RCUTILS_LOGGING_USE_STDOUT") == "1" else \
            sys.stderr
        stamp = time.time_ns()
        write_line(stream, f"[{severity.name}] [{stamp // 1_000_000_000}."
                           f"{stamp % 1_000_000_000:09d}] [{name}]: {message}")
        return True

    def _context(self, site: CallerId, name: str, severity: LoggingSeverity,
                 kwargs: dict[str, Any]) -> Any:
        found = get_filters_from_kwargs(**kwargs)
        context = self.contexts.get(site)
        if context is None:
            context = {"name": name, "severity": severity, "filters": found}
            for key in found:
                FILTERS[key].initialize_context(context, **kwargs)
            self.contexts[site] = context
            return context
        for what, now in (("severity", severity), ("name", name), ("filters", found)):
            if context[what] != now:
                raise ValueError(f"Logger {what} cannot be changed between calls.")
        for key in found:
            for param, default in FILTERS[key].params.items():
                if context[param] != kwargs.get(param, default):
                    raise ValueError("Logging filter parameters cannot be changed between "
                                     "calls.")
        return context

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



from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)

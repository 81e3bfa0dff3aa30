"""`log` (with `level`), and `log_info`, `log_warning`, `log_error`, `log_debug`."""

from __future__ import annotations

from typing import Any, ClassVar

from launcher.description.action import Action
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import perform_text
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext

LEVELS = {"debug": "DEBUG", "info": "INFO", "warn": "WARN", "warning": "WARN", "error": "ERROR"}


@action("log")
@dataclass(kw_only=True, eq=False)
class Log(Action):
    msg: Any = attr(Kind.TEXT, name="message", aliases=("msg",), required=True,
                    doc="The text to log.")
    level: Any = attr(Kind.TEXT, "info", choices=tuple(LEVELS), doc="debug, info, warn, error.")

    def execute(self, context: LaunchContext) -> None:
        spec = type(self).__dataclass_fields__["level"].metadata.get("launch")
        level = LEVELS[resolve(context, self.level, Kind.TEXT, "level", spec).lower()]
        message = perform_text(context, self.msg)
        if context.service is not None:
            context.service.log(level, "launch", message)


@dataclass(kw_only=True, eq=False)
class LevelFixed(Log):
    fixed: ClassVar[str] = "info"
    level: Any = None

    def __post_init__(self) -> None:
        super().__post_init__()
        self.level = self.fixed


@action("log_info")
@dataclass(kw_only=True, eq=False)
class LogInfo(LevelFixed):
    fixed = "info"


@action("log_warning")
@dataclass(kw_only=True, eq=False)
class LogWarning(LevelFixed):
    fixed = "warning"


@action("log_error")
@dataclass(kw_only=True, eq=False)
class LogError(LevelFixed):
    fixed = "error"


@action("log_debug")
@dataclass(kw_only=True, eq=False)
class LogDebug(LevelFixed):
    fixed = "debug"

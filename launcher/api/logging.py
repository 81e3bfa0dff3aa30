"""launch.logging: the launch's loggers (`launch.logging.get_logger('x').info(...)`), which
print as launch's do: `[INFO] [x]: message` on the screen."""

from __future__ import annotations

import logging
import sys
from typing import Any


class LaunchConfig:
    """launch.logging.launch_config: the level, the log folder and the screen's format."""

    def __init__(self) -> None:
        self.level = logging.INFO
        self.log_dir: str | None = None
        self.screen_format = "[{levelname}] [{name}]: {msg}"
        self.log_handler_factory: Any = None

    def set_screen_format(self, screen_format: str, *, screen_style: str = "{") -> None:
        self.screen_format = screen_format

    def set_log_format(self, log_format: str, *, log_style: str = "{") -> None:
        self.log_format = log_format

    def set_level(self, new_level: Any) -> None:
        self.level = new_level
        logging.getLogger("launch").setLevel(new_level)


launch_config = LaunchConfig()
_screen: logging.Handler | None = None


def get_logger(name: str | None = None) -> logging.Logger:
    """The logger `name` (launch's own without one), printing on stderr as launch does."""
    global _screen
    if _screen is None:
        _screen = logging.StreamHandler(sys.stderr)
        _screen.setFormatter(_Format())
        root = logging.getLogger("launch")
        root.addHandler(_screen)
        root.setLevel(launch_config.level)
        root.propagate = False
    return logging.getLogger("launch" if name is None else f"launch.{name}")


class _Format(logging.Formatter):
    def format(self, record: logging.LogRecord) -> str:
        name = record.name.removeprefix("launch.") if record.name != "launch" else "launch"
        return launch_config.screen_format.format(levelname=record.levelname, name=name,
                                                  msg=record.getMessage())


def get_output_loggers(process_name: str, output_config: Any) -> tuple[logging.Logger,
                                                                        logging.Logger]:
    """The loggers of a process's stdout and stderr."""
    logger = get_logger(process_name)
    return logger, logger


def reset() -> None:
    """Forget the loggers' handlers and the configuration (as at start)."""
    global _screen, launch_config
    if _screen is not None:
        logging.getLogger("launch").removeHandler(_screen)
    _screen = None
    launch_config = LaunchConfig()


def __getattr__(name: str) -> Any:
    """launch.logging.handlers, imported when first asked for (the standard library's
    logging.handlers brings sockets and pickle: a launch's start-up need not pay for them)."""
    if name == "handlers":
        import logging.handlers

        return logging.handlers
    raise AttributeError(f"module '{__name__}' has no attribute '{name}'")

"""launch.logging (launcher.api.logging)."""

from typing import Any

from launcher.api import logging as _logging
from launcher.api.logging import get_logger, get_output_loggers, launch_config, reset
from launcher.compat.finder import rest_from_layout

__all__ = ["get_logger", "get_output_loggers", "handlers", "launch_config", "reset"]

_rest = rest_from_layout(__name__)


def __getattr__(name: str) -> Any:
    return _logging.handlers if name == "handlers" else _rest(name)

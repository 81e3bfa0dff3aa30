"""rclpy.logging_service.LoggingService: a node's `~/get_logger_levels` and
`~/set_logger_levels` services (rcl_interfaces), which Node makes with
enable_logger_service=True."""

from __future__ import annotations

from typing import Any

from rcl_interfaces.msg import LoggerLevel, SetLoggerLevelsResult
from rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels

from rclpy.impl.logging_severity import LoggingSeverity
from rclpy.logging import get_logger, get_logger_level
from rclpy.validate_topic_name import TOPIC_SEPARATOR_STRING

__all__ = ["TOPIC_SEPARATOR_STRING", "LoggingService", "LoggingSeverity"]


class LoggingService:
    """The logger-level services of `node`."""

    def __init__(self, node: Any) -> None:
        node.create_service(GetLoggerLevels, "~/get_logger_levels", self._get_levels)
        node.create_service(SetLoggerLevels, "~/set_logger_levels", self._set_levels)

    @staticmethod
    def _get_levels(request: Any, response: Any) -> Any:
        """Each named logger's own level (0 when unset)."""
        response.levels = [LoggerLevel(name=name, level=int(get_logger_level(name)))
                           for name in request.names]
        return response

    @staticmethod
    def _set_levels(request: Any, response: Any) -> Any:
        """Set each named logger's level; a result for each."""
        results = []
        for wanted in request.levels:
            try:
                get_logger(wanted.name).set_level(LoggingSeverity(wanted.level))
                results.append(SetLoggerLevelsResult(successful=True))
            except ValueError:
                results.append(SetLoggerLevelsResult(
                    successful=False, reason=f"{wanted.level} is not a logging severity "
                                             "(0, 10, 20, 30, 40, 50)"))
        response.results = results
        return response

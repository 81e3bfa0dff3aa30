"""A node's logger (launcher's own nodes and sim): ROS 2's levels and line layout, warnings
and errors on stderr, the rest on stdout, as Gazebo's console writes them; `once=True` says
a message one time only. (A user's rclpy node logs as rcutils does: rclpy/logging.py.)"""

from __future__ import annotations

import sys
import threading
import time
from typing import TextIO

_LINES = threading.RLock()  # (a signal handler that logs mid-line must not deadlock)


def write_line(stream: TextIO, line: str) -> None:
    """Write `line` and its newline as one write, flushed, under one lock: a node's threads
    (a multi-threaded executor's callbacks) never run their lines into each other."""
    with _LINES:
        stream.write(line + "\n")
        stream.flush()


class Logger:
    LEVELS = {"DEBUG": 10, "INFO": 20, "WARN": 30, "ERROR": 40, "FATAL": 50}

    def __init__(self, name: str, level: str = "INFO") -> None:
        self.name, self.threshold = name, self.LEVELS.get(level.upper(), 20)
        self._once: set[str] = set()

    def _log(self, level: str, message: str, once: bool = False) -> None:
        if self.LEVELS[level] < self.threshold or (once and message in self._once):
            return
        self._once.add(message)
        stream = sys.stderr if self.LEVELS[level] >= 30 else sys.stdout
        stamp = time.time_ns()
        write_line(stream, f"[{level}] [{stamp // 1_000_000_000}.{stamp % 1_000_000_000:09d}] "
                           f"[{self.name}]: {message}")

    def debug(self, message: str, once: bool = False) -> None:
        self._log("DEBUG", message, once)

    def info(self, message: str, once: bool = False) -> None:
        self._log("INFO", message, once)

    def warning(self, message: str, once: bool = False) -> None:
        self._log("WARN", message, once)

    warn = warning

    def error(self, message: str, once: bool = False) -> None:
        self._log("ERROR", message, once)

    def fatal(self, message: str, once: bool = False) -> None:
        self._log("FATAL", message, once)

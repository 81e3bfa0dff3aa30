"""Output as typed records and a pure formatter over them.

Every line from every process, and every message of the launcher itself, becomes a `Record`.
`Printer.format` turns one into a line (`[name-1] text`, `[INFO] [launch]: text`), coloured when
writing to a terminal, or as the environment says (`color_wanted`); `Printer.emit` writes it.
A launcher message of several lines (a command's stderr, a value with a newline in it) has its
further lines indented, and carriage returns shown as `\r`, so no text the user controls can
pass for a line of the launcher's own.
"""

from __future__ import annotations

import os
import sys
import time
import zlib
from collections.abc import Mapping
from typing import NamedTuple, TextIO

from launcher.records import dataclass, field

LEVELS = ("DEBUG", "INFO", "WARN", "ERROR")


class Record(NamedTuple):
    source: str  # a process label (`talker-1`) or `launch`
    text: str
    stream: str = "stdout"  # stdout | stderr | launcher
    level: str | None = None  # for launcher messages
    time: float = 0.0  # seconds since the epoch; 0 means "when written"


def color_wanted(out: TextIO, environ: Mapping[str, str] = os.environ) -> bool:
    """Colour or not: RCUTILS_COLORIZED_OUTPUT=0/1 (ROS 2's own) says so; else NO_COLOR (set
    and not empty) says no; else FORCE_COLOR (set, not 0) says yes; else a terminal has it."""
    ros = environ.get("RCUTILS_COLORIZED_OUTPUT", "")
    if ros in ("0", "1"):
        return ros == "1"
    if environ.get("NO_COLOR"):
        return False
    if environ.get("FORCE_COLOR", "0") not in ("", "0"):
        return True
    return bool(getattr(out, "isatty", lambda: False)())


_COLORS = (31, 32, 33, 34, 35, 36, 91, 92, 93, 94, 95, 96)
_LEVEL_COLORS = {"DEBUG": 2, "INFO": 0, "WARN": 33, "ERROR": 31}


@dataclass
class Printer:
    out: TextIO = field(default_factory=lambda: sys.stdout)
    color: bool | None = None  # None: as color_wanted() says for `out`

    def __post_init__(self) -> None:
        if self.color is None:
            self.color = color_wanted(self.out)

    def format(self, record: Record) -> str:
        if record.level is not None:
            line = f"[{record.level}] [{record.source}]: {contained(record.text)}"
            code = _LEVEL_COLORS.get(record.level, 0)
            return f"\x1b[{code}m{line}\x1b[0m" if self.color and code else line
        label = f"[{record.source}]"
        if self.color:
            code = _COLORS[zlib.crc32(record.source.encode()) % len(_COLORS)]
            label = f"\x1b[{code}m{label}\x1b[0m"
        return f"{label} {record.text}"

    def emit(self, record: Record) -> None:
        try:
            self.out.write(self.format(record) + "\n")
            self.out.flush()
        except (BrokenPipeError, ValueError):  # stdout closed: keep supervising quietly
            pass


def plain(record: Record) -> str:
    """The record as it goes into log files: with a timestamp, never coloured."""
    stamp = f"{record.time or time.time():.7f}"
    if record.level is not None:
        return f"{stamp} [{record.level}] [{record.source}]: {contained(record.text)}"
    return f"{stamp} [{record.source}] {record.text}"


CONTINUATION = "    "


def contained(text: str) -> str:
    """A message's further lines indented; no bare carriage return."""
    return text.replace("\r", "\\r").replace("\n", "\n" + CONTINUATION)

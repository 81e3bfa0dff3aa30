"""Output as typed records and a pure formatter over them.

Every line from every process, and every message of the launcher itself, becomes a `Record`.
`Printer.format` turns one into a line (`[name-1] text`, `[INFO] [launch]: text`), coloured when
writing to a terminal, or as the environment says (`color_wanted`); `Printer.emit` writes it.
A launcher message of several lines (a command's stderr, a value with a newline in it) has its
further lines indented, and carriage returns shown as `\r`, so no text the user controls can
pass for a line of the launcher's own.

A launch's printer is `queued` (`start()`): its lines go to a thread that writes them, so a
screen slower than the processes' output (a terminal, a pipe read slowly) never holds up the
launch. At most SCREEN_BACKLOG bytes wait; past that, the processes' lines are not shown (the
log files have those that go to the log too, whole; `launcher logs` has the latest) and, once
the screen has caught up, one line says how many were not. The launcher's own messages are
never dropped. A screen that takes nothing for FLUSH_WAIT at the launch's end is let go: what
still waits is dropped, never written behind the launcher's back.
"""

from __future__ import annotations

import os
import sys
import threading
import time
import zlib
from collections import deque
from collections.abc import Mapping
from typing import NamedTuple, TextIO

from launcher.records import dataclass, field

LEVELS = ("DEBUG", "INFO", "WARN", "ERROR")
SCREEN_BACKLOG = 4 << 20  # bytes of lines waiting for the screen, past which lines are dropped
FLUSH_WAIT = 5.0  # seconds the end of a launch waits for the screen to take what waits


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


class ScreenQueue:
    """Lines for `out`, written by a thread of their own (see the module's words)."""

    def __init__(self, out: TextIO) -> None:
        self.out = out
        self._lines: deque[str] = deque()
        self._size = 0
        self.dropped = 0  # lines not shown since the last word about it
        self._ready = threading.Condition()
        self._closing = False
        self._abandoned = False  # (the end waited long enough: nothing more is written)
        self._thread = threading.Thread(target=self._write_all, name="screen", daemon=True)
        self._thread.start()

    def put(self, line: str, keep: bool) -> None:
        with self._ready:
            if not keep and self._size > SCREEN_BACKLOG:
                self.dropped += 1
                return
            self._lines.append(line)
            self._size += len(line)
            self._ready.notify()

    def _write_all(self) -> None:
        while True:
            with self._ready:
                while not self._lines and not self._closing:
                    self._ready.wait()
                if not self._lines:
                    return
                batch = "".join(self._lines)
                self._lines.clear()
                self._size = 0
                dropped, self.dropped = self.dropped, 0
                if self._abandoned:
                    return
            if dropped:
                batch += (f"[launch] {dropped} lines were not shown: the screen could not keep "
                          "up (`launcher logs` and the log files keep them)\n")
            try:
                self.out.write(batch)
                self.out.flush()
            except (BrokenPipeError, ValueError, OSError):  # stdout closed: quietly on
                pass

    def close(self) -> None:
        with self._ready:
            self._closing = True
            self._ready.notify()
        self._thread.join(FLUSH_WAIT)
        with self._ready:
            self._abandoned = True
            self._lines.clear()


@dataclass
class Printer:
    out: TextIO = field(default_factory=lambda: sys.stdout)
    color: bool | None = None  # None: as color_wanted() says for `out`
    queue: ScreenQueue | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        if self.color is None:
            self.color = color_wanted(self.out)

    def start(self) -> None:
        """From here on, lines are written by the screen's thread (a launch's printer)."""
        if self.queue is None:
            self.queue = ScreenQueue(self.out)

    def close(self) -> None:
        """Write what waits (up to FLUSH_WAIT), and write directly again."""
        queue, self.queue = self.queue, None
        if queue is not None:
            queue.close()

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
        queue = self.queue
        if queue is not None:
            queue.put(self.format(record) + "\n", keep=record.level is not None)
            return
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

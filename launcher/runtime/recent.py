"""The latest lines of each process, kept in memory for `launcher logs` (a launch with no log
files too): at most LINES lines and SIZE bytes a process, numbered from 1 in the order they
came, so that a follower asks for the lines after the last one it has."""

from __future__ import annotations

import time
from collections import deque
from typing import NamedTuple

LINES = 2000
SIZE = 256 << 10  # bytes of text


class Line(NamedTuple):
    number: int
    stream: str
    stamp: float
    text: str


class Kept:
    __slots__ = ("lines", "size", "count")

    def __init__(self) -> None:
        self.lines: deque[Line] = deque()
        self.size = 0
        self.count = 0  # lines ever added


class Recent:
    def __init__(self, lines: int = LINES, size: int = SIZE) -> None:
        self.most, self.most_size = lines, size
        self._kept: dict[str, Kept] = {}

    def add(self, name: str, stream: str, text: str) -> None:
        kept = self._kept.get(name)
        if kept is None:
            kept = self._kept[name] = Kept()
        kept.count += 1
        kept.lines.append(Line(kept.count, stream, time.time(), text))
        kept.size += len(text)
        while len(kept.lines) > self.most or (kept.size > self.most_size and
                                              len(kept.lines) > 1):
            kept.size -= len(kept.lines.popleft().text)

    def after(self, name: str, number: int) -> tuple[int, list[Line]]:
        """(the number of the first line still held, the held lines after `number`)."""
        kept = self._kept.get(name)
        if kept is None or not kept.lines:
            return (kept.count + 1 if kept else 1), []
        first = kept.lines[0].number
        skip = max(0, number - first + 1)
        return first, [kept.lines[i] for i in range(skip, len(kept.lines))]

"""What each process of the launch costs: CPU (percent of one core) and resident memory of its
process group, sampled once a second from /proc (one pass over it for every process), kept for
`launcher ps` and written to `processes.csv` in the run's log folder (`launcher plot
--processes` draws it). A process on another host has no figures here."""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Iterable
from pathlib import Path

from launcher.runtime.logs import DEFAULT_LIMIT, LogFile

PERIOD = 1.0  # seconds between samples
HEADER = "time,name,pid,cpu_percent,rss_bytes\n"
_TICKS = os.sysconf("SC_CLK_TCK")
_PAGE = os.sysconf("SC_PAGE_SIZE")


class Figure:
    __slots__ = ("cpu", "memory")

    def __init__(self, cpu: float, memory: int) -> None:
        self.cpu, self.memory = cpu, memory


def groups(proc: Path = Path("/proc")) -> dict[int, tuple[int, int]]:
    """Each process group → (its CPU ticks, its resident pages), over every process."""
    found: dict[int, tuple[int, int]] = {}
    for name in os.listdir(proc):
        if not name.isdigit():
            continue
        try:
            with open(proc / name / "stat", "rb") as handle:
                stat = handle.read()
        except OSError:
            continue
        fields = stat[stat.rfind(b")") + 2:].split()
        # (after the command: state, ppid, pgrp, …, utime at 14, stime 15, rss 24; 1-based)
        pgrp, ticks, pages = int(fields[2]), int(fields[11]) + int(fields[12]), int(fields[21])
        was = found.get(pgrp, (0, 0))
        found[pgrp] = (was[0] + ticks, was[1] + pages)
    return found


class Figures:
    def __init__(self, folder: Path | None, limit: int = DEFAULT_LIMIT,
                 read: Callable[[], dict[int, tuple[int, int]]] = groups,
                 clock: Callable[[], float] = time.monotonic) -> None:
        """`folder`: the run's log folder (None: no file); `limit`: the size at which the
        file rotates, as the run's logs do."""
        self.read, self.clock, self.limit = read, clock, limit
        self.now: dict[int, Figure] = {}  # pid (its group's leader) → its latest figures
        self._before: dict[int, int] = {}  # pid → CPU ticks at the previous sample
        self._when = 0.0
        self._csv: LogFile | None = None
        self.path = folder / "processes.csv" if folder is not None else None

    def sample(self, processes: Iterable[tuple[str, int]]) -> None:
        """Sample the groups of `processes` ((name, pid) of each running one)."""
        now = self.clock()
        elapsed = now - self._when if self._when else 0.0
        self._when = now
        try:
            table = self.read()
        except OSError:  # (no file descriptor to spare, /proc unreadable: the last ones stay)
            return
        figures: dict[int, Figure] = {}
        ticks: dict[int, int] = {}
        rows = []
        stamp = time.time()
        for name, pid in processes:
            used, pages = table.get(pid, (0, 0))
            before = self._before.get(pid)
            cpu = max(0.0, 100.0 * (used - before) / _TICKS / elapsed) \
                if before is not None and elapsed > 0 else 0.0  # (a member gone: not < 0)
            ticks[pid] = used
            figures[pid] = Figure(cpu, pages * _PAGE)
            rows.append(f"{stamp:.3f},{name},{pid},{cpu:.1f},{pages * _PAGE}\n")
        self.now, self._before = figures, ticks
        self._write(rows)

    def _write(self, rows: list[str]) -> None:
        if self.path is None or not rows:
            return
        try:
            if self._csv is None:
                self._csv = LogFile(self.path, self.limit, HEADER)
            for row in rows:
                self._csv.write(row)
            self._csv.flush()
        except OSError:  # (a full disk: the figures for ps go on, the file stops)
            self.path = None

    def close(self) -> None:
        if self._csv is not None:
            self._csv.close()
            self._csv = None

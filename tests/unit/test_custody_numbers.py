"""Custody tells its watchdog when an adopted child is collected, wherever it is collected: a
collected child's number may soon be an unrelated process's, which the watchdog would end at
the launch's end as the launch's."""

from __future__ import annotations

import os
import time
from pathlib import Path

from launcher.runtime.custody import Custody


def watched_custody() -> tuple[Custody, int]:
    """A custody whose watchdog is a pipe the test reads."""
    read, write = os.pipe()
    custody = Custody()
    custody.watchdog = (-1, write)
    return custody, read


def exited_child() -> int:
    pid = os.fork()
    if pid == 0:
        os._exit(0)
    stat = Path(f"/proc/{pid}/stat")
    while stat.read_text().split()[2] != "Z":  # (a zombie: it has exited, not been collected)
        time.sleep(0.001)
    return pid


def told(read: int) -> list[str]:
    os.set_blocking(read, False)
    try:
        return os.read(read, 4096).decode().split()
    except BlockingIOError:
        return []


def test_a_child_collected_at_the_end_is_forgotten_by_the_watchdog():
    custody, read = watched_custody()
    pid = exited_child()
    custody.adopted.add(pid)
    assert pid not in custody.leftovers()
    assert told(read) == [f"p-{pid}"]
    assert pid not in custody.adopted


def test_a_child_collected_on_a_tick_is_forgotten_by_the_watchdog():
    custody, read = watched_custody()
    pid = exited_child()
    custody.adopted.add(pid)
    custody.tick(set())
    assert told(read) == [f"p-{pid}"]

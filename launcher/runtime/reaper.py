"""The watchdog that ends a launch's processes if the launcher itself dies, even by SIGKILL.

`fork_watchdog()` forks the launcher (before it has threads or children) into a small process
in its own session that reads a pipe. The launcher writes `+PGID` when it starts a process
group and `-PGID` when the group is gone. When the pipe closes (the launcher exited, however
it exited) every group still listed gets SIGTERM, and SIGKILL after a grace period. Terminal
signals are ignored; SIGTERM to the watchdog itself runs the same clean-up.
"""

from __future__ import annotations

import os
import signal
import time

from launcher.runtime.system import group_alive

GRACE_SECONDS = 1.0


def _signal_all(groups: set[int], sig: int) -> None:
    for pgid in list(groups):
        try:
            os.killpg(pgid, sig)
        except (ProcessLookupError, PermissionError):
            groups.discard(pgid)


def clean_up(groups: set[int]) -> None:
    """SIGTERM every group, then SIGKILL what is left after the grace period."""
    _signal_all(groups, signal.SIGTERM)
    deadline = time.monotonic() + GRACE_SECONDS
    while groups and time.monotonic() < deadline:
        groups.intersection_update({g for g in groups if group_alive(g)})
        time.sleep(0.02)
    _signal_all(groups, signal.SIGKILL)


def watch(fd: int) -> None:
    """Follow the `+PGID`/`-PGID` lines on fd until it closes, then clean up."""
    groups: set[int] = set()

    def on_term(_signum: int, _frame: object) -> None:
        clean_up(groups)
        os._exit(0)

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGHUP, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, on_term)
    pending = b""
    while chunk := os.read(fd, 4096):
        *lines, pending = (pending + chunk).split(b"\n")
        for line in lines:
            if line.startswith(b"+"):
                groups.add(int(line[1:]))
            elif line.startswith(b"-"):
                groups.discard(int(line[1:]))
    clean_up(groups)


def fork_watchdog() -> tuple[int, int]:
    """Start the watchdog; return (its pid, the fd to write to). Call before any thread."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the watchdog: never return into the launcher's code
        code = 0
        try:
            os.setsid()
            os.close(write)
            watch(read)
        except BaseException:  # noqa: BLE001 - nothing to report to; still clean up
            code = 1
        finally:
            os._exit(code)
    os.close(read)
    os.set_inheritable(write, False)
    return pid, write

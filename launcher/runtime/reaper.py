"""The watchdog that ends a launch's processes if the launcher itself dies, even by SIGKILL.

`fork_watchdog(mark)` forks the launcher (before it has threads or children) into a small
process in its own session that reads a pipe. The launcher writes `+PGID` when it starts a
process group and `-PGID` when the group is gone, and `p+PID` / `p-PID` for a process it
adopted (see lineage.py). When the pipe closes (the launcher exited, however it exited) the
watchdog ends everything that is still the launch's: those groups and processes, and every
process carrying the launch's mark, including ones that were only being spawned when the
launcher died (it looks again until a look finds nothing). SIGTERM first, SIGKILL after a
grace period. Terminal signals are ignored; SIGTERM to the watchdog itself runs the same
clean-up. A launch that ended and found nothing of its own left says `=` last: the watchdog
then only checks the groups it was told of, and exits.
"""

from __future__ import annotations

import contextlib
import os
import signal
import time

from launcher import lineage
from launcher.runtime.system import group_alive

GRACE_SECONDS = 1.0
LOOKS = 3  # looks for marked processes that find nothing before the watchdog is done
LOOK_INTERVAL = 0.05  # seconds between them


class Launch:
    """What the watchdog knows of the launch."""

    def __init__(self, mark: str | None) -> None:
        self.mark = mark
        self.groups: set[int] = set()
        self.pids: set[int] = set()
        self.ended = False  # the launcher said it ended with nothing of the launch left

    def follow(self, line: bytes) -> None:
        if line == b"=":
            self.ended = True
            return
        self.ended = False  # (nothing follows "=" from a launcher that keeps its word)
        kind, number = (line[:2], line[2:]) if line.startswith(b"p") else (line[:1], line[1:])
        with contextlib.suppress(ValueError):
            target = self.pids if kind.startswith(b"p") else self.groups
            (target.add if kind.endswith(b"+") else target.discard)(int(number))

    def live(self) -> tuple[set[int], set[int]]:
        """(groups, pids) of the launch still running."""
        self.groups = lineage.live_groups({g for g in self.groups if group_alive(g)})
        self.pids = {p for p in self.pids if lineage.alive(p)}
        if self.mark:
            self.pids |= lineage.marked(self.mark)
        return self.groups, self.pids

    def clean_up(self, grace: float = GRACE_SECONDS) -> None:
        """End everything of the launch: SIGTERM, then SIGKILL `grace` seconds later."""
        if self.ended and not lineage.live_groups({g for g in self.groups if group_alive(g)}):
            return  # the launcher looked last: nothing of the launch was left
        quiet = 0
        while quiet < LOOKS:
            groups, pids = self.live()
            if not groups and not pids:
                quiet += 1
                time.sleep(LOOK_INTERVAL)
                continue
            quiet = 0
            _signal(groups, pids, signal.SIGTERM)
            deadline = time.monotonic() + grace
            while time.monotonic() < deadline and any(self.live()):
                time.sleep(0.02)
            _signal(*self.live(), signal.SIGKILL)


def _signal(groups: set[int], pids: set[int], sig: int) -> None:
    for pgid in groups:
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.killpg(pgid, sig)
    lineage.signal_all(pids, sig)


def watch(fd: int, mark: str | None) -> None:
    """Follow the lines on fd until it closes, then clean up."""
    launch = Launch(mark)

    def on_term(_signum: int, _frame: object) -> None:
        launch.clean_up()
        os._exit(0)

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGHUP, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, on_term)
    pending = b""
    while chunk := os.read(fd, 4096):
        *lines, pending = (pending + chunk).split(b"\n")
        for line in lines:
            launch.follow(line)
    launch.clean_up()


def _let_go_of_streams(keep: int) -> None:
    """Close every inherited fd but `keep`, the standard ones onto /dev/null: a launcher
    whose stdout is a pipe (the remote supervisor's: ssh's channel) is seen to end when that
    closes, which a watchdog holding a copy would put off until its own end."""
    null = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        if fd != null:
            os.dup2(null, fd)
    for name in os.listdir("/proc/self/fd"):
        if int(name) > 2 and int(name) != keep:
            with contextlib.suppress(OSError):  # (listdir's own fd, closed already)
                os.close(int(name))


def fork_watchdog(mark: str | None = None) -> tuple[int, int]:
    """Start the watchdog; return (its pid, the fd to write to). Call before any thread."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the watchdog: never return into the launcher's code
        code = 0
        try:
            os.setsid()
            _let_go_of_streams(read)
            watch(read, mark)
        except BaseException:  # noqa: BLE001 - nothing to report to; still clean up
            code = 1
        finally:
            os._exit(code)
    os.close(read)
    os.set_inheritable(write, False)
    return pid, write

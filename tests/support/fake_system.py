"""A recording fake of the operating system for supervision's unit tests: spawns, signals and
exits that the test makes happen (runtime/system.py's System, without processes)."""

from __future__ import annotations

import itertools

from launcher.runtime.system import Started
from tests.support.fake_loop import FakeLoop


class FakeSystem:
    """Records spawns and signals; the test says when a process writes, exits, and whether
    its group still holds anything."""

    def __init__(self, fail_spawns: int = 0) -> None:
        self.pids = itertools.count(100)
        self.fds = itertools.count(10)
        self.spawned: list[int] = []
        self.signals: list[tuple[int, int]] = []
        self.group: dict[int, bool] = {}
        self.exits: dict[int, object] = {}
        self.output: dict[int, list[bytes]] = {}
        self.closed: list[int] = []
        self.fail_spawns = fail_spawns
        self.loop: FakeLoop | None = None

    def spawn(self, argv, env, cwd, tty):
        if self.fail_spawns:
            self.fail_spawns -= 1
            raise FileNotFoundError(2, "No such file or directory", argv[0])
        pid = next(self.pids)
        self.spawned.append(pid)
        self.group[pid] = True
        started = Started(pid, next(self.fds), next(self.fds))
        self.output[started.stdout], self.output[started.stderr] = [], []
        self.streams = started
        return started

    def watch_exit(self, pid, loop, exited):
        self.exits[pid] = exited

    def read(self, fd):
        chunks = self.output[fd]
        return chunks.pop(0) if chunks else b""

    def close(self, fd):
        self.closed.append(fd)

    def kill_group(self, pgid, sig):
        self.signals.append((pgid, sig))

    def group_alive(self, pgid):
        return self.group.get(pgid, False)

    def end_servers(self):
        self.servers_ended = True

    # --- what the test makes happen ---------------------------------------------------------
    def leader_exits(self, loop: FakeLoop, pid: int, code: int, group_empty: bool = True):
        """The leader ends with `code`: its output reaches its end, then it is reaped."""
        self.group[pid] = not group_empty
        for fd in (self.streams.stdout, self.streams.stderr):
            if fd in loop.readers:
                loop.ready(fd)
        self.exits.pop(pid)(code)

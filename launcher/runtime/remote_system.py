"""A process on another host as supervision sees it: the `Processes` of runtime/system.py over a
host's link, so that respawn, escalation, `required`, the event handlers and the exit status
run the same code for it as for a local one.

Its output arrives in frames; each stream is a local pipe used as a doorbell (the loop reads
it as it reads a child's pipe) in front of the bytes kept here. Its pid is the one on its host;
its process group is signalled there. A link that is lost ends its processes: their streams
end and they "exit" without a code (they could not be waited for), as a local process that
could not be waited on.
"""

from __future__ import annotations

import contextlib
import errno
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launcher.runtime.machine import RemoteStart
from launcher.runtime.system import Started

FILES_MAX = 8 << 20  # bytes of parameter files one start may carry to a host
SPAWN_WAIT = 10.0  # s a start may take there before it is taken as failed


class Stream:
    """One output stream of a remote process: a doorbell pipe and the bytes behind it."""

    def __init__(self) -> None:
        self.read_fd, self.write_fd = os.pipe()
        os.set_blocking(self.read_fd, False)
        os.set_blocking(self.write_fd, False)
        self.data = bytearray()
        self.ended = False

    def ring(self) -> None:
        with contextlib.suppress(BlockingIOError, OSError):
            os.write(self.write_fd, b"\0")

    def take(self) -> bytes | None:
        with contextlib.suppress(BlockingIOError, OSError):
            os.read(self.read_fd, 4096)
        if self.data:
            data, self.data = bytes(self.data), bytearray()
            return data
        return b"" if self.ended else None

    def close(self) -> None:
        for fd in (self.read_fd, self.write_fd):
            with contextlib.suppress(OSError):
                os.close(fd)


class RemoteProcess:
    """What the link knows of one started process (by its id in the frames)."""

    def __init__(self, ident: int) -> None:
        self.ident = ident
        self.pid = 0
        self.streams = {1: Stream(), 2: Stream()}
        self.exited: Callable[[int | None], None] | None = None
        self.code: int | None = None
        self.done = False  # its exit is known
        self.group_alive = True
        self.answer: dict[str, Any] | None = None  # started / failed


class RemoteSystem:
    """The `Processes` of one ManagedProcess on a host (`start`: how it starts there)."""

    def __init__(self, host: Any, start: RemoteStart) -> None:
        self.host, self.start = host, start
        self._current: RemoteProcess | None = None

    def spawn(self, argv: list[str], env: dict[str, str], cwd: str | None,
              tty: bool) -> Started:
        """Start it there; OSError as for a local process (not found, cannot start)."""
        process = self.host.start(self.start, argv, env, cwd, tty)
        self._current = process
        return Started(process.pid, process.streams[1].read_fd, process.streams[2].read_fd)

    def watch_exit(self, pid: int, loop: Any, exited: Callable[[int | None], None]) -> None:
        process = self._current
        assert process is not None and process.pid == pid
        if process.done:
            loop.call_soon(exited, process.code)
        else:
            process.exited = exited

    def read(self, fd: int) -> bytes | None:
        process = self._current
        if process is None:
            return b""
        for stream in process.streams.values():
            if stream.read_fd == fd:
                return stream.take()
        return b""

    def close(self, fd: int) -> None:
        process = self._current
        if process is None:
            return
        for stream in process.streams.values():
            if stream.read_fd == fd:
                stream.close()

    def kill_group(self, pgid: int, sig: int) -> None:
        process = self._current
        if process is not None and process.pid == pgid and process.group_alive:
            self.host.signal(process, sig)

    def group_alive(self, pgid: int) -> bool:
        process = self._current
        return process is not None and process.pid == pgid and process.group_alive


def shipped_files(paths: tuple[str, ...], label: str) -> list[dict[str, str]]:
    """The text of each file a start carries to its host (the node's parameter files)."""
    files, total = [], 0
    for path in paths:
        try:
            text = Path(path).read_text(encoding="utf-8")
        except OSError as exc:
            raise OSError(exc.errno or errno.EIO, f"cannot read {path} to send it: "
                                                  f"{exc.strerror}") from None
        total += len(text.encode())
        if total > FILES_MAX:
            raise OSError(errno.E2BIG, f"{label}'s parameter files are {total >> 20} MB or "
                                       f"more; at most {FILES_MAX >> 20} MB go to another host")
        files.append({"path": path, "text": text})
    return files

"""The operating system as supervision sees it: start a process in its own session with its
output on pipes (or a pty), learn when it exits, read its output, signal its process group.

`System` does it for real (subprocess, pidfd, killpg); tests hand ManagedProcess a recording
fake with the same methods, so escalation, respawn and exit codes can be replayed as event
histories in milliseconds.
"""

from __future__ import annotations

import contextlib
import errno
import os
import pty
import subprocess
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, NamedTuple, Protocol

from launcher.dispositions import reset_for_children

if TYPE_CHECKING:
    from launcher.runtime.warm import WarmStarts

EXIT_POLL = 0.01  # seconds between looks at a leader's exit where there is no pidfd


class Started(NamedTuple):
    pid: int
    stdout: int  # file descriptors to read its output from (non-blocking)
    stderr: int


class Processes(Protocol):
    def spawn(self, argv: list[str], env: dict[str, str], cwd: str | None,
              tty: bool) -> Started: ...

    def watch_exit(self, pid: int, loop: Any, exited: Callable[[int | None], None]) -> None: ...

    def read(self, fd: int) -> bytes | None: ...

    def close(self, fd: int) -> None: ...

    def kill_group(self, pgid: int, sig: int) -> None: ...

    def group_alive(self, pgid: int) -> bool: ...

    def end_servers(self) -> None: ...


class System:
    """The real one; with `warm`, Python processes start warm where they can
    (runtime/warm.py)."""

    def __init__(self, warm: WarmStarts | None = None) -> None:
        self._children: dict[int, subprocess.Popen | Adopted] = {}
        self.warm = warm

    def spawn(self, argv: list[str], env: dict[str, str], cwd: str | None,
              tty: bool) -> Started:
        """Start `argv` in a session of its own. OSError (not found, not executable, bad
        cwd) goes to the caller. It starts with the stop signals at their defaults."""
        reset_for_children()
        out_r, out_w = _channel(tty)
        err_r, err_w = _channel(tty)
        try:
            pid = self._warm(argv, env, cwd, out_w, err_w) if not tty else None
            child = Adopted(pid) if pid is not None else subprocess.Popen(
                argv, stdin=subprocess.DEVNULL, stdout=out_w, stderr=err_w, cwd=cwd, env=env,
                start_new_session=True, close_fds=True)
        except BaseException:
            os.close(out_r)
            os.close(err_r)
            raise
        finally:
            os.close(out_w)
            os.close(err_w)
        self._children[child.pid] = child
        for fd in (out_r, err_r):
            os.set_blocking(fd, False)
        return Started(child.pid, out_r, err_r)

    def _warm(self, argv: list[str], env: dict[str, str], cwd: str | None, out: int,
              err: int) -> int | None:
        if self.warm is None:
            return None
        null = os.open(os.devnull, os.O_RDONLY)
        try:
            return self.warm.start(argv, env, cwd, [null, out, err])
        finally:
            os.close(null)

    def end_servers(self) -> None:
        """The warm start's servers end (what they started is the launch's, as any child):
        at the launch's end, before it looks for what its processes left running."""
        if self.warm is not None:
            self.warm.close()

    def watch_exit(self, pid: int, loop: Any, exited: Callable[[int | None], None]) -> None:
        """Call `exited(returncode)` on the loop when the process ends (a pidfd, or polls)."""
        try:
            pidfd = os.pidfd_open(pid)
        except (AttributeError, OSError):  # no pidfd on this system: poll
            loop.call_later(EXIT_POLL, self._poll, pid, loop, exited)
            return

        def readable(fd: int) -> None:
            loop.remove_reader(fd)
            os.close(fd)
            self._poll(pid, loop, exited)

        loop.add_reader(pidfd, readable, pidfd)

    def _poll(self, pid: int, loop: Any, exited: Callable[[int | None], None]) -> None:
        child = self._children[pid]
        if child.poll() is None:
            loop.call_later(EXIT_POLL, self._poll, pid, loop, exited)
            return
        del self._children[pid]
        exited(child.returncode)

    def read(self, fd: int) -> bytes | None:
        """What is there to read: None for nothing now, b"" at the end."""
        try:
            return os.read(fd, 65536)
        except BlockingIOError:
            return None
        except OSError as exc:  # a pty reads EIO once the other side is closed
            if exc.errno != errno.EIO:
                raise
            return b""

    def close(self, fd: int) -> None:
        os.close(fd)

    def kill_group(self, pgid: int, sig: int) -> None:
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.killpg(pgid, sig)

    def group_alive(self, pgid: int) -> bool:
        return group_alive(pgid)


class Adopted:
    """A child the launcher did not fork itself (a warm start's: runtime/warm.py), waited for
    as subprocess waits for its own: `poll()` and `returncode`, negative for a signal."""

    def __init__(self, pid: int) -> None:
        self.pid = pid
        self.returncode: int | None = None

    def poll(self) -> int | None:
        if self.returncode is None:
            try:
                done, status = os.waitpid(self.pid, os.WNOHANG)
            except ChildProcessError:  # (reaped elsewhere: its status is lost)
                self.returncode = 255
                return self.returncode
            if done == self.pid:
                self.returncode = os.waitstatus_to_exitcode(status)
        return self.returncode


def group_alive(pgid: int) -> bool:
    """Whether any process is left in the group (one we may not signal counts too)."""
    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _channel(tty: bool) -> tuple[int, int]:
    """A (read, write) pair for one output stream: a pipe, or a pty when emulating a tty."""
    return pty.openpty() if tty else os.pipe()

"""The processes a remote supervisor (supervisor.py) started for its launch, and what it tells
the launch of each, in the order a local child shows it to ManagedProcess: its output, the end
of each stream, its exit code, then its process group empty.

Policy (respawn, escalation, what an exit means) is the launching host's; here a process is
only started, read, signalled and watched. Each runs in a session of its own, as locally
(system.py).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.records import dataclass, field
from launcher.runtime import remote_frames as frames
from launcher.runtime.loop import EventLoop, Timer
from launcher.runtime.process import GROUP_POLL, STREAM_GRACE
from launcher.runtime.remote_frames import ProtocolError
from launcher.runtime.system import Processes


@dataclass(frozen=True)
class StartRequest:
    """A `start` message, checked."""

    ident: int
    label: str
    argv: list[str]
    package: str | None
    executable: str | None
    at: int
    env_set: dict[str, str]
    env_unset: list[str]
    cwd: str | None
    tty: bool
    files: list[tuple[str, str]]  # (path on the launching host, text)

    @classmethod
    def parse(cls, body: dict[str, Any]) -> StartRequest:
        """ProtocolError names the first field that is not what `start` takes."""
        argv = _field(body, "argv", list, "a list")
        at = _field(body, "at", int, "an index into argv", 0)
        if not 0 <= at <= len(argv):
            raise ProtocolError(f"start: 'at' is {at}; expected an index into argv "
                                f"(0 to {len(argv)})")
        env_set = _field(body, "env_set", dict, "an object", {})
        env_unset = _field(body, "env_unset", list, "a list", [])
        if not _strings(*argv, *env_set, *env_set.values(), *env_unset):
            raise ProtocolError("start: argv, env_set and env_unset hold strings only")
        files = []
        for entry in _field(body, "files", list, "a list", []):
            if not isinstance(entry, dict) or not _strings(entry.get("path"),
                                                            entry.get("text")) \
                    or not entry["path"]:
                raise ProtocolError(f"start: a file is {str(entry)[:80]}; expected "
                                    "{\"path\": a path, \"text\": its text}")
            files.append((entry["path"], entry["text"]))
        return cls(ident=_field(body, "id", int, "a number"),
                   label=_field(body, "label", str, "a text", ""), argv=argv,
                   package=_field(body, "package", str | None, "a name or null", None),
                   executable=_field(body, "executable", str | None, "a name or null", None),
                   at=at, env_set=env_set, env_unset=env_unset,
                   cwd=_field(body, "cwd", str | None, "a path or null", None),
                   tty=_field(body, "tty", bool, "true or false", False), files=files)


def _field(body: dict[str, Any], name: str, kind: Any, expected: str,
           default: Any = ...) -> Any:
    value = body.get(name, default)
    if value is ...:
        raise ProtocolError(f"start: '{name}' is missing")
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        raise ProtocolError(f"start: '{name}' is {str(value)[:80]!r}; expected {expected}")
    return value


def _strings(*values: Any) -> bool:
    return all(isinstance(value, str) for value in values)


@dataclass
class Child:
    ident: int
    pid: int
    streams: dict[int, int]  # open fd → stream number (frames.STDOUT or STDERR)
    code: int | None = None
    leader_gone: bool = False
    reported: bool = False  # its exit has been told
    timer: Timer | None = field(default=None, repr=False)


class Children:
    def __init__(self, loop: EventLoop, system: Processes, send: Callable[[bytes], None],
                 group: Callable[[int, bool], None], gone: Callable[[int], None]) -> None:
        """`send` takes frames for the launch; `group(pgid, alive)` tells the watchdog;
        `gone(ident)` once a process's group is empty (its files may go)."""
        self.loop, self.system, self.send = loop, system, send
        self.group, self.gone = group, gone
        self.running: dict[int, Child] = {}
        self.paused = False

    def start(self, ident: int, argv: list[str], env: dict[str, str], cwd: str | None,
              tty: bool) -> int:
        """Spawn it; its pid. OSError (not found, not executable, bad cwd) goes to the caller."""
        with self.loop.shielded():  # (a signal must not land between spawn and record)
            started = self.system.spawn(argv, env, cwd, tty)
            child = Child(ident, started.pid, {started.stdout: frames.STDOUT,
                                               started.stderr: frames.STDERR})
            self.running[ident] = child
            self.group(child.pid, True)
        if not self.paused:
            self._read(child)
        self.system.watch_exit(child.pid, self.loop, lambda code: self._leader_exited(child,
                                                                                      code))
        return child.pid

    def signal(self, ident: int, sig: int) -> None:
        child = self.running.get(ident)
        if child is not None:  # (one whose group is gone: nothing to signal)
            self.system.kill_group(child.pid, sig)

    def leaders(self) -> set[int]:
        """The processes system.py has yet to collect (no one else may wait for them)."""
        return {c.pid for c in self.running.values() if not c.leader_gone}

    def groups(self) -> set[int]:
        return {c.pid for c in self.running.values()}

    def end_all(self) -> None:
        """Stop reading and watching (the supervisor is ending them all, then itself)."""
        for child in self.running.values():
            for fd in list(child.streams):
                self.loop.remove_reader(fd)
            if child.timer is not None:
                child.timer.cancel()

    # --- output -----------------------------------------------------------------------------
    def pause(self, paused: bool) -> None:
        """Stop (or go on) reading every process's output: the launch is not taking it as
        fast as they write, and they then wait, as behind a slow terminal."""
        if paused == self.paused:
            return
        self.paused = paused
        for child in self.running.values():
            if paused:
                for fd in child.streams:
                    self.loop.remove_reader(fd)
            else:
                self._read(child)

    def _read(self, child: Child) -> None:
        for fd in child.streams:
            self.loop.add_reader(fd, self._readable, child, fd)

    def _readable(self, child: Child, fd: int) -> None:
        data = self.system.read(fd)
        if data is None:
            return
        if data:
            self.send(frames.output(child.ident, child.streams[fd], data))
            return
        self._end_stream(child, fd)
        self._maybe_report(child)

    def _end_stream(self, child: Child, fd: int) -> None:
        stream = child.streams.pop(fd)
        self.loop.remove_reader(fd)
        self.system.close(fd)
        self.send(frames.message({"t": "eof", "id": child.ident, "stream": stream}))

    # --- the end of one -----------------------------------------------------------------------
    def _leader_exited(self, child: Child, code: int | None) -> None:
        child.code, child.leader_gone = code, True
        if child.streams:  # something it started may hold them: not for long
            child.timer = self.loop.call_later(STREAM_GRACE, self._streams_over, child)
        self._maybe_report(child)

    def _streams_over(self, child: Child) -> None:
        child.timer = None
        if self.paused:  # what is in its pipes is still to be read
            child.timer = self.loop.call_later(STREAM_GRACE, self._streams_over, child)
            return
        for fd in list(child.streams):
            self._end_stream(child, fd)
        self._maybe_report(child)

    def _maybe_report(self, child: Child) -> None:
        if child.reported or not child.leader_gone or child.streams:
            return
        child.reported = True
        if child.timer is not None:
            child.timer.cancel()
            child.timer = None
        self.send(frames.message({"t": "exited", "id": child.ident, "code": child.code}))
        self._watch_group(child)

    def _watch_group(self, child: Child) -> None:
        if self.running.get(child.ident) is not child:  # (ended by the supervisor's end)
            return
        if self.system.group_alive(child.pid):
            self.loop.call_later(GROUP_POLL, self._watch_group, child)
            return
        del self.running[child.ident]
        self.group(child.pid, False)
        self.send(frames.message({"t": "group", "id": child.ident, "alive": False}))
        self.gone(child.ident)


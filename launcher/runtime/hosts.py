"""The other hosts of a launch: one link each (host_link.py), opened when the first process
sent there starts, shared by every process sent there (machines with the same settings are one
host, as roslaunch unifies them), and closed when the launch ends.

A process there is started with its argv and with the environment the launch gave it, told as
what differs from the launch's own (the host's environment is its own: its login, its
env-loader); its executable is found there, and its parameter files travel with it. What the
launch asks of it (signals) and what it does (output, exit, its group gone) go over the link.
"""

from __future__ import annotations

import errno
import itertools
import os
import selectors
import shutil
import tempfile
import time
from collections.abc import Callable, Mapping
from typing import Any, Protocol

from launcher.errors import LaunchError
from launcher.lineage import MARK_PREFIX
from launcher.runtime import ssh
from launcher.runtime.host_link import PING, SLICE, HostLink
from launcher.runtime.loop import EventLoop
from launcher.runtime.machine import Machine, RemoteStart
from launcher.runtime.remote_system import SPAWN_WAIT, RemoteProcess, RemoteSystem, shipped_files

GOODBYE_WAIT = 1.0  # s a host is given to end what is left and say `done`

class Graph(Protocol):
    """How another host joins the launch's graph (the cli's, which knows the bus)."""

    def join(self, address: str) -> dict[str, Any]:
        """For a host that reaches this one at `address`: where, and with what."""

    def close(self) -> None: ...


class RemoteHost:
    """One host: its link and the processes started there."""

    def __init__(self, link: HostLink, loop: EventLoop, base: Mapping[str, str],
                 log: Callable[[str, str, str], None]) -> None:
        self.link, self.loop, self._base, self._log = link, loop, base, log
        self.processes: dict[int, RemoteProcess] = {}
        self._ids = itertools.count(1)
        self.done = False
        self.on_done: Callable[[], None] = lambda: None
        link.on_message, link.on_output, link.on_lost = self._on_message, self._on_output, \
            self._on_lost

    @property
    def name(self) -> str:
        return self.link.name

    # --- starting ---------------------------------------------------------------------------
    def start(self, start: RemoteStart, argv: list[str], env: dict[str, str], cwd: str | None,
              tty: bool) -> RemoteProcess:
        """Start a process there and wait for its pid; OSError when it cannot start."""
        if self.link.lost:
            raise OSError(errno.ENOTCONN, f"machine '{self.name}' is lost ({self.link.lost})")
        process = RemoteProcess(next(self._ids))
        self.processes[process.ident] = process
        label = start.executable or (argv[0] if argv else "process")
        set_, unset = self._delta(env)
        self.link.send({"t": "start", "id": process.ident, "label": label, "argv": argv,
                        "package": start.package, "executable": start.executable,
                        "at": start.at, "env_set": set_, "env_unset": unset, "cwd": cwd,
                        "tty": tty, "files": shipped_files(start.files, label)})
        answer = self._wait_answer(process)
        if answer.get("t") != "started":
            del self.processes[process.ident]
            text = str(answer.get("text") or "it could not start")
            raise OSError(int(answer.get("errno") or errno.EIO),
                          text if self.name in text else f"{text} (on {self.name})")
        process.pid = int(answer["pid"])
        return process

    def _delta(self, env: Mapping[str, str]) -> tuple[dict[str, str], list[str]]:
        """What the launch changed in a process's environment (not the launch's marks: the
        host's supervisor marks its own)."""
        base = self._base
        changed = {key: value for key, value in env.items()
                   if base.get(key) != value and not key.startswith(MARK_PREFIX)}
        removed = [key for key in base if key not in env and not key.startswith(MARK_PREFIX)]
        return changed, removed

    def _wait_answer(self, process: RemoteProcess) -> dict[str, Any]:
        """Read the link until the host answers this start (frames for others are kept)."""
        deadline = time.monotonic() + SPAWN_WAIT
        fd = self.link.stdout_fd
        with selectors.DefaultSelector() as selector:
            selector.register(fd, selectors.EVENT_READ)
            while process.answer is None:
                if self.link.lost:
                    raise OSError(errno.ENOTCONN,
                                  f"machine '{self.name}' is lost ({self.link.lost})")
                left = deadline - time.monotonic()
                if left <= 0:
                    raise OSError(errno.ETIMEDOUT, f"machine '{self.name}' did not answer "
                                                   f"within {SPAWN_WAIT:g} s")
                if selector.select(min(left, SLICE)):  # (slices: see HostLink's wait)
                    self.link.read_now()
        return process.answer

    # --- what the host says -----------------------------------------------------------------
    def _on_message(self, body: dict[str, Any]) -> None:
        kind = body.get("t")
        process = self.processes.get(int(body.get("id", 0) or 0))
        if kind == "done":
            self.done = True
            self.on_done()
        elif process is None:
            return
        elif kind in ("started", "failed"):
            process.answer = body
        elif kind == "eof":
            stream = process.streams.get(int(body.get("stream", 1)))
            if stream is not None:
                stream.ended = True
                stream.ring()
        elif kind == "exited":
            self._exited(process, body.get("code"))
        elif kind == "group":
            process.group_alive = bool(body.get("alive"))

    def _on_output(self, ident: int, stream: int, data: bytes) -> None:
        process = self.processes.get(ident)
        if process is not None and stream in process.streams:
            process.streams[stream].data += data
            process.streams[stream].ring()

    def _exited(self, process: RemoteProcess, code: Any) -> None:
        process.done, process.code = True, None if code is None else int(code)
        if process.exited is not None:  # (never inside a start's wait: on the loop)
            self.loop.call_soon(process.exited, process.code)

    def _on_lost(self, reason: str) -> None:
        if self.done:  # (it said `done`: its connection ending now is its goodbye)
            return
        running = [p for p in self.processes.values() if not p.done or p.group_alive]
        self._log("ERROR", self.name,
                  f"lost machine '{self.name}': {reason}; its {len(running)} process(es) are "
                  "taken as ended (the host ends them itself)")
        for process in running:
            for stream in process.streams.values():
                stream.ended = True
                stream.ring()
            process.group_alive = False
            if not process.done:
                self._exited(process, None)
        self.done = True
        self.on_done()

    def signal(self, process: RemoteProcess, sig: int) -> None:
        self.link.send({"t": "signal", "id": process.ident, "sig": int(sig)})


class Hosts:
    def __init__(self, loop: EventLoop, base: Mapping[str, str],
                 stamp: Callable[[dict[str, str]], dict[str, str]],
                 log: Callable[[str, str, str], None], launch_id: str,
                 graph: Graph | None = None) -> None:
        """`base`: the launch's environment (processes tell the difference); `stamp` marks
        ssh as the launch's; `graph(facing address)` says how a host joins the launch's graph
        (where the router for it listens, and the credentials)."""
        self.loop, self.base, self.stamp, self.log = loop, dict(base), stamp, log
        self.launch_id, self.graph = launch_id, graph
        self._hosts: dict[tuple, RemoteHost] = {}
        self._control: str | None = None
        self._closing: Callable[[], None] | None = None

    def system_for(self, machine: Machine, start: RemoteStart) -> RemoteSystem:
        """The Processes a process on `machine` is started through (its link opened now, if
        this is its first); LaunchError when the host cannot be reached."""
        host = self._hosts.get(machine.key())
        if host is None:
            host = self._open(machine)
        return RemoteSystem(host, start)

    def _open(self, machine: Machine) -> RemoteHost:
        if self._control is None:
            self._control = tempfile.mkdtemp(prefix="launcher-ssh-")  # (0700; short: %C)
        link = HostLink(machine, self.loop, os.path.join(self._control, "%C"), self.base,
                        self.stamp, lambda level, text: self.log(level, machine.name, text))
        ready = link.open({"t": "hello", "launch": self.launch_id, "ping": PING,
                           "silence": link.silence, "domain": self._domain()})
        facing = str(ready.get("ssh", "")).split(" ")[0]
        if self.graph is not None and facing:
            try:
                joined = self.graph.join(facing)
            except LaunchError:
                link.close()
                raise
            link.send({"t": "graph", **joined})
        host = RemoteHost(link, self.loop, self.base, self.log)
        self._hosts[machine.key()] = host
        self.log("INFO", machine.name, f"connected to {ssh.describe(machine)}: host "
                                       f"'{ready.get('host', '?')}', supervisor pid "
                                       f"{ready.get('pid', '?')}")
        return host

    def _domain(self) -> int:
        """The launch's ROS_DOMAIN_ID, which its processes there are on too."""
        text = self.base.get("ROS_DOMAIN_ID", "").strip()
        return int(text) if text.isdigit() else 0

    @property
    def open(self) -> bool:
        return any(not host.done for host in self._hosts.values())

    def pids(self) -> set[int]:
        """The local processes the links run (ssh): the launch's own, not leftovers."""
        return {host.link.pid for host in self._hosts.values() if host.link.pid}

    def close(self, then: Callable[[], None]) -> None:
        """Say goodbye to every host (each ends what is left there), then call `then` once
        all have answered or GOODBYE_WAIT has passed."""
        if self._closing is not None:
            return
        self._closing = then
        live = [host for host in self._hosts.values() if not host.done]
        for host in live:
            host.on_done = self._check_closed
            host.link.say_goodbye()
        self.loop.call_later(GOODBYE_WAIT, self._finish_close)
        self._check_closed()

    def _check_closed(self) -> None:
        if all(host.done for host in self._hosts.values()):
            self._finish_close()

    def _finish_close(self) -> None:
        for host in self._hosts.values():
            host.done = True
            host.link.close()
        if self.graph is not None:
            self.graph.close()
        if self._control is not None:
            shutil.rmtree(self._control, ignore_errors=True)
            self._control = None
        then, self._closing = self._closing, lambda: None
        if then is not None:
            then()


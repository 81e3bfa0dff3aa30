"""One other host of a launch: its link (host_link.py) and the processes started there.

A process there is started with its argv and with the environment the launch gave it, told as
what differs from the launch's own (the host's environment is its own: its login, its
env-loader); its executable is found there, and its parameter files travel with it. What the
launch asks of it (signals) and what it does (output, exit, its group gone) go over the link.
"""

from __future__ import annotations

import errno
import itertools
import selectors
import time
from collections.abc import Callable, Mapping
from typing import Any

from launcher.lineage import MARK_PREFIX
from launcher.runtime.host_link import SLICE, HostLink
from launcher.runtime.loop import EventLoop
from launcher.runtime.machine import RemoteStart
from launcher.runtime.remote_system import SPAWN_WAIT, RemoteProcess, shipped_files


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

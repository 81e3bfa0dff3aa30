"""The other hosts of a launch: one link each (remote_host.py), opened when the first process
sent there starts, shared by every process sent there (machines with the same settings are one
host, as roslaunch unifies them), and closed when the launch ends. What reaches another host
is imported only when a launch has one: most launches have none (start-up time)."""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any, Protocol

from launcher.errors import LaunchError
from launcher.runtime.loop import EventLoop
from launcher.runtime.machine import Machine, RemoteStart

if TYPE_CHECKING:
    from launcher.runtime.remote_host import RemoteHost
    from launcher.runtime.remote_system import RemoteSystem

GOODBYE_WAIT = 1.0  # s a host is given to end what is left and say `done`

class Graph(Protocol):
    """How another host joins the launch's graph (the cli's, which knows the bus)."""

    def join(self, address: str) -> dict[str, Any]:
        """For a host that reaches this one at `address`: where, and with what."""

    def close(self) -> None: ...


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
        from launcher.runtime.remote_system import RemoteSystem

        host = self._hosts.get(machine.key())
        if host is None:
            host = self._open(machine)
        return RemoteSystem(host, start)

    def _open(self, machine: Machine) -> RemoteHost:
        import tempfile

        from launcher.runtime import ssh
        from launcher.runtime.host_link import PING, HostLink
        from launcher.runtime.remote_host import RemoteHost

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
            import shutil

            shutil.rmtree(self._control, ignore_errors=True)
            self._control = None
        then, self._closing = self._closing, lambda: None
        if then is not None:
            then()


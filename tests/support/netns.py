"""A private network of hosts: Linux network namespaces on one bridge, made by a test (root).

A switch namespace holds the bridge; each host is a namespace of its own with one veth, named
`eth0` there, whose other end is a port of the bridge. Every device is made inside the
namespaces, so nothing shows in the machine's own network and parallel tests (pytest-xdist)
cannot clash: their namespaces carry a tag, the test process's pid and a random part. Removing
the network ends every process still in one of its namespaces, then deletes the namespaces
(the devices go with them); a network whose test process was killed before it could is
removed by the next one made.
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import time
import uuid
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import psutil

DEVICE = "eth0"  # each host's one device, named in its own namespace
OWNED = re.compile(r"^ln(?:S|.+-)(\d+)x[0-9a-f]{4}$")  # a namespace of ours: its owner's pid


@dataclass(frozen=True)
class Host:
    name: str
    namespace: str
    address: str


def ip(*args: str) -> None:
    done = subprocess.run(["ip", *args], capture_output=True, text=True, timeout=30)
    if done.returncode != 0:
        raise RuntimeError(f"ip {' '.join(args)}: {done.stderr.strip()}")


def namespace_id(namespace: str) -> tuple[int, int]:
    found = os.stat(f"/run/netns/{namespace}")
    return found.st_dev, found.st_ino


class Network:
    """Hosts `names` on one bridge, 10.X.Y.N/24 (N = 1, 2, … in the order given)."""

    def __init__(self, names: Sequence[str]) -> None:
        random = uuid.uuid4().hex[:4]
        self.tag = f"{os.getpid()}x{random}"
        self.switch = f"lnS{self.tag}"
        # (the addresses only need to differ on this bridge; a range of its own reads better
        # in `ip` listings than test_hosts.py's)
        subnet = f"10.{150 + int(random[:2], 16) % 50}.{int(random[2:], 16)}"
        self.hosts = {name: Host(name, f"ln{name}-{self.tag}", f"{subnet}.{n}")
                      for n, name in enumerate(names, start=1)}

    def __enter__(self) -> Network:
        try:
            self.make()
        except BaseException:
            self.remove()
            raise
        return self

    def __exit__(self, *exc: object) -> None:
        self.remove()

    def make(self) -> None:
        sweep_stale()
        ip("netns", "add", self.switch)
        ip("-n", self.switch, "link", "add", "br0", "type", "bridge")
        ip("-n", self.switch, "link", "set", "br0", "up")
        for port, host in enumerate(self.hosts.values(), start=1):
            ip("netns", "add", host.namespace)
            ip("-n", self.switch, "link", "add", f"p{port}", "type", "veth",
               "peer", "name", DEVICE, "netns", host.namespace)
            ip("-n", self.switch, "link", "set", f"p{port}", "master", "br0", "up")
            ip("-n", host.namespace, "addr", "add", f"{host.address}/24", "dev", DEVICE)
            ip("-n", host.namespace, "link", "set", DEVICE, "up")
            ip("-n", host.namespace, "link", "set", "lo", "up")

    def cut(self, name: str) -> None:
        """The host's cable pulled: its device down, so nothing reaches it or leaves it."""
        ip("-n", self.hosts[name].namespace, "link", "set", DEVICE, "down")

    def restore(self, name: str) -> None:
        ip("-n", self.hosts[name].namespace, "link", "set", DEVICE, "up")

    def processes_in(self, name: str) -> list[psutil.Process]:
        """Every live process in the host's network namespace (a zombie has left it)."""
        return processes_in_namespace(self.hosts[name].namespace)

    def remove(self) -> None:
        """Ends what is left in the namespaces, then deletes them; safe to call twice."""
        namespaces = [self.switch, *(host.namespace for host in self.hosts.values())]
        for namespace in namespaces:
            if os.path.exists(f"/run/netns/{namespace}"):
                end_all(lambda ns=namespace: processes_in_namespace(ns))
        for namespace in namespaces:
            if os.path.exists(f"/run/netns/{namespace}"):
                ip("netns", "del", namespace)


def sweep_stale() -> None:
    """Removes the namespaces of networks whose test process is gone (killed by a timeout,
    say), with whatever still runs in them."""
    names = os.listdir("/run/netns") if os.path.isdir("/run/netns") else []
    for namespace in names:
        owner = OWNED.match(namespace)
        if owner and not psutil.pid_exists(int(owner[1])):
            end_all(lambda ns=namespace: processes_in_namespace(ns))
            # (a sweep beside this one may delete it first)
            subprocess.run(["ip", "netns", "del", namespace], capture_output=True, timeout=30)


def processes_in_namespace(namespace: str) -> list[psutil.Process]:
    try:
        wanted = namespace_id(namespace)
    except FileNotFoundError:
        return []  # deleted meanwhile
    found = []
    for proc in psutil.process_iter():
        try:
            own = os.stat(f"/proc/{proc.pid}/ns/net")
        except OSError:
            continue  # gone, or a zombie
        if (own.st_dev, own.st_ino) == wanted:
            found.append(proc)
    return found


def end_all(find: Callable[[], list[psutil.Process]], timeout: float = 10.0) -> None:
    """Ends every process `find` lists, asking it again after each round: one may have
    started a child while it was being ended."""
    deadline = time.monotonic() + timeout
    while (processes := find()) and time.monotonic() < deadline:
        end_bottom_up(processes, deadline)


def end_bottom_up(processes: list[psutil.Process], deadline: float) -> None:
    """SIGKILL, children before their parents, each level waited for: a parent still alive
    reaps its children, where an orphan would wait on a PID 1 that may never reap it."""
    levels: dict[int, list[psutil.Process]] = {}
    for proc in processes:
        levels.setdefault(depth(proc), []).append(proc)
    for level in sorted(levels, reverse=True):
        for proc in levels[level]:
            for sig in (signal.SIGCONT, signal.SIGKILL):  # (a frozen one is woken to die)
                with contextlib.suppress(psutil.Error):
                    proc.send_signal(sig)
        while any(unreaped(p) for p in levels[level]) and time.monotonic() < deadline:
            time.sleep(0.02)


def depth(proc: psutil.Process) -> int:
    try:
        return len(proc.parents())
    except psutil.Error:
        return 0


def unreaped(proc: psutil.Process) -> bool:
    """Alive, or dead and waiting for a parent that will reap it soon (not PID 1, which may
    never reap, nor this process, which reaps its own children when it waits for them)."""
    try:
        return proc.status() != psutil.STATUS_ZOMBIE or proc.ppid() not in (1, os.getpid())
    except psutil.Error:
        return False

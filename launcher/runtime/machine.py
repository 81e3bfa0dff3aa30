"""Where a process runs: a machine a launch file declares (roslaunch's `<machine>`, and
launcher's extension of ROS 2 files), and how a process on another host is started there.

A machine whose address names this host (and whose user, if any, is ours) is this host: its
processes run here as any other. Machines with one `key()` are one host reached one way, so
they share one connection whatever their names (roslaunch's config.assign_machines).
"""

from __future__ import annotations

import functools
import os

from launcher.records import dataclass, field

DEFAULT_TIMEOUT = 10.0  # seconds (roslaunch's core._DEFAULT_REGISTER_TIMEOUT)
LOOPBACK_NAMES = ("localhost", "::1", "ip6-localhost", "ip6-loopback")


@dataclass(frozen=True)
class Machine:
    name: str
    address: str
    user: str | None = None
    ssh_port: int | None = None  # None: ssh's own (its config, else 22)
    env_loader: str | None = None  # run on that host around launcher's command
    timeout: float = DEFAULT_TIMEOUT  # seconds the whole connection set-up may take
    where: str = field(default="", compare=False)  # "file:line:col" of its declaration

    def key(self) -> tuple:
        """What makes two machines one host reached one way (names aside)."""
        return (self.address, self.user, self.ssh_port, self.env_loader, self.timeout)

    @property
    def local(self) -> bool:
        """Whether it is this host, as this user: its processes run here, without ssh."""
        return _names_this_host(self.address) and self.user in (None, _current_user())


@dataclass(frozen=True)
class RemoteStart:
    """How a process on another host is started there."""

    package: str | None  # a node's package, resolved on that host; None: argv is run as is
    executable: str | None
    at: int = 0  # where in ProcessSpec.argv the executable's own words (found there) go
    files: tuple[str, ...] = ()  # local files (parameter files) whose text goes there too


def _names_this_host(address: str) -> bool:
    """The loopback names and addresses, and this host's own names (an address of another
    interface of this host counts as another host: the connection says so plainly)."""
    address = address.strip().lower()
    if address in LOOPBACK_NAMES or address.startswith("127.") or address == _hostname():
        return True
    # (getfqdn may ask DNS: only for a dotted name that is no IPv4 address)
    return "." in address and not address.replace(".", "").isdigit() and address == _fqdn()


@functools.cache
def _hostname() -> str:
    import socket  # (only when a launch declares a machine: start-up time)

    return socket.gethostname().lower()


@functools.cache
def _fqdn() -> str:
    import socket

    return socket.getfqdn().lower()


@functools.cache
def _current_user() -> str | None:
    import pwd  # (as _hostname)

    try:
        return pwd.getpwuid(os.getuid()).pw_name
    except KeyError:  # a uid without a passwd entry (a container's): no name to match
        return None

"""The foxglove bridge's private network, where only its front (front.py) reaches the SDK.

The Foxglove SDK serves the protocol but offers no hook before its WebSocket handshake, so
it cannot ask for the graph's token itself, and any local user can connect to any loopback
port. So the SDK's server listens in a network namespace of its own (a private loopback that
nothing outside this process can reach), and the port users connect to is launcher's front.

Only one thread enters the private namespace (`PrivateNetwork`): the SDK's server is started
from it, so the server's threads are made there, while the bridge's graph session and every
other socket stay in the host's network (a router on another host still works). A user
other than root first enters a user namespace of its own, where it may make the network
namespace; that must happen while the process has one thread (before the graph session).
Where the kernel allows neither (unprivileged user namespaces turned off, or restricted as
Ubuntu 24.04's AppArmor does by default), no other way keeps the SDK's server from the other
local users: the SDK listens on TCP alone, with no hook before its handshake and nothing to
tell one client from another, and Linux gives a user no way to close a loopback port to the
others. So the bridge does not start, and says why and what to do (`advice`): let launcher's
Python make namespaces (one AppArmor profile, or one sysctl, as root), or turn the token off.
"""

from __future__ import annotations

import ctypes
import fcntl
import os
import queue
import socket
import struct
import sys
import threading
from collections.abc import Callable
from typing import Any

from launcher.bus import listen_token
from launcher.errors import LaunchError

CLONE_NEWUSER, CLONE_NEWNET = 0x10000000, 0x40000000
_SIOCGIFFLAGS, _SIOCSIFFLAGS, _IFF_UP = 0x8913, 0x8914, 0x1


class IsolationError(LaunchError):
    pass


def enter_user_namespace() -> None:
    """As a user other than root: a user namespace of this process's own (same ids), where
    it may make a network namespace. Call it while the process has a single thread."""
    if os.getuid() == 0:
        return
    uid, gid = os.getuid(), os.getgid()
    _unshare(CLONE_NEWUSER, "a user namespace")
    try:
        with open("/proc/self/setgroups", "w") as handle:
            handle.write("deny")
        for name, value in (("uid_map", uid), ("gid_map", gid)):
            with open(f"/proc/self/{name}", "w") as handle:
                handle.write(f"{value} {value} 1")
    except OSError as exc:
        raise IsolationError(f"cannot map this user into its own namespace: "
                             f"{exc.strerror}") from None


def _unshare(flags: int, what: str) -> None:
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.unshare(flags) != 0:
        raise IsolationError(advice(what, os.strerror(ctypes.get_errno())))


PROFILE = "/etc/apparmor.d/launcher-foxglove"


def advice(what: str, refusal: str, proc: str = "/proc/sys") -> str:
    """Why the bridge cannot make `what`, and what the user can do, once, in words."""
    import getpass

    def setting(name: str) -> str | None:
        try:
            with open(f"{proc}/{name}") as handle:
                return handle.read().strip()
        except OSError:
            return None

    python = os.path.realpath(sys.executable)
    if setting("kernel/apparmor_restrict_unprivileged_userns") == "1":
        cause = ("AppArmor restricts unprivileged user namespaces, as Ubuntu 24.04 does: "
                 "kernel.apparmor_restrict_unprivileged_userns=1")
        fix = (f"let launcher's Python make them with an AppArmor profile:\n"
               f"    printf 'abi <abi/4.0>,\\ninclude <tunables/global>\\nprofile "
               f"launcher-foxglove {python} flags=(unconfined) {{\\n  userns,\\n}}\\n' "
               f"| sudo tee {PROFILE}\n"
               f"    sudo apparmor_parser -r {PROFILE}\n"
               f"  (every program run by {python} may then make namespaces, as any program "
               "could before Ubuntu 24.04)")
    elif setting("kernel/unprivileged_userns_clone") == "0":
        cause = "unprivileged user namespaces are off: kernel.unprivileged_userns_clone=0"
        fix = ("turn them on: sudo sysctl -w kernel.unprivileged_userns_clone=1 (and put "
               "kernel.unprivileged_userns_clone=1 in /etc/sysctl.d/ to keep it)")
    elif setting("user/max_user_namespaces") == "0":
        cause = "no user namespace may be made: user.max_user_namespaces=0"
        fix = ("allow them: sudo sysctl -w user.max_user_namespaces=15000 (and put it in "
               "/etc/sysctl.d/ to keep it)")
    else:
        cause = "the kernel refuses it"
        fix = "allow unprivileged user namespaces for this user (ask who runs the machine)"
    return (f"cannot start behind the graph's token: the bridge keeps the Foxglove SDK's "
            f"server in a private network, and this system does not let user "
            f"{getpass.getuser()} make {what} ({refusal}; {cause}). To keep the token, "
            f"once, with sudo, {fix}.\nOr serve without the token (token:=false, or "
            f"{listen_token.OFF_VARIABLE}=1), only on a machine you alone use: then every "
            "local user can watch and command the graph through the bridge's port.")


class PrivateNetwork:
    """A thread in a network namespace of its own, with its loopback up; `call(fn)` runs
    `fn` there (sockets and threads made by `fn` belong to that network)."""

    def __init__(self) -> None:
        self._work: queue.Queue[tuple[Callable[[], Any], queue.Queue[Any]] | None] = \
            queue.Queue()
        ready: queue.Queue[BaseException | None] = queue.Queue()
        self._thread = threading.Thread(target=self._run, args=(ready,), daemon=True,
                                        name="private-network")
        self._thread.start()
        failure = ready.get()
        if failure is not None:
            raise failure

    def _run(self, ready: queue.Queue[BaseException | None]) -> None:
        try:
            _unshare(CLONE_NEWNET, "a network namespace")
            _loopback_up()
        except BaseException as exc:  # noqa: BLE001 - said by the constructor
            ready.put(exc)
            return
        ready.put(None)
        while (item := self._work.get()) is not None:
            job, answer = item
            try:
                answer.put((True, job()))
            except BaseException as exc:  # noqa: BLE001 - raised again by call()
                answer.put((False, exc))

    def call(self, job: Callable[[], Any]) -> Any:
        answer: queue.Queue[Any] = queue.Queue()
        self._work.put((job, answer))
        ok, value = answer.get()
        if not ok:
            raise value
        return value

    def close(self) -> None:
        self._work.put(None)


def _loopback_up() -> None:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        request = struct.pack("16sH14x", b"lo", 0)
        flags = struct.unpack("16sH14x", fcntl.ioctl(probe, _SIOCGIFFLAGS, request))[1]
        fcntl.ioctl(probe, _SIOCSIFFLAGS, struct.pack("16sH14x", b"lo", flags | _IFF_UP))

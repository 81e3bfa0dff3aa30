"""The foxglove bridge's listener, where only token holders reach it.

The Foxglove SDK serves the protocol but offers no hook before its WebSocket handshake, so
it cannot ask for the graph's token itself, and any local user can connect to any loopback
port. So the SDK's server listens in a network namespace of its own (a private loopback that
nothing outside this process can reach), and the port users connect to is launcher's front:
it reads each connection's HTTP request, refuses it (403, closed) unless it presents the
graph's token (bus/listen_token.py), and otherwise passes the bytes both ways, untouched, to
the SDK's server. The protocol stays the SDK's; the front never reads a frame.

Only one thread enters the private namespace (`PrivateNetwork`): the SDK's server is started
from it, so the server's threads are made there, while the bridge's graph session and every
other socket stay in the host's network (a router on another host still works). A user
other than root first enters a user namespace of its own, where it may make the network
namespace; that must happen while the process has one thread (before the graph session).
Where the kernel allows neither (unprivileged user namespaces turned off), the bridge says
so and does not start, unless the token check is turned off.
"""

from __future__ import annotations

import contextlib
import ctypes
import fcntl
import os
import queue
import socket
import struct
import threading
from collections.abc import Callable
from typing import Any

from launcher.bus import listen_token
from launcher.errors import LaunchError

CLONE_NEWUSER, CLONE_NEWNET = 0x10000000, 0x40000000
_SIOCGIFFLAGS, _SIOCSIFFLAGS, _IFF_UP = 0x8913, 0x8914, 0x1
HEAD_LIMIT = 16 * 1024  # bytes of request line and headers a client may send
HEAD_WAIT = 10.0  # s a client has to send them
CHUNK = 256 * 1024


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
        error = ctypes.get_errno()
        raise IsolationError(
            f"cannot make {what} for the bridge's private network: {os.strerror(error)} "
            "(the kernel does not let this user make namespaces: unprivileged user "
            "namespaces are off, or restricted, as Ubuntu's AppArmor does). The bridge "
            "refuses to listen where anyone could reach its server past the token; run it "
            f"with token:=false (or {listen_token.OFF_VARIABLE}=1) only on a machine you "
            "alone use")


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


class Front:
    """The listener users connect to: the token checked on each connection's HTTP request,
    then its bytes passed both ways to the server `connect()` reaches."""

    def __init__(self, listener: socket.socket, token: str | None,
                 connect: Callable[[], socket.socket], log: Callable[[str], None]) -> None:
        self._listener, self._token, self._connect, self._log = listener, token, connect, log
        self.port = listener.getsockname()[1]
        self._refusal = _refusal_response()
        self._closed = False
        threading.Thread(target=self._accept, daemon=True, name="front").start()

    def close(self) -> None:
        self._closed = True
        with contextlib.suppress(OSError):
            self._listener.shutdown(socket.SHUT_RDWR)
        self._listener.close()

    def _accept(self) -> None:
        while not self._closed:
            try:
                client, _ = self._listener.accept()
            except OSError:
                return
            threading.Thread(target=self._serve, args=(client,), daemon=True,
                             name="front-client").start()

    def _serve(self, client: socket.socket) -> None:
        with contextlib.ExitStack() as stack:
            stack.callback(client.close)
            head = _read_head(client)
            if head is None:
                return
            if self._token is not None:
                target, headers = _parse_head(head)
                given, _ = listen_token.presented(target, headers, self.port)
                if not listen_token.matches(given, self._token):
                    with contextlib.suppress(OSError):
                        client.sendall(self._refusal)
                    return
            try:
                server = self._connect()
            except OSError as exc:
                self._log(f"the bridge's server did not take a connection: {exc}")
                return
            stack.callback(server.close)
            server.sendall(head)
            other = threading.Thread(target=_pass, args=(server, client), daemon=True,
                                     name="front-down")
            other.start()
            _pass(client, server)
            other.join()


def _read_head(client: socket.socket) -> bytes | None:
    """The request line and headers (with whatever came after them), or None for a client
    that sends too much, too slowly, or no HTTP."""
    client.settimeout(HEAD_WAIT)
    head = b""
    try:
        while b"\r\n\r\n" not in head:
            if len(head) > HEAD_LIMIT:
                return None
            chunk = client.recv(4096)
            if not chunk:
                return None
            head += chunk
    except OSError:
        return None
    client.settimeout(None)
    return head


def _parse_head(head: bytes) -> tuple[str, list[tuple[str, str]]]:
    lines = head.split(b"\r\n\r\n", 1)[0].decode("latin-1").split("\r\n")
    parts = lines[0].split(" ")
    target = parts[1] if len(parts) >= 2 else ""
    headers = [(k.strip(), v.strip()) for k, _, v in (line.partition(":") for line in lines[1:])]
    return target, headers


def _refusal_response() -> bytes:
    page = listen_token.refusal().encode()
    return (b"HTTP/1.1 403 Forbidden\r\nContent-Type: text/html; charset=utf-8\r\n"
            b"Content-Length: " + str(len(page)).encode() + b"\r\nConnection: close\r\n\r\n"
            + page)


def _pass(source: socket.socket, sink: socket.socket) -> None:
    """Bytes from `source` to `sink` until either side ends, then both are shut."""
    buffer = memoryview(bytearray(CHUNK))
    try:
        while True:
            count = source.recv_into(buffer)
            if not count:
                break
            sink.sendall(buffer[:count])
    except OSError:
        pass
    for side in (source, sink):
        with contextlib.suppress(OSError):
            side.shutdown(socket.SHUT_RDWR)


def listen(address: str, port: int) -> socket.socket:
    """The front's listening socket (in the host's network: made before any private one)."""
    family = socket.AF_INET6 if ":" in address else socket.AF_INET
    listener = socket.socket(family, socket.SOCK_STREAM)
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        listener.bind((address, port))
        listener.listen(64)
    except OSError as exc:
        listener.close()
        raise LaunchError(f"foxglove_bridge cannot listen on {address} port {port}: "
                          f"{exc.strerror or exc} (another bridge or program has it? set "
                          "the parameter port)") from None
    return listener

"""The foxglove bridge's listener, the port users connect to (launcher's front of the SDK's
server): it reads each connection's HTTP request, refuses it (403, closed) unless it presents
the graph's token (bus/listen_token.py), and otherwise passes the bytes both ways to the
SDK's server, which the front alone reaches (isolation.py).

The protocol stays the SDK's, and the front reads no frame, but it speaks for clients of the
protocol's old name: the SDK accepts only the subprotocol `foxglove.sdk.v1`, and Foxglove's
own @foxglove/ws-protocol client, older Foxglove and Lichtblick apps and roslibjs-foxglove
offer only `foxglove.websocket.v1`, the same protocol. A request offering the old name alone
reaches the SDK offering the new one, and the SDK's answer reaches the client naming the one
it offered, as WebSocket requires.
"""

from __future__ import annotations

import contextlib
import socket
import threading
from collections.abc import Callable

from launcher.bus import listen_token
from launcher.errors import LaunchError

HEAD_LIMIT = 16 * 1024  # bytes of request line and headers a client may send
HEAD_WAIT = 10.0  # s a client has to send them
CHUNK = 256 * 1024
SDK_NAME, OLD_NAME = "foxglove.sdk.v1", "foxglove.websocket.v1"
PROTOCOL_HEADER = "sec-websocket-protocol"


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
            head, renamed = offered_as_sdk(head)
            server.sendall(head)
            if renamed:  # the answer names the protocol as the client offered it
                answer = _read_head(server)
                if answer is None:
                    return
                with contextlib.suppress(OSError):
                    client.sendall(answered_as_offered(answer))
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


def offered_as_sdk(head: bytes) -> tuple[bytes, bool]:
    """The request as the SDK takes it, and whether the protocol's name was changed: one
    offering the old name and not the SDK's offers the SDK's in its place."""
    top, _, rest = head.partition(b"\r\n\r\n")
    lines = top.split(b"\r\n")
    for index, line in enumerate(lines[1:], 1):
        name, _, value = line.decode("latin-1").partition(":")
        if name.strip().lower() != PROTOCOL_HEADER:
            continue
        offered = [word.strip() for word in value.split(",")]
        if OLD_NAME in offered and SDK_NAME not in offered:
            lines[index] = f"{name}: {SDK_NAME}".encode("latin-1")
            return b"\r\n".join(lines) + b"\r\n\r\n" + rest, True
    return head, False


def answered_as_offered(head: bytes) -> bytes:
    """The SDK's answer to a request offered_as_sdk changed, naming the old name."""
    top, _, rest = head.partition(b"\r\n\r\n")
    lines = top.split(b"\r\n")
    for index, line in enumerate(lines[1:], 1):
        name, _, value = line.decode("latin-1").partition(":")
        if name.strip().lower() == PROTOCOL_HEADER and value.strip() == SDK_NAME:
            lines[index] = f"{name}: {OLD_NAME}".encode("latin-1")
    return b"\r\n".join(lines) + b"\r\n\r\n" + rest


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

"""The web viewer's gate: the graph's token on its page, its files and its streams, and only
this user's processes on Studio's internal port (studio.py puts both in Studio's server while
it starts).

MuJoCo Studio's server has no authentication, and two TCP listeners (REFERENCE §10):
- the page's port (HTTP and the /state, /ui and /drop WebSockets): every request passes the
  token check (bus/listen_token.py) before Studio sees it; without the token, a 403 page
  and no handshake. The processes page (processes_page.py) is answered here too, after the
  check, and only where there is a token. A browser that opened the printed URL
  (`?token=…`) gets the cookie, so the page's own files and streams carry it;
- the loopback port Studio's headless UI client connects to from inside this process (its
  commands are the page's buttons: pause, step, reset). That client cannot present a token,
  so the port takes only connections whose other end belongs to this user (the kernel's
  socket table says who owns each loopback socket); others are closed unread.
"""

from __future__ import annotations

import http
import os
import socket
from collections.abc import Callable
from typing import Any

from launcher.bus import listen_token


def guarded_serve(serve: Callable[..., Any], token: str, port: int,
                  pages: Callable[[str], tuple[int, str, bytes] | None] | None = None
                  ) -> Callable[..., Any]:
    """Studio's `serve` (websockets'), its requests checked for the token first; a request
    `pages(path)` answers ((status, content type, body)) never reaches Studio."""
    from websockets.datastructures import Headers
    from websockets.http11 import Response

    page = listen_token.refusal().encode()

    def serving(handler: Any, *args: Any, process_request: Any = None,
                process_response: Any = None, **kwargs: Any) -> Any:
        came_in_url: set[int] = set()  # requests whose token was in their URL: set the cookie

        def check(connection: Any, request: Any) -> Any:
            given, in_url = listen_token.presented(request.path,
                                                   list(request.headers.raw_items()), port)
            if not listen_token.matches(given, token):
                return Response(http.HTTPStatus.FORBIDDEN, "Forbidden", Headers(
                    [("Content-Type", "text/html; charset=utf-8"),
                     ("Content-Length", str(len(page))), ("Cache-Control", "no-store")]),
                    page)
            if in_url:
                came_in_url.add(id(request))
            answered = pages(request.path) if pages is not None else None
            if answered is not None:
                status, kind, body = answered
                return Response(status, http.HTTPStatus(status).phrase, Headers(
                    [("Content-Type", kind), ("Content-Length", str(len(body))),
                     ("Cache-Control", "no-store")]), body)
            return process_request(connection, request) if process_request else None

        def answer(connection: Any, request: Any, response: Any) -> Any:
            if process_response is not None:
                response = process_response(connection, request, response) or response
            if id(request) in came_in_url:
                came_in_url.discard(id(request))
                response.headers["Set-Cookie"] = listen_token.set_cookie(port, token)
            return response

        return serve(handler, *args, process_request=check, process_response=answer, **kwargs)

    return serving


class OwnUserListener(socket.socket):
    """A listening socket whose accept() hands over only connections from this user's own
    processes, closing the others (asyncio's server calls accept() on it)."""

    def accept(self) -> tuple[socket.socket, Any]:
        while True:
            connection, address = super().accept()
            if peer_uid(connection) == os.getuid():
                return connection, address
            connection.close()


def own_user_listener(port: int = 0) -> socket.socket:
    """Studio's bind_loopback_socket, as an OwnUserListener."""
    listener = OwnUserListener(socket.AF_INET, socket.SOCK_STREAM)
    listener.bind(("127.0.0.1", port))
    listener.listen()
    return listener


def peer_uid(connection: socket.socket) -> int | None:
    """The user owning the other end of a loopback TCP connection (its socket in
    /proc/net/tcp: the entry whose local address is our peer and remote address is us)."""
    try:
        here, there = connection.getsockname(), connection.getpeername()
    except OSError:
        return None
    wanted = (_hex_endpoint(there), _hex_endpoint(here))
    try:
        with open("/proc/net/tcp", encoding="ascii") as table:
            next(table)
            for line in table:
                fields = line.split()
                if (fields[1], fields[2]) == wanted:
                    return int(fields[7])
    except (OSError, ValueError, IndexError, StopIteration):
        return None
    return None


def _hex_endpoint(address: tuple[str, int]) -> str:
    """An IPv4 endpoint as /proc/net/tcp writes it: the address's bytes in host order."""
    packed = socket.inet_aton(address[0])
    return f"{int.from_bytes(packed, 'little'):08X}:{address[1]:04X}"

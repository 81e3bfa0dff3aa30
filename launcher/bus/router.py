"""The graph's router (see discovery.py for its life).

Started by discovery (`--lock-fd`): it listens on the domain's socket, lets the start lock go,
and stops once nothing has been connected for `--linger` seconds. Run by `launcher router`
(standing): it serves the domain's socket itself, unless a router already does, and with
`--listen` it is also the gateway for other hosts: a second router session, joined to the
local one, listening there and admitting only those who present the user's credentials;
with `--join` it is the other end, a bridge from this host's router to such a one elsewhere
(bridge.py). It runs until SIGINT or SIGTERM. Both sweep the socket files of peers that died.
The router that serves the domain's socket also hosts the graph's parameter server
(graph_parameters.py), as roscore's master does. A started router's server forgets what it
was given once nothing is connected (the launch, or the roscore, that used it has ended), as
a ROS 1 master ends with the roslaunch or roscore that started it: whatever comes next finds
a fresh master's parameters, however soon it comes. A standing router is the user's roscore:
its parameters stay until it stops.
"""

from __future__ import annotations

import argparse
import contextlib
import fcntl
import os
import signal
import sys
import threading
import time
from collections.abc import Callable
from typing import Any

import zenoh

from launcher.arguments import Parser
from launcher.bus import bridge, credentials, discovery
from launcher.bus.session import config, declare_host
from launcher.errors import LaunchError, UsageError, reported
from launcher.private import open_private, private_folder

POLL = 0.25  # seconds between two looks at what is connected
SWEEP = 10.0  # seconds between two sweeps of dead peers' socket files (standing)


def run(listen: list[str], join: str | None, stop: threading.Event) -> int:
    """A standing router (`launcher router`): serving this host's graph, or with `join` a
    bridge from it to another host's router; its exit status."""
    if join is None:
        return serve(listen, None, None, stop)
    if listen:
        raise UsageError(f"--join {join} and --listen {listen[0]}: --listen lets other hosts "
                         "join this one, --join joins this one to another; run one router "
                         "for each")
    return bridge.join(join, stop)


def serve(listen: list[str], linger: float | None, lock_fd: int | None,
          stop: threading.Event) -> int:
    """Run the router until `stop` (or, with `linger`, until idle that long); its exit status."""
    sock = discovery.socket_path()
    remote = [discovery.check_endpoint(e, "--listen") for e in listen]
    if remote:
        credentials.load()  # a bad credentials file is said before the router starts
    private_folder(sock.parent)
    discovery.sweep_peer_sockets(sock.parent)
    sessions: list[zenoh.Session] = []
    hosted = None
    try:
        hosting = lock_fd is not None or not discovery.answers(sock)
        if hosting:
            made = _local_router(sock, lock_fd)
            if made is None:  # a launch's router started meanwhile: this one joins it
                hosting = False
            else:
                session, hosted = made
                sessions.append(session)
                _token = declare_host(session)  # (held: its parameter server is this host's)
        if remote:  # checks credentials, which the local router cannot ask of its peers
            try:
                sessions.append(zenoh.open(config("router", remote,
                                                  [f"unixsock-stream/{sock}"],
                                                  check_others=True)))
            except zenoh.ZError as exc:
                reason = str(exc).split(" at /")[0]
                raise LaunchError(f"--listen {', '.join(remote)}: cannot listen there "
                                  f"({reason}); is the address this host's, and the port "
                                  "free?") from None
        where = ", ".join(([str(sock)] if hosting else []) + remote)
        print(f"router of domain {discovery.domain_id()} listening on {where}"
              + ("" if hosting else f" (joined to the router on {sock})"), flush=True)
        if linger is None:
            while not stop.wait(SWEEP):
                discovery.sweep_peer_sockets(sock.parent)
        else:
            _until_idle(sessions[0], linger, stop,
                        hosted.reset if hosted is not None else lambda: None)
    finally:
        if hosted is not None:
            hosted.stop()
        for session in sessions:
            with contextlib.suppress(zenoh.ZError):
                session.close()
    return 0


def _local_router(sock: os.PathLike,
                  lock_fd: int | None) -> tuple[zenoh.Session, Any | None] | None:
    """The router on the domain's socket, hosting the graph's parameter server (as roscore's
    master holds it; graph_parameters.Hosted); the start lock is held until both are there,
    so whoever finds the router finds the server. None when a standing router finds, once it
    holds the start lock, that another (a launch's, started meanwhile) answers there."""
    from launcher.bus import graph_parameters

    with contextlib.ExitStack() as held:
        if lock_fd is None:  # standing: take the socket as discovery.start would
            lock = held.enter_context(open_private(discovery.lock_path(sock), "a"))
            fcntl.flock(lock, fcntl.LOCK_EX)
            if discovery.answers(sock):
                return None
            with contextlib.suppress(FileNotFoundError):
                os.unlink(sock)
        session = zenoh.open(config("router", [f"unixsock-stream/{sock}"], []))
        # (one joined to another host's graph by a launch's bridge: that graph's master serves)
        hosted = None if os.environ.get(discovery.JOINED_VARIABLE) == "1" else \
            graph_parameters.host(session)
    if lock_fd is not None:
        os.close(lock_fd)  # listening: whoever waits to connect may go on
    return session, hosted


class Connections:
    """What is connected, from Zenoh's transport events (asking for the list of transports
    now and then, instead, upset the router's routing)."""

    def __init__(self, session: zenoh.Session, idle: Callable[[], None] = lambda: None) -> None:
        """`idle()` is called as the last connection goes (on Zenoh's thread, before any
        later connection is seen)."""
        self._open: set[str] = set()
        self._idle = idle
        self._lock = threading.Lock()
        self._listener = session.info.declare_transport_events_listener(self._on_event,
                                                                        history=True)

    def _on_event(self, event: zenoh.TransportEvent) -> None:
        with self._lock:
            if event.kind == zenoh.SampleKind.PUT:
                self._open.add(str(event.transport.zid))
                return
            last = bool(self._open)
            self._open.discard(str(event.transport.zid))
            last = last and not self._open
        if last:
            self._idle()

    def any(self) -> bool:
        with self._lock:
            return bool(self._open)


def _until_idle(session: zenoh.Session, linger: float, stop: threading.Event,
                idle: Callable[[], None]) -> None:
    """Return once nothing has been connected for `linger` seconds, holding the start lock
    exclusively so that nobody is halfway through connecting; `idle()` each time the last
    connection goes."""
    connections = Connections(session, idle)
    idle_since = time.monotonic()
    while not stop.wait(POLL):
        if connections.any():
            idle_since = time.monotonic()
            continue
        if time.monotonic() - idle_since < linger:
            continue
        lock = open_private(discovery.lock_path(discovery.socket_path()), "a")
        fcntl.flock(lock, fcntl.LOCK_EX)
        if connections.any():
            lock.close()
            idle_since = time.monotonic()
            continue
        discovery.sweep_peer_sockets(discovery.socket_path().parent)
        # the path goes first, so that nobody sees a socket that no longer answers; the lock
        # goes when this process does
        with contextlib.suppress(FileNotFoundError):
            os.unlink(discovery.socket_path())
        session.close()
        return


def main(argv: list[str] | None = None) -> int:
    parser = Parser(prog="launcher router", description=(
        "Run the graph's router for ROS_DOMAIN_ID until Ctrl-C; --listen lets other hosts "
        "join (they set LAUNCHER_ROUTER to that endpoint, or run --join there, and hold a "
        "copy of ~/.launcher/credentials: every link is authenticated)."))
    parser.add_argument("--listen", action="append", default=[], metavar="ENDPOINT",
                        help="also listen here, e.g. tcp/0.0.0.0:7447")
    parser.add_argument("--join", metavar="ENDPOINT", default=None,
                        help="join this host's graph to the router listening there")
    parser.add_argument("--linger", type=float, default=None, help=argparse.SUPPRESS)
    parser.add_argument("--lock-fd", type=int, default=None, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    stop = threading.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: stop.set())
    if args.join is not None:
        return reported(lambda: run(args.listen, args.join, stop), "router")
    return reported(lambda: serve(args.listen, args.linger, args.lock_fd, stop), "router")


if __name__ == "__main__":
    sys.exit(main())

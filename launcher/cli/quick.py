"""`topic list` as shells run it, in loops and at prompts: `launcher topic list`,
`ros2 topic list` and `rostopic list`, with no options, answered with zenoh and `os` alone.

The full command's imports (argparse, pathlib, re, typing, the launcher's classes) were four
fifths of its run; this path reads the router's place (places.py), the session's settings
(zenoh_settings.py) and the tokens (tokens.py) with none of them (bench/commands measures
it). Anything else (other words or options, LAUNCHER_ROUTER, a bad ROS_DOMAIN_ID, no router
answering, any failure) goes the full way (main.py), which starts a router, or says what is
wrong, as always.
"""

from __future__ import annotations

import os
import sys

from launcher.bus import places, tokens
from launcher.bus.zenoh_settings import json5, settings

# the command words, and whether ROS 2's hidden names are left out (ros2cli leaves them out;
# ROS 1 has none, and rostopic lists everything)
LISTS = {("topic", "list"): True, ("ros2", "topic", "list"): True, ("rostopic", "list"): False}
TOKEN_WAIT = 1.0  # seconds for the router's answer, as graph.entities waits


def answer(argv: list[str]) -> int | None:
    """The exit status, with the list printed; None: take the full way."""
    hide = LISTS.get(tuple(argv))
    if hide is None or os.environ.get(places.ROUTER_VARIABLE):
        return None
    domain = places.domain(os.environ)
    if domain is None:
        return None
    socket = places.socket_file(os.environ, domain)
    try:
        names = _topics(socket, domain) if len(socket) <= places.SOCKET_PATH_MAX else None
    except Exception:  # noqa: BLE001 - the full way says what is wrong, as the user knows it
        return None
    if names is None:
        return None
    shown = sorted(name for name in names if not (hide and tokens.hidden(name)))
    try:
        sys.stdout.write("".join(f"{name}\n" for name in shown))
        sys.stdout.flush()
    except BrokenPipeError:  # `… | head -1`: the reader has what it wanted
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    return 0


def _topics(socket: str, domain: int) -> set[str] | None:
    """The topics of the graph's tokens; None where no router answers on `socket`."""
    import fcntl

    try:
        lock = os.open(places.lock_file(socket), os.O_RDONLY)
    except OSError:
        return None
    try:
        fcntl.flock(lock, fcntl.LOCK_SH)  # the router does not stop meanwhile (discovery.py)
        if not _answers(socket):
            return None
        import zenoh

        config = zenoh.Config()
        for key, value in settings("client", [], [f"unixsock-stream/{socket}"],
                                   places.timeout(os.environ)).items():
            config.insert_json5(key, json5(value))
        session = zenoh.open(config)
    finally:
        os.close(lock)
    try:
        found = set()
        for reply in session.liveliness().get(f"{tokens.ROS}/{domain}/**", timeout=TOKEN_WAIT):
            seen = tokens.endpoint(str(reply.ok.key_expr)) if reply.ok is not None else None
            if seen is not None and seen[0] in (tokens.PUBLISHER, tokens.SUBSCRIPTION):
                found.add(seen[1])
        return found
    finally:
        session.close()


def _answers(socket: str) -> bool:
    """Whether a router listens there (`_socket`: the `socket` module imports enum)."""
    import _socket

    probe = _socket.socket(_socket.AF_UNIX, _socket.SOCK_STREAM)
    try:
        probe.connect(socket)
    except OSError:
        return False
    finally:
        probe.close()
    return True

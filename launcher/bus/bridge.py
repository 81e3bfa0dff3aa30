"""A bridge (`launcher router --join ENDPOINT`): this host's graph joined to another host's
through the router listening there (its `launcher router --listen`, or a launch's gateway),
presenting the user's credentials. What runs on this host then joins this host's own router,
as always, and sees the graph of both: a second shell here finds every node.

Two router sessions, in this process: the near one joins this host's router (started if none
runs, as any command's would be, so that it lingers and ends as usual) and listens on a socket
of its own in the run folder, admitting only the credentials; the far one connects to it and
to ENDPOINT, presenting them. Two, because Zenoh's credentials are a session's, not a link's:
this host's router, which asks for none, refuses a link that presents some.

It says one line once joined, and runs until SIGINT or SIGTERM, or until its stdin closes when
that is a pipe (the remote supervisor that started it has gone).
"""

from __future__ import annotations

import contextlib
import os
import socket
import stat
import sys
import threading
from collections.abc import Mapping

import zenoh

from launcher.bus import credentials, discovery
from launcher.bus.session import config
from launcher.errors import LaunchError, UsageError

JOIN_WAIT = 3.0  # s the far router may take to answer
PROBE_WAIT = 1.0  # s a plain connection may take, to tell why the link was not taken
JOINED = "joined to"  # in the line said once joined (a supervisor waits for it)
_STREAMED = ("tcp/", "tls/", "ws/")  # endpoints a plain TCP connection can probe


def check(endpoint: str) -> str:
    """`endpoint` if --join can connect there, else a UsageError saying why."""
    target = discovery.check_endpoint(endpoint, "--join")
    if discovery.is_local(target):
        raise UsageError(f"--join {target}: a Unix socket is this host's own; --join connects "
                         "to another host's router (e.g. tcp/192.168.1.5:7447, where it runs "
                         "`launcher router --listen`)")
    return target


def join(endpoint: str, stop: threading.Event, wait: float = JOIN_WAIT,
         environ: Mapping[str, str] | None = None) -> int:
    """Bridge this host's graph to the router at `endpoint` until `stop`; its exit status."""
    env = dict(os.environ if environ is None else environ)
    target = check(endpoint)
    secret = credentials.load(env)  # a bad credentials file is said before anything starts
    sessions: list[zenoh.Session] = []
    try:
        # (a router started here for the bridge hosts no parameter server: the graph it
        # joins has its master, ROS 1's one, on the launching host)
        with discovery.router({**env, discovery.JOINED_VARIABLE: "1"}) as local:
            near = discovery.peer_endpoint(env)
            sessions.append(_open(config("router", [near], local, wait, env,
                                         check_others=True), "this host's router", local))
        far = config("router", [], [near, target], wait, env)
        try:
            sessions.append(_open(far, target, [target]))
        except LaunchError:
            raise LaunchError(f"--join {target}: {_why(target, wait, secret.file)}") from None
        print(f"router of domain {discovery.domain_id(env)} at {local[0]} {JOINED} {target}",
              flush=True)
        _watch_stdin(stop)
        stop.wait()
    finally:
        for session in reversed(sessions):
            with contextlib.suppress(zenoh.ZError):
                session.close()
    return 0


def _open(settings: zenoh.Config, what: str, endpoints: list[str]) -> zenoh.Session:
    """A router session connected to every endpoint it names (a router's connections are
    otherwise made in the background, and never said to have failed)."""
    settings.insert_json5("connect/exit_on_failure", "true")
    try:
        return zenoh.open(settings)
    except zenoh.ZError as exc:
        reason = str(exc).split(" at /")[0]
        raise LaunchError(f"cannot connect to {what} at {', '.join(endpoints)} "
                          f"({reason})") from None


def _why(target: str, wait: float, secrets: os.PathLike) -> str:
    """Why the far router did not take the link, as far as a plain connection tells."""
    if not target.startswith(_STREAMED):
        return (f"no router there took the link within {wait:g} s (is it listening, and "
                f"does it hold the credentials of {secrets}?)")
    host, _, port = target.split("/", 1)[1].split("#")[0].rpartition(":")
    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=PROBE_WAIT):
            pass
    except OSError as exc:
        said = exc.strerror or str(exc) or "no answer"
        return (f"nothing answered there within {wait:g} s ({said}): is its router "
                "running, and does nothing between the hosts stop this one (a firewall, NAT "
                "or a jump host)?")
    return (f"something answers there but did not take the link: is it launcher's router "
            f"(`launcher router --listen`), and does it hold the credentials of {secrets} (the "
            "same file on both hosts)?")


def _watch_stdin(stop: threading.Event) -> None:
    """`stop` once stdin closes, when it is a pipe or a socket (whoever started this one is
    gone); a terminal's or /dev/null is no one's."""
    try:
        mode = os.fstat(sys.stdin.fileno()).st_mode
    except (OSError, ValueError, AttributeError):
        return
    if not (stat.S_ISFIFO(mode) or stat.S_ISSOCK(mode)):
        return

    def read_until_closed() -> None:
        with contextlib.suppress(OSError):
            while os.read(sys.stdin.fileno(), 4096):
                pass
        stop.set()

    threading.Thread(target=read_until_closed, name="stdin", daemon=True).start()

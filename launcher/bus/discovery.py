"""Finding the graph's router, and starting it when none runs (without importing zenoh: the
launcher uses this).

One graph per user and ROS_DOMAIN_ID (0–232, default 0), as in ROS 2: every launch, node and
CLI of the user joins it with nothing to set. Its router listens on a Unix socket,
`<run folder>/domain-<N>.sock`, in a 0700 folder (LAUNCHER_RUN_DIR, else
$XDG_RUNTIME_DIR/launcher, else ~/.launcher/run), so other local users cannot reach it.

The router's life: the first process that needs the graph and finds no router answering
starts one (`python -m launcher.bus.router`, detached), holding `domain-<N>.lock` exclusively
until the router listens, so two starting at the same instant make one router. Processes
connect holding that lock shared; the router takes it exclusively before it stops, which it
does once nothing has been connected to it for LINGER seconds (LAUNCHER_ROUTER_LINGER). So
the router outlives the launch that started it while anything else uses it, and nothing
stays behind for good.
`launcher router` runs a standing one (and can listen beyond this host).

LAUNCHER_ROUTER=ENDPOINT[,ENDPOINT…] connects there instead and starts nothing (another
host's router, or an explicit set-up).
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import re
import sys
import time
from collections.abc import Iterator, Mapping
from pathlib import Path

from launcher import lineage
from launcher.bus import places
from launcher.bus.places import (  # noqa: F401 - the names discovery's users know
    DEFAULT_TIMEOUT,
    DOMAIN_VARIABLE,
    MAX_DOMAIN,
    ROUTER_VARIABLE,
    TIMEOUT_VARIABLE,
    is_local,
)
from launcher.errors import LaunchError, UsageError
from launcher.private import open_private, private_folder

LINGER = 3.0  # seconds a started router waits with nothing connected before it stops
LINGER_VARIABLE = "LAUNCHER_ROUTER_LINGER"  # sets that
JOINED_VARIABLE = "LAUNCHER_ROUTER_JOINED"  # "1": a router started for a bridge (bridge.py)
PEER_PREFIX = "peer-"
PEER_NAME_MAX = len(f"{PEER_PREFIX}4194304-00000000.sock")  # (Linux's largest pid)
_ENDPOINT = re.compile(r"(?P<protocol>tcp|udp|tls|quic|ws)/(?P<host>\[[0-9a-fA-F:.]+\]|[^/:\s"
                       r"\[\]]+):(?P<port>\d{1,5})(?:#.*)?$|unixsock-stream/(?P<path>/\S+)$")


class NoRouter(LaunchError):
    pass


def domain_id(environ: Mapping[str, str] | None = None) -> int:
    env = os.environ if environ is None else environ
    found = places.domain(env)
    if found is None:
        raise UsageError(f"{DOMAIN_VARIABLE}={env[DOMAIN_VARIABLE].strip()!r}: expected a "
                         f"whole number from 0 to {MAX_DOMAIN} (as ROS 2 allows)")
    return found


def run_dir(environ: Mapping[str, str] | None = None) -> Path:
    return Path(places.run_folder(os.environ if environ is None else environ))


def socket_path(environ: Mapping[str, str] | None = None) -> Path:
    env = os.environ if environ is None else environ
    path = Path(places.socket_file(env, domain_id(env)))
    longest = len(str(path.parent)) + 1 + max(len(path.name), PEER_NAME_MAX)
    if longest > places.SOCKET_PATH_MAX:
        raise UsageError(f"the run folder {path.parent} is too long a path for the graph's "
                         f"sockets (its nodes' need up to {longest} characters, a Unix socket "
                         f"takes {places.SOCKET_PATH_MAX}); set LAUNCHER_RUN_DIR to a shorter "
                         "folder")
    return path


def peer_endpoint(environ: Mapping[str, str] | None = None) -> str:
    """A Unix socket for a peer to listen on, in the run folder (its pid in the name, so that
    a dead peer's files can be swept)."""
    import secrets

    folder = socket_path(environ).parent
    return f"unixsock-stream/{folder}/{PEER_PREFIX}{os.getpid()}-{secrets.token_hex(4)}.sock"


def sweep_peer_sockets(folder: Path) -> None:
    """Remove the socket files of peers that died without closing them (SIGKILL)."""
    for path in folder.glob(f"{PEER_PREFIX}*.sock*"):
        pid = path.name[len(PEER_PREFIX):].split("-", 1)[0]
        if pid.isdigit() and not lineage.alive(int(pid)):
            with contextlib.suppress(OSError):
                path.unlink()


def check_endpoint(text: str, where: str) -> str:
    """`text` if it is a Zenoh endpoint launcher can use, else a UsageError naming `where`."""
    match = _ENDPOINT.match(text.strip())
    if match is None or (match["port"] and not 0 < int(match["port"]) < 65536):
        raise UsageError(f"{where}: {text!r} is not an endpoint: expected PROTOCOL/HOST:PORT "
                         "(e.g. tcp/192.168.1.5:7447, tcp/[::1]:7447) or "
                         "unixsock-stream/PATH")
    return text.strip()


def explicit_endpoints(environ: Mapping[str, str] | None = None) -> list[str]:
    env = os.environ if environ is None else environ
    text = env.get(ROUTER_VARIABLE, "").strip()
    return [check_endpoint(part, ROUTER_VARIABLE) for part in text.split(",")] if text else []


def timeout(environ: Mapping[str, str] | None = None) -> float:
    return places.timeout(os.environ if environ is None else environ)


def linger(environ: Mapping[str, str] | None = None) -> float:
    env = os.environ if environ is None else environ
    try:
        return max(0.0, float(env.get(LINGER_VARIABLE, LINGER)))
    except ValueError:
        return LINGER


def answers(path: Path) -> bool:
    """Whether a router listens on the socket (a stale file of a dead one does not)."""
    import socket  # here: the launch imports this module at start, and seldom gets here

    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as probe:
        try:
            probe.connect(str(path))
        except OSError:
            return False
    return True


def _own_folder(folder: Path) -> None:
    """The run folder, made 0700 (and found to be this user's), or a clear error."""
    try:
        private_folder(folder)
    except OSError as exc:
        raise NoRouter(f"cannot use the run folder {folder}: {exc.strerror} (it must be "
                       "this user's own; LAUNCHER_RUN_DIR chooses another)") from None


def lock_path(sock: Path) -> Path:
    return Path(places.lock_file(str(sock)))


def log_path(sock: Path) -> Path:
    return sock.with_suffix(".log")


@contextlib.contextmanager
def router(environ: Mapping[str, str] | None = None) -> Iterator[list[str]]:
    """The endpoints to connect to, the graph's router started first if none answers; while
    inside, the router does not stop (connect before leaving)."""
    env = dict(os.environ if environ is None else environ)
    explicit = explicit_endpoints(env)
    if explicit:
        yield explicit
        return
    sock = socket_path(env)
    _own_folder(sock.parent)
    with open_private(lock_path(sock), "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_SH)
        if not answers(sock):
            fcntl.flock(lock, fcntl.LOCK_UN)
            start(env)
            fcntl.flock(lock, fcntl.LOCK_SH)  # the router holds it exclusively until it listens
            if not answers(sock):
                raise NoRouter(f"the graph's router did not start (its log: {log_path(sock)})")
        yield [f"unixsock-stream/{sock}"]


def start(environ: Mapping[str, str] | None = None, wait: bool = True) -> None:
    """Start the graph's router unless one answers (or LAUNCHER_ROUTER names one); returns at
    once, the router still starting (connecting through `router()` waits for it). With
    `wait=False`, a router another process is starting is left to it (no waiting for its
    lock)."""
    env = dict(os.environ if environ is None else environ)
    if explicit_endpoints(env):
        return
    sock = socket_path(env)
    _own_folder(sock.parent)
    with open_private(lock_path(sock), "a") as lock:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | (0 if wait else fcntl.LOCK_NB))
        except BlockingIOError:
            return
        if answers(sock):
            return
        with contextlib.suppress(FileNotFoundError):
            sock.unlink()  # a dead router's
        with open_private(log_path(sock), "a") as log:
            log.write(f"--- {time.strftime('%Y-%m-%d %H:%M:%S')} started by pid {os.getpid()}\n")
            log.flush()
            # Through sh, which exits at once: the router is nobody's child (no zombie in a
            # long-lived node that started it), and detached: no launch's sweep stops it
            # (lineage.py). It inherits the lock and lets it go when it listens.
            argv = [sys.executable, "-m", "launcher.bus.router", "--lock-fd",
                    str(lock.fileno()), "--linger", str(linger(env))]
            import subprocess  # only to start a router (~20 ms of a node's start otherwise)

            subprocess.run(["/bin/sh", "-c", '"$@" &', "launcher-router", *argv],
                           stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=log,
                           env=lineage.detached(env), pass_fds=(lock.fileno(),),
                           start_new_session=True, check=True)

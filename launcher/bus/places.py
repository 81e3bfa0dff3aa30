"""Where the graph's router listens, read from the environment with `os` alone.

The listing commands' fast path (cli/quick.py) finds the router through this without
pathlib or the launcher's errors (their imports are most of a listing's run time);
discovery.py builds on it and says what is wrong where these return None.
"""

from __future__ import annotations

import os

TYPE_CHECKING = False  # (typing's own import is dearer than the fast path can pay)
if TYPE_CHECKING:
    from collections.abc import Mapping

ROUTER_VARIABLE = "LAUNCHER_ROUTER"
TIMEOUT_VARIABLE = "LAUNCHER_BUS_TIMEOUT"  # seconds to wait for a router; default 5
DOMAIN_VARIABLE = "ROS_DOMAIN_ID"
RUN_VARIABLE = "LAUNCHER_RUN_DIR"  # the run folder: the graph's socket and its peers'
DEFAULT_TIMEOUT = 5.0
MAX_DOMAIN = 232  # as ROS 2 allows
SOCKET_PATH_MAX = 107  # sun_path, less its terminating NUL


def domain(environ: Mapping[str, str]) -> int | None:
    """ROS_DOMAIN_ID (0 when unset), or None when it is not one ROS 2 allows."""
    text = environ.get(DOMAIN_VARIABLE, "").strip()
    if not text:
        return 0
    return int(text) if text.isdigit() and int(text) <= MAX_DOMAIN else None


def run_folder(environ: Mapping[str, str]) -> str:
    """LAUNCHER_RUN_DIR, else $XDG_RUNTIME_DIR/launcher, else ~/.launcher/run."""
    if environ.get(RUN_VARIABLE):
        return environ[RUN_VARIABLE]
    runtime = environ.get("XDG_RUNTIME_DIR")
    if runtime and os.path.isdir(runtime):
        return os.path.join(runtime, "launcher")
    return os.path.join(os.path.expanduser("~"), ".launcher", "run")


def socket_file(environ: Mapping[str, str], domain_id: int) -> str:
    return os.path.join(run_folder(environ), f"domain-{domain_id}.sock")


def lock_file(socket: str) -> str:
    return socket.removesuffix(".sock") + ".lock"


def is_local(endpoint: str) -> bool:
    """Whether the endpoint is a Unix socket (this host, guarded by file permissions)."""
    return endpoint.startswith("unixsock-stream/")


def timeout(environ: Mapping[str, str]) -> float:
    try:
        return float(environ.get(TIMEOUT_VARIABLE, DEFAULT_TIMEOUT))
    except ValueError:
        return DEFAULT_TIMEOUT

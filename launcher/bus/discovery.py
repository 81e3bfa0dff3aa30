"""Finding the bus of a run, without importing zenoh (the launcher uses this).

Each `launcher launch` hosts a Zenoh router on a free loopback port and tells its children
through LAUNCHER_ROUTER (e.g. `tcp/127.0.0.1:40123`). It also writes a run file,
`<LAUNCHER_RUN_DIR or ~/.launcher/run>/<pid>.json`, so that a node or a CLI started by hand in
another terminal finds the newest running launch with no configuration, as `ros2 topic echo`
does. LAUNCHER_ROUTER picks a given run (or a router on another host);
LAUNCHER_ZENOH_CONFIG names a full Zenoh config file for multi-host set-ups.
"""

from __future__ import annotations

import json
import os
import socket
from collections.abc import Mapping
from pathlib import Path

from launcher.private import private_folder, write_private

ROUTER_VARIABLE = "LAUNCHER_ROUTER"
CONFIG_VARIABLE = "LAUNCHER_ZENOH_CONFIG"
TIMEOUT_VARIABLE = "LAUNCHER_BUS_TIMEOUT"  # seconds to wait for the router; default 5
DEFAULT_TIMEOUT = 5.0


def run_dir(environ: Mapping[str, str] | None = None) -> Path:
    env = os.environ if environ is None else environ
    return Path(env.get("LAUNCHER_RUN_DIR") or Path.home() / ".launcher" / "run")


def free_endpoint(host: str = "127.0.0.1") -> str:
    with socket.socket() as probe:
        probe.bind((host, 0))
        return f"tcp/{host}:{probe.getsockname()[1]}"


def write_run_file(endpoint: str, environ: Mapping[str, str] | None = None) -> Path:
    folder = private_folder(run_dir(environ))  # the router's address: the user's only
    path = folder / f"{os.getpid()}.json"
    write_private(path, json.dumps({"pid": os.getpid(), "router": endpoint}))
    return path


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def running_endpoints(environ: Mapping[str, str] | None = None) -> list[str]:
    """Routers of launches still running, newest first (stale run files are removed)."""
    found: list[tuple[float, str]] = []
    folder = run_dir(environ)
    try:
        files = list(folder.glob("*.json"))
    except OSError:
        return []
    for path in files:
        try:
            data = json.loads(path.read_text())
            if not _alive(int(data["pid"])):
                path.unlink(missing_ok=True)
                continue
            found.append((path.stat().st_mtime, str(data["router"])))
        except (OSError, ValueError, KeyError):
            continue
    return [endpoint for _, endpoint in sorted(found, reverse=True)]


def router_endpoint(environ: Mapping[str, str] | None = None) -> str | None:
    env = os.environ if environ is None else environ
    if env.get(ROUTER_VARIABLE):
        return env[ROUTER_VARIABLE]
    endpoints = running_endpoints(env)
    return endpoints[0] if endpoints else None


def timeout(environ: Mapping[str, str] | None = None) -> float:
    env = os.environ if environ is None else environ
    try:
        return float(env.get(TIMEOUT_VARIABLE, DEFAULT_TIMEOUT))
    except ValueError:
        return DEFAULT_TIMEOUT

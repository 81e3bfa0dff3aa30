"""Zenoh sessions on safe defaults: no multicast scouting, loopback listeners, gossip on.

Never the default config (it scouts the LAN by multicast and listens on every interface).
A node is a peer connected to its run's router; opening waits (bounded) until the router
answers. CLI tools connect as clients. LAUNCHER_ZENOH_CONFIG replaces all of this with a
config file of the user's (multi-host).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping

import zenoh

from launcher.bus import discovery
from launcher.errors import LaunchError


class NoRouter(LaunchError):
    pass


def config(mode: str, listen: list[str], connect: list[str],
           timeout_s: float = discovery.DEFAULT_TIMEOUT) -> zenoh.Config:
    c = zenoh.Config()
    c.insert_json5("mode", json.dumps(mode))
    c.insert_json5("scouting/multicast/enabled", "false")
    c.insert_json5("scouting/gossip/enabled", "true")
    c.insert_json5("scouting/delay", "0")
    c.insert_json5("listen/endpoints", json.dumps(listen))
    c.insert_json5("connect/endpoints", json.dumps(connect))
    if connect:
        ms = int(timeout_s * 1000)
        c.insert_json5("connect/timeout_ms", json.dumps({"router": ms, "peer": ms,
                                                         "client": ms}))
        c.insert_json5("connect/exit_on_failure", json.dumps({"router": False, "peer": True,
                                                              "client": True}))
        c.insert_json5("connect/retry", json.dumps({"period_init_ms": 20,
                                                    "period_max_ms": 500,
                                                    "period_increase_factor": 2}))
    return c


def open_session(mode: str = "peer", environ: Mapping[str, str] | None = None,
                 listen: list[str] | None = None, host_if_alone: bool = False) -> zenoh.Session:
    """A session of `mode` (peer or client) on the run's bus.

    With no launch running, `host_if_alone` makes this session the router of a bus of its
    own (on a free loopback port, with a run file so others find it); otherwise that is an
    error saying nothing is running.
    """
    env = os.environ if environ is None else environ
    if env.get(discovery.CONFIG_VARIABLE):
        return zenoh.open(zenoh.Config.from_file(env[discovery.CONFIG_VARIABLE]))
    endpoint = discovery.router_endpoint(env)
    if endpoint is None and host_if_alone:
        return _host(env)
    if endpoint is None:
        raise NoRouter("no launch is running (no router to connect to); start one with "
                       "`launcher launch …`, or set LAUNCHER_ROUTER=tcp/HOST:PORT")
    wait = discovery.timeout(env)
    default_listen = ["tcp/127.0.0.1:0"] if mode == "peer" else []
    try:
        return zenoh.open(config(mode, default_listen if listen is None else listen,
                                 endpoint.split(","), wait))
    except zenoh.ZError as exc:
        raise NoRouter(f"no router reachable at {endpoint} within {wait:g} s "
                       f"({discovery.TIMEOUT_VARIABLE} sets the wait): {exc}") from None


def _host(environ: Mapping[str, str]) -> zenoh.Session:
    """A router session of this process's own; its run file goes when the process does."""
    import atexit

    endpoint = discovery.free_endpoint()
    session = zenoh.open(config("router", [endpoint], []))
    run_file = discovery.write_run_file(endpoint, environ)
    atexit.register(run_file.unlink, missing_ok=True)
    return session

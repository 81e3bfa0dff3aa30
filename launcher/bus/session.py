"""Zenoh sessions on safe defaults: no multicast scouting, listeners only where the user alone
can reach them, gossip on.

Never the default config (it scouts the LAN by multicast and listens on every interface).
On this host a node is a peer: connected to the graph's router (see discovery.py), it listens
on a Unix socket of its own in the same 0700 run folder, where other peers link to it directly
for data; CLI tools connect as clients. Through a router on another host (LAUNCHER_ROUTER with
a TCP endpoint), every process is a client of that router and presents the user's credentials
(credentials.py), which the router checks.

A session that holds nodes (a peer's) says which host it runs on, in one token of launcher's
own (keys.host_key): on a graph that spans hosts, `node list` shows where each node runs.
"""

from __future__ import annotations

import atexit
import contextlib
import json
import os
import threading
from collections.abc import Callable, Mapping
from pathlib import Path

import zenoh

from launcher.bus import credentials, discovery, keys
from launcher.bus.discovery import NoRouter
from launcher.bus.zenoh_settings import json5, settings
from launcher.private import write_private

SESSION_DESCRIPTORS = 32  # what opening a session may take (measured: 15), with room

__all__ = ["NoRouter", "config", "declare_host", "is_client", "open_session", "settings",
           "write_session_config"]

_host_tokens: dict[str, zenoh.LivelinessToken] = {}  # (a token lives as long as it is held)
_clients: set[str] = set()  # (the sessions opened as clients, by zid)
_open: list[zenoh.Session] = []  # (the sessions opened here, closed at exit if still open)


def before_threads_join(hook: Callable[[], None]) -> None:
    """Run `hook` as the interpreter exits, before it joins the non-daemon threads: Zenoh
    runs callbacks on such threads, and they end only once their entities (or session) are
    closed. The threading module's own exit hooks (concurrent.futures uses them) run then, the
    last registered first."""
    getattr(threading, "_register_atexit", atexit.register)(hook)


def _close_left_open() -> None:
    """A session its program never closed (a subscriber never undeclared) kept a callback
    thread waiting, and the program hung at its exit for good."""
    for session in _open:
        if not session.is_closed():
            with contextlib.suppress(zenoh.ZError):
                session.close()
    _open.clear()


before_threads_join(_close_left_open)  # (the first registered: it runs after the nodes' own)


def config(mode: str, listen: list[str], connect: list[str],
           timeout_s: float = discovery.DEFAULT_TIMEOUT,
           environ: Mapping[str, str] | None = None, check_others: bool = False) -> zenoh.Config:
    c = zenoh.Config()
    for key, value in settings(mode, listen, connect, timeout_s, environ,
                               check_others).items():
        c.insert_json5(key, json5(value))
    return c


def write_session_config(environ: Mapping[str, str] | None = None) -> Path:
    """Write, next to the graph's socket and 0600, a Zenoh config file that puts another Zenoh
    program (rmw_zenoh's ZENOH_SESSION_CONFIG_URI) on the graph: a client of its router,
    which passes all its data on (one config for any number of programs: a peer would need a
    listener of its own); its path."""
    path = discovery.socket_path(environ).with_suffix(".json5")
    with discovery.router(environ) as endpoints:
        values = settings("client", [], endpoints, environ=environ)
    tree: dict[str, object] = {}
    for key, value in values.items():
        *parents, leaf = key.split("/")
        node = tree
        for part in parents:
            node = node.setdefault(part, {})  # type: ignore[assignment]
        node[leaf] = value  # type: ignore[index]
    write_private(path, json.dumps(tree, indent=2) + "\n")
    return path


def open_session(mode: str = "client", environ: Mapping[str, str] | None = None,
                 listen: list[str] | None = None, holds_nodes: bool = False) -> zenoh.Session:
    """A session of `mode` on the graph, its router started if none runs (a client, whatever
    `mode`, of a router on another host); `holds_nodes`: it announces this host (a node's).

    Nodes are the router's clients, its links a star: peers would link to one another,
    n(n−1)/2 links for n nodes, and a graph of 100 nodes spent its first 40 s and then
    1.7 cores making and keeping 4,950 of them (bench/graph.py); through the router, data
    takes one hop more (tens of µs)."""
    env = os.environ if environ is None else environ
    discovery.domain_id(env)  # a bad ROS_DOMAIN_ID is said before anything else
    _room_for_a_session()
    wait = discovery.timeout(env)
    with discovery.router(env) as endpoints:
        if not all(discovery.is_local(e) for e in endpoints):
            mode = "client"
        if listen is None:
            listen = [discovery.peer_endpoint(env)] if mode == "peer" else []
        try:
            session = zenoh.open(config(mode, listen, endpoints, wait, env))
        except zenoh.ZError as exc:
            place, reason = ",".join(endpoints), str(exc).split(" at /")[0]
            raise NoRouter(
                f"no router answered at {place} within {wait:g} s ({reason}); is it running"
                + ("" if all(discovery.is_local(e) for e in endpoints) else
                   f", and does it hold the same credentials as {credentials.path(env)}")
                + f"? ({discovery.TIMEOUT_VARIABLE} sets the wait)") from None
    if holds_nodes:
        _host_tokens[str(session.zid())] = declare_host(session)
    if mode == "client":
        _clients.add(str(session.zid()))
    _open[:] = [*(each for each in _open if not each.is_closed()), session]
    return session


def is_client(session: zenoh.Session) -> bool:
    """Whether `session` was opened here as a client (the router answers its graph
    questions with every token)."""
    return str(session.zid()) in _clients


def _room_for_a_session() -> None:
    """Zenoh aborts the whole process (a panic in a destructor) when the file descriptors run
    out while a session opens: too few left is said as an error instead, before it begins."""
    import resource

    limit = resource.getrlimit(resource.RLIMIT_NOFILE)[0]
    if limit == resource.RLIM_INFINITY:
        return
    try:
        used = len(os.listdir("/proc/self/fd"))
    except OSError:  # (no /proc: nothing to say)
        return
    if limit - used < SESSION_DESCRIPTORS:
        raise NoRouter(f"too few file descriptors are left to join the graph: {limit - used} "
                       f"of {limit} (ulimit -n), where a session needs up to "
                       f"{SESSION_DESCRIPTORS}")


def declare_host(session: zenoh.Session) -> zenoh.LivelinessToken:
    """The token saying which host `session` runs on (held by the caller: dropped, it goes)."""
    return session.liveliness().declare_token(
        keys.host_key(keys.domain(), str(session.zid()), os.uname().nodename))

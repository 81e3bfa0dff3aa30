"""How the launch's other hosts join its graph: a gateway router, on the address each host
reached this one from, that admits only those who present the user's credentials (no port
open to the network without them). The credentials travel to each host inside its ssh
channel, never on a command line. One gateway per address, ended with the launch."""

from __future__ import annotations

import contextlib
import socket
import subprocess
import sys
import time
from collections.abc import Callable, Mapping
from typing import Any

from launcher.bus import credentials
from launcher.errors import LaunchError

LISTEN_WAIT = 10.0  # s a gateway may take to listen


class RemoteGraph:
    def __init__(self, environment: Mapping[str, str],
                 stamp: Callable[[dict[str, str]], dict[str, str]]) -> None:
        """`stamp` marks a gateway as the launch's (the watchdog ends it with the launch)."""
        self._environment, self._stamp = dict(environment), stamp
        self._gateways: dict[str, tuple[subprocess.Popen[bytes], str]] = {}

    def join(self, address: str) -> dict[str, Any]:
        """Where a host that reaches this one at `address` joins the graph, with what."""
        if address not in self._gateways:
            self._gateways[address] = self._start(address)
        endpoint = self._gateways[address][1]
        secret = credentials.load(self._environment)
        return {"router": endpoint, "credentials": secret.file.read_text(encoding="utf-8")}

    def _start(self, address: str) -> tuple[subprocess.Popen[bytes], str]:
        host = f"[{address}]" if ":" in address else address
        try:
            port = _free_port(address)
        except OSError as exc:  # (an address not of this host: NAT, a jump host)
            raise LaunchError(f"the graph cannot be offered to a host that reached this one as "
                              f"{address} ({exc.strerror or exc}): NAT or a jump host between "
                              "them? The hosts of a launch must reach each other directly") \
                from None
        endpoint = f"tcp/{host}:{port}"
        env = self._stamp(dict(self._environment))
        gateway = subprocess.Popen([sys.executable, "-m", "launcher", "router", "--listen",
                                    endpoint], stdin=subprocess.DEVNULL,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env,
                                   start_new_session=True)
        deadline = time.monotonic() + LISTEN_WAIT
        while not _listens(address, port):
            if gateway.poll() is not None or time.monotonic() > deadline:
                said = (gateway.stderr.read() if gateway.poll() is not None and gateway.stderr
                        else b"").decode("utf-8", "replace").strip()
                _end(gateway)
                raise LaunchError(f"the graph's gateway for other hosts could not listen on "
                                  f"{endpoint}{': ' + said if said else ''}")
            time.sleep(0.02)
        return gateway, endpoint

    def close(self) -> None:
        for gateway, _ in self._gateways.values():
            _end(gateway)
        self._gateways.clear()


def _free_port(address: str) -> int:
    family = socket.AF_INET6 if ":" in address else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as probe:
        probe.bind((address, 0))
        return int(probe.getsockname()[1])


def _listens(address: str, port: int) -> bool:
    with contextlib.suppress(OSError), socket.create_connection((address, port), timeout=0.2):
        return True
    return False


def _end(gateway: subprocess.Popen[bytes]) -> None:
    if gateway.poll() is None:
        gateway.terminate()
        try:
            gateway.wait(3)
        except subprocess.TimeoutExpired:
            gateway.kill()
            gateway.wait()
    if gateway.stderr is not None:
        gateway.stderr.close()

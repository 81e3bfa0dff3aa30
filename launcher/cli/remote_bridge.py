"""How a launch's other host joins its graph: the remote supervisor starts a bridge there
(`launcher router --join`, bus/bridge.py) from that host's own router to the launch's gateway,
presenting the credentials the launch sent (written 0600 in its folder). The bridge carries
the supervisor's mark and reads its stdin: it ends with the supervisor however that ends.
What the launch starts there, and any shell there, then joins that host's router as always."""

from __future__ import annotations

import os
import selectors
import subprocess
import sys
import time
from collections.abc import Mapping
from pathlib import Path

from launcher.errors import LaunchError

JOINED = "joined to"  # in the line a bridge says once joined (bus/bridge.py's, without zenoh)
BRIDGE_WAIT = 7.0  # s a bridge may take to start and join (its own waits: 3 s, then 1 s)
EXIT_WAIT = 1.0  # s a bridge that closed its stdout may take to exit

_running: list[subprocess.Popen[bytes]] = []  # (their stdin pipes stay open with them)


def start(router: str, secrets: Path, environment: Mapping[str, str], host: str,
          log: Path) -> None:
    """Start a bridge to `router` with the credentials file `secrets` and wait until it has
    joined; a LaunchError says why it could not (its stderr goes to `log`)."""
    with open(log, "ab") as errors:
        bridge = subprocess.Popen(
            [sys.executable, "-m", "launcher.bus.router", "--join", router],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=errors,
            env={**environment, "LAUNCHER_CREDENTIALS": str(secrets)},
            start_new_session=True)
    _running.append(bridge)
    if _joined(bridge):
        return
    said = _said(log) if _end(bridge) else ""
    reason = said.removeprefix(f"--join {router}: ") or (
        f"it did not join within {BRIDGE_WAIT:g} s: a firewall, NAT or a jump host between "
        "them?")
    raise LaunchError(f"{host} cannot reach this host's graph at {router}: {reason}")


def _joined(bridge: subprocess.Popen[bytes]) -> bool:
    """Whether the bridge says it joined within BRIDGE_WAIT (False when it exits first)."""
    assert bridge.stdout is not None
    fd = bridge.stdout.fileno()
    deadline = time.monotonic() + BRIDGE_WAIT
    said = b""
    with selectors.DefaultSelector() as selector:
        selector.register(fd, selectors.EVENT_READ)
        while b"\n" not in said:
            left = deadline - time.monotonic()
            if left <= 0 or not selector.select(left):
                return False
            data = os.read(fd, 4096)
            if not data:
                return False
            said += data
    return JOINED.encode() in said


def _said(log: Path) -> str:
    """The bridge's own error, without its reporter's prefix."""
    try:
        lines = [line for line in log.read_text(errors="replace").splitlines() if line.strip()]
    except OSError:
        return ""
    return lines[-1].split("error: ", 1)[-1].strip() if lines else ""


def _end(bridge: subprocess.Popen[bytes]) -> bool:
    """End a bridge that did not join; whether it had ended by itself (and said why)."""
    try:
        bridge.wait(EXIT_WAIT)
        by_itself = True
    except subprocess.TimeoutExpired:
        bridge.kill()
        bridge.wait()
        by_itself = False
    _running.remove(bridge)
    for pipe in (bridge.stdin, bridge.stdout):
        if pipe is not None:
            pipe.close()
    return by_itself

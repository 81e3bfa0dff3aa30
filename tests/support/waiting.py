"""Waiting for a condition, and a free local port."""

from __future__ import annotations

import socket
import time


def wait_for(predicate, timeout: float = 30.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError("timed out")


def wait_until(check, timeout: float = 20.0, every: float = 0.3):
    """`check()`'s first true value, or its last value once `timeout` has passed (for an
    assertion that prints what it saw)."""
    deadline = time.monotonic() + timeout
    while True:
        value = check()
        if value or time.monotonic() > deadline:
            return value
        time.sleep(every)


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]

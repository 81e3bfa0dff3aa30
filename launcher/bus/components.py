"""The scope a component container makes a component in (rclcpp's NodeOptions, for Python).

A component is a callable that makes its node(s) with no arguments. While the container calls
it, the thread's scope says what those nodes are given in place of the process's command line:
the `--ros-args` the container was asked for (name, namespace, remaps), typed parameters, the
container's Zenoh session (one per process), and for rclpy nodes their own rclpy context.
Every node made in the scope is recorded, so the container knows what to spin and to destroy.
"""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Iterator
from typing import Any

from launcher.records import dataclass, field

_local = threading.local()


@dataclass(eq=False)
class Scope:
    argv: list[str]
    parameters: dict[str, Any]
    session: Any
    context: Any = None  # an rclpy Context, for components written with rclpy
    nodes: list[Any] = field(default_factory=list)  # launcher bus nodes made in it


def current() -> Scope | None:
    return getattr(_local, "scope", None)


@contextlib.contextmanager
def making(scope: Scope) -> Iterator[Scope]:
    """Nodes made on this thread inside the block belong to `scope`."""
    outer = current()
    _local.scope = scope
    try:
        yield scope
    finally:
        _local.scope = outer

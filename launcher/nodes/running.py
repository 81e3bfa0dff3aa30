"""How a built-in node runs: set up, spin until Ctrl-C or SIGTERM; errors through the one
reporter (`[name] error: …` on stderr)."""

from __future__ import annotations

from collections.abc import Callable

from launcher.bus.node import Node
from launcher.errors import reported


def run_node(name: str, setup: Callable[[Node], object]) -> int:
    """Make the node, `setup(node)`, spin."""
    return reported(lambda: _spin(name, setup), name)


def _spin(name: str, setup: Callable[[Node], object]) -> int:
    node = Node(name)
    try:
        setup(node)
        node.spin()
    finally:
        node.destroy_node()
    return 0

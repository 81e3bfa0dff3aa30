"""How a built-in node runs: set up, spin until Ctrl-C or SIGTERM, one clean line on error."""

from __future__ import annotations

import sys
from collections.abc import Callable

from launcher.bus.node import Node
from launcher.errors import LaunchError


def run_node(name: str, setup: Callable[[Node], object]) -> int:
    """Make the node, `setup(node)`, spin; a LaunchError is `[name] error: …` and exit 1."""
    node = Node(name)
    try:
        setup(node)
        node.spin()
    except LaunchError as exc:
        print(f"[{name}] error: {exc}", file=sys.stderr, flush=True)
        return 1
    finally:
        node.destroy_node()
    return 0

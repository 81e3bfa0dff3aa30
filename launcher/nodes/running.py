"""How a built-in node runs: set up, spin until Ctrl-C or SIGTERM; errors through the one
reporter (`[name] error: …` on stderr). The same set-up is the node's component, for a
component container (see launcher/packages/components.py)."""

from __future__ import annotations

from collections.abc import Callable

from launcher.bus.node import Node
from launcher.errors import reported


def run_node(name: str, setup: Callable[[Node], object], node_name: str = "") -> int:
    """Make the node (named `node_name`, else `name`), `setup(node)`, spin; errors are said
    as `name`'s."""
    return reported(lambda: _spin(node_name or name, setup), name)


def _spin(name: str, setup: Callable[[Node], object]) -> int:
    node = Node(name)
    try:
        setup(node)
        node.spin()
    finally:
        node.destroy_node()
    return 0


def component(name: str, setup: Callable[[Node], object]) -> Callable[[], Node]:
    """The callable a container loads: it makes the node (the container gives it its name,
    namespace, remaps and parameters) and sets it up."""
    def make() -> Node:
        node = Node(name)
        try:
            setup(node)
        except BaseException:
            node.destroy_node()
            raise
        return node

    make.__name__ = make.__qualname__ = f"{name}_component"
    return make

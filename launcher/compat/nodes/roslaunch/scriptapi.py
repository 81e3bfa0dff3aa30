"""roslaunch.scriptapi: ROSLaunch, roslaunch for scripts: start it, then launch Nodes one by
one (each returns its process, with is_alive() and stop()), and stop it."""

from __future__ import annotations

from typing import Any

from roslaunch.core import Master, Node, RLException  # noqa: F401 (roslaunch.scriptapi has them)
from roslaunch.parent import ROSLaunchParent
from roslaunch.rlutil import get_or_generate_uuid


class ROSLaunch:
    """A launch that a script adds nodes to as it goes."""

    def __init__(self) -> None:
        self.parent = ROSLaunchParent(get_or_generate_uuid(None, True), [], is_core=False,
                                      show_summary=False)
        self.started = False

    def load(self, f: str) -> None:
        """Load launch file `f` (roslaunch's is not implemented either)."""
        raise NotImplementedError

    def load_str(self, s: str) -> None:
        """Load launch XML `s` (roslaunch's is not implemented either)."""
        raise NotImplementedError

    def launch(self, node: Node) -> Any:
        """Start `node`; its process (is_alive(), stop())."""
        if not self.started:
            raise RLException("please start ROSLaunch first")
        if not isinstance(node, Node):
            raise ValueError("arg must be of type Node")
        assert self.parent.runner is not None
        process, success = self.parent.runner.launch_node(node)
        if not success:
            raise RLException(f"failed to launch {node.package}/{node.type}")
        return process

    def start(self) -> None:
        """Start the launch (it runs until stop(), even with no node running)."""
        self.parent.start(auto_terminate=False)
        self.started = True

    def spin(self) -> None:
        """Wait until the launch has ended."""
        self.parent.spin()

    def spin_once(self) -> None:
        """Let the launch run a moment."""
        self.parent.spin_once()

    def stop(self) -> None:
        """Stop every node launched, and the launch."""
        self.parent.shutdown()

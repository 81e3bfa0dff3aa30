"""The checks ros2_control users' launch tests import: a node is up, controllers are in a
state, joint states are published."""

from __future__ import annotations

import time
from typing import Any

from launch_testing_ros import WaitForTopics
from sensor_msgs.msg import JointState

from controller_manager.controller_manager_services import list_controllers

SETTLE = 10.0  # s the controllers are given to appear and reach their state


def check_node_running(node: Any, node_name: str, timeout: float = 5.0) -> None:
    """`node_name` appears on the graph within `timeout` seconds."""
    deadline = time.monotonic() + timeout
    while node_name not in node.get_node_names():
        assert time.monotonic() < deadline, f"{node_name} not found!"
        time.sleep(0.1)


def check_controllers_running(node: Any, cnames: list[str], namespace: str = "",
                              state: str = "active") -> None:
    """Each of `cnames` has its node in `namespace` and is in `state` (within ten seconds)."""
    ns = "/" + namespace.strip("/") if namespace.strip("/") else "/"
    deadline = time.monotonic() + SETTLE
    missing = set(cnames)
    while missing and time.monotonic() < deadline:
        present = node.get_node_names_and_namespaces()
        missing -= {name for name, where in present if where == ns}
        if missing:
            time.sleep(0.1)
    assert not missing, (f"Controller node(s) not found: "
                         f"{', '.join(f'ns: {ns}, ctrl:{c}' for c in sorted(missing))}, but "
                         f"seeing {node.get_node_names_and_namespaces()}")
    manager = f"{ns.rstrip('/')}/controller_manager" if ns != "/" else "controller_manager"
    waiting = set(cnames)
    while waiting and time.monotonic() < deadline + SETTLE:
        controllers = list_controllers(node, manager, 5.0).controller
        assert controllers, "No controllers found!"
        waiting -= {c.name for c in controllers if c.state == state}
        if waiting:
            time.sleep(0.1)
    assert not waiting, f"Controller(s) not found or not {state}: {', '.join(sorted(waiting))}"


def check_if_js_published(topic: str, joint_names: list[str]) -> None:
    """`topic` carries JointState messages naming exactly `joint_names` (in any order)."""
    waited = WaitForTopics([(topic, JointState)], timeout=20.0)
    try:
        assert waited.wait(), f"Topic '{topic}' not found!"
        message = waited.received_messages(topic)[0]
        assert len(message.name) == len(joint_names), "Wrong number of joints in message"
        assert set(message.name) == set(joint_names), "Wrong joint names"
    finally:
        waited.shutdown()

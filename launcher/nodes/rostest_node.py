"""What rostest's test nodes (hztest, paramtest, publishtest) share: the start of their test
case, a topic's type once it is published, and their main, as rostest.rosrun runs them."""

from __future__ import annotations

import sys
import time
import unittest
from typing import Any


def start_node(case: unittest.TestCase, node: str, parameter: str, needed: str) -> Any:
    """Start the test node (anonymous, as rostest's) and read its private `parameter`; the
    case fails, saying `needed`, where it is not set."""
    import rospy

    rospy.init_node(node, anonymous=True)
    value = rospy.get_param(parameter, None)
    case.assertTrue(value, needed)
    return value


def published_type(rospy: Any, topic: str, wait: float) -> Any:
    """The message class of `topic` once someone publishes it (None if none does in time)."""
    import importlib

    name = rospy.resolve_name(topic)
    deadline = time.monotonic() + wait
    while time.monotonic() < deadline:
        found = dict(rospy.get_published_topics()).get(name)
        if found:
            package, kind = found.split("/")[0], found.split("/")[-1]
            return getattr(importlib.import_module(f"{package}.msg"), kind)
        time.sleep(0.1)
    return None


def run(node: str, case: type[unittest.TestCase], argv: list[str] | None) -> None:
    """The node's main: its case run by rostest.rosrun, the result where rostest asked."""
    import rostest

    rostest.rosrun("rostest", node, case, sys.argv if argv is None else argv)

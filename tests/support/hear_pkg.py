"""A ROS 1 package with a rospy talker and a rostest test that hears it (`hear_pkg`), for the
rostest tests and the fault campaign (bench/fault_campaign.py)."""

from __future__ import annotations

from pathlib import Path

MANIFEST = """<?xml version="1.0"?>
<package format="2">
  <name>hear_pkg</name>
  <version>0.0.1</version>
  <description>hears</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>rospy</depend>
  <test_depend>rostest</test_depend>
</package>
"""
TALKER = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import String

rospy.init_node("talker")
pub = rospy.Publisher("chatter", String, queue_size=10)
rate = rospy.Rate(10)
try:
    while not rospy.is_shutdown():
        pub.publish(String(data="hello"))
        rate.sleep()
except rospy.ROSInterruptException:
    pass
"""
HEAR_TEST = """#!/usr/bin/env python3
import time
import unittest

import rospy
import rostest
from std_msgs.msg import String


class TestHear(unittest.TestCase):
    def test_hears_{expected}(self):
        rospy.init_node("hear_test")
        time.sleep({delay})
        message = rospy.wait_for_message("chatter", String, timeout=10)
        self.assertEqual(message.data, "{expected}")


if __name__ == "__main__":
    rostest.rosrun("hear_pkg", "hear_test", TestHear)
"""
TEST_FILE = """<launch>
  <node pkg="hear_pkg" type="talker.py" name="talker" />
  <test test-name="hear_test" pkg="hear_pkg" type="{type}" time-limit="{limit}" {extra}/>
</launch>
"""


def make_package(src: Path) -> Path:
    """`hear_pkg` under `src`, with its talker; its test written by write_test()."""
    root = src / "hear_pkg"
    (root / "scripts").mkdir(parents=True)
    (root / "test").mkdir()
    (root / "package.xml").write_text(MANIFEST)
    talker = root / "scripts" / "talker.py"
    talker.write_text(TALKER)
    talker.chmod(0o755)
    return root


def write_test(root: Path, expected: str = "hello", delay: float = 0.0,
               type_: str = "hear_test.py", limit: float = 30, extra: str = "") -> None:
    """hear_test.py (hears "expected" on chatter after `delay` s) and test/hear.test."""
    script = root / "scripts" / "hear_test.py"
    script.write_text(HEAR_TEST.format(expected=expected, delay=delay))
    script.chmod(0o755)
    (root / "test" / "hear.test").write_text(
        TEST_FILE.format(type=type_, limit=limit, extra=extra))

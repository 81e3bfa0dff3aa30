"""Job files for the tests of `launcher batch`: a launch test whose talker says the job's seed
on /chatter and whose test hears only its own; one that fails; one that outlasts any limit,
with a grandchild that leaves its session and a process that ignores SIGINT."""

from __future__ import annotations

from pathlib import Path

TALKER = """\
import os
import rclpy
from std_msgs.msg import String

rclpy.init()
node = rclpy.create_node("talker")
publisher = node.create_publisher(String, "chatter", 10)
seed = os.environ["LAUNCHER_BATCH_SEED"]


def tick():
    publisher.publish(String(data=seed))


node.create_timer(0.05, tick)
rclpy.spin(node)
"""

CHATTER_TEST = """\
import os
import sys
import time
import unittest

import launch
import launch.actions
import launch_testing.actions
import rclpy
from std_msgs.msg import String

HERE = os.path.dirname(os.path.abspath(__file__))
LISTEN = float(os.environ.get("CHATTER_LISTEN", "2"))


def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.DeclareLaunchArgument("rate", default_value="10"),
        launch.actions.ExecuteProcess(cmd=[sys.executable, os.path.join(HERE, "talker.py")]),
        launch_testing.actions.ReadyToTest()])


class TestChatter(unittest.TestCase):
    def test_hears_only_its_own_seed(self):
        rclpy.init()
        node = rclpy.create_node("listener")
        heard = []
        node.create_subscription(String, "chatter", lambda m: heard.append(m.data), 10)
        deadline = time.monotonic() + LISTEN
        while time.monotonic() < deadline or not heard and time.monotonic() < deadline + 20:
            rclpy.spin_once(node, timeout_sec=0.05)
        node.destroy_node()
        rclpy.shutdown()
        output = os.environ["LAUNCHER_BATCH_OUTPUT"]
        with open(os.path.join(output, "heard.txt"), "w") as f:
            f.write(" ".join(sorted(set(heard))))
        with open(os.path.join(output, "where.txt"), "w") as f:
            f.write(HERE)
        self.assertEqual(set(heard), {os.environ["LAUNCHER_BATCH_SEED"]})
"""

FAILING_TEST = """\
import os
import unittest

import launch
import launch_testing.actions


def generate_test_description():
    # (a process under test that outlives the test: a launch with none would end at once,
    # racing the test, as it does under real launch_testing)
    return launch.LaunchDescription([
        launch.actions.DeclareLaunchArgument("fail_on", default_value="none"),
        launch.actions.ExecuteProcess(cmd=["sleep", "60"]),
        launch_testing.actions.ReadyToTest()])


class TestSeed(unittest.TestCase):
    def test_the_seed_is_not_the_bad_one(self):
        self.assertNotEqual(os.environ["LAUNCHER_BATCH_SEED"], "1", "seed 1 is the bad one")
"""

# a test whose launch never ends by itself: a process that ignores SIGINT, and a grandchild
# that leaves the launch's session (setsid) and ignores SIGTERM
STUCK_TEST = """\
import os
import sys
import unittest

import launch
import launch.actions
import launch_testing.actions

STUCK = "import signal, time; signal.signal(signal.SIGINT, signal.SIG_IGN); time.sleep(600)"
GONE = ("import os, signal, subprocess, sys, time; subprocess.Popen([sys.executable, '-c', "
        "'import os, signal, time; os.setsid(); signal.signal(signal.SIGTERM, "
        "signal.SIG_IGN); time.sleep(600)']); time.sleep(600)")


def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=[sys.executable, "-c", STUCK]),
        launch.actions.ExecuteProcess(cmd=[sys.executable, "-c", GONE]),
        launch_testing.actions.ReadyToTest()])


class TestForever(unittest.TestCase):
    def test_waits(self, proc_output):
        proc_output.assertWaitFor("never said", timeout=600)
"""


def write_jobs(folder: Path) -> Path:
    """The job files in `folder`; returns it."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "talker.py").write_text(TALKER)
    (folder / "chatter_test.py").write_text(CHATTER_TEST)
    (folder / "failing_test.py").write_text(FAILING_TEST)
    (folder / "stuck_test.py").write_text(STUCK_TEST)
    return folder

# The demo's robot in lockstep, its driver started once the robot is spawned (on create's
# exit), so that a run to a sim time repeats exactly; the world is the job's argument.
LOCKSTEP_LAUNCH = """\
launch:
  - arg: {{name: world_name, default: robot.world}}
  - executable:
      cmd: gz sim -v 3 -s -r --lockstep $(var world_name)
      output: screen
  - node: {{pkg: ros_gz_bridge, exec: parameter_bridge, output: screen,
           args: "--ros-args -p config_file:={bridge}"}}
  - node:
      pkg: robot_state_publisher
      exec: robot_state_publisher
      param:
        - name: robot_description
          value: "$(command 'xacro $(find-pkg-share robot_description)/urdf/robot.xacro')"
  - node:
      pkg: ros_gz_sim
      exec: create
      args: "-entity my_robot -topic robot_description"
      on_exit:
        - node: {{pkg: robot_application, exec: driver, output: screen,
                 param: [{{name: use_sim_time, value: true}}]}}
"""


def write_lockstep(folder: Path, repo: Path) -> Path:
    """The lockstep scenario in `folder` (its packages are the repo's); returns its file."""
    folder.mkdir(parents=True, exist_ok=True)
    bridge = repo / "packages" / "robot_bringup" / "config" / "bridge.yaml"
    path = folder / "drive.launch.yaml"
    path.write_text(LOCKSTEP_LAUNCH.format(bridge=bridge))
    return path

"""robot_state_publisher as a real process on a real bus, started by a launch file."""

from __future__ import annotations

import json
import signal
import subprocess
import sys

import pytest

from tests.support.robots import CHAIN

PY = sys.executable
LAUNCH = """
launch:
  - node:
      pkg: robot_state_publisher
      exec: robot_state_publisher
      namespace: arm1
      output: screen
      param:
        - {name: robot_description, value: "$(command 'cat arm.urdf')"}
        - {name: publish_frequency, value: 1000.0}
        - {name: frame_prefix, value: "arm1/"}
"""
# Publishes joint states as a sim bridge would and reports what arrives on /tf.
PROBE = """
import json, time
from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("probe")
frames = []
node.create_subscription("tf2_msgs/msg/TFMessage", "/tf", lambda m: frames.append(
    [(t.header.frame_id, t.child_frame_id, t.transform.translation.y, t.header.stamp.sec)
     for t in m.transforms]))
pub = node.create_publisher("sensor_msgs/msg/JointState", "/arm1/joint_states")
def send(sec, names, positions):
    pub.publish(node.message("sensor_msgs/msg/JointState", header={"stamp": {"sec": sec}},
                             name=names, position=positions))
    node.spin(0.2)
deadline = time.monotonic() + 20
while not frames and time.monotonic() < deadline:
    send(1, ["j1", "fa"], [0.1, 0.02])
send(2, ["j1", "fa", "nonsense"], [0.1, 0.02, 0.0])
for _ in range(20):  # malformed, again and again: one warning, never a traceback
    send(3, ["j1", "fa"], [0.1])
pub.publish_raw(bytes(4) + b"garbage")
node.spin(0.2)
print("RESULT", json.dumps(frames[-1]), flush=True)
node.destroy_node()
"""


@pytest.fixture
def rsp_ws(ws):
    ws.own_bus()
    ws.write("arm.urdf", CHAIN)
    return ws


def test_tf_static_for_late_subscribers_tf_from_joint_states_and_mimics(rsp_ws):
    rsp_ws.write("rsp.launch.yaml", LAUNCH)
    proc = rsp_ws.start("launch", "rsp.launch.yaml", output="launch.out")
    try:
        rsp_ws.wait_for_output("robot 'arm': 5 moving joints, 1 fixed", 60, "launch.out")
        static = rsp_ws.run("topic", "echo", "/tf_static", "--once")  # joins late
        assert "frame_id: arm1/l3" in static.stdout and "child_frame_id: arm1/tool" in \
            static.stdout, static.stderr
        description = rsp_ws.run("topic", "echo", "/arm1/robot_description", "--once", "-f")
        assert "robot name=" in description.stdout and "mimic joint=" in description.stdout
        rsp_ws.write("probe.py", PROBE)
        probe = subprocess.run([PY, "probe.py"], cwd=rsp_ws.root, env=rsp_ws.env,
                               capture_output=True, text=True, timeout=60)
        assert probe.returncode == 0, probe.stderr
        frames = json.loads(probe.stdout.split("RESULT", 1)[1])
        by_child = {child: (parent, y, sec) for parent, child, y, sec in frames}
        assert by_child["arm1/l1"][0] == "arm1/base" and by_child["arm1/l1"][2] == 2
        assert by_child["arm1/finger_a"][1] == pytest.approx(0.02)
        assert by_child["arm1/finger_b"][1] == pytest.approx(-0.02 + 0.01)  # the mimic
        out = rsp_ws.wait_for_output("warned once", 10, "launch.out")
        assert out.count("joint 'nonsense'") == 1
        out = rsp_ws.wait_for_output("dropping joint_states messages that are not a valid "
                                     "sensor_msgs/msg/JointState (the first: 2 names but 1 "
                                     "positions); warned once", 10, "launch.out")
        assert out.count("dropping joint_states") == 1 and "Traceback" not in out
        changed = CHAIN.replace('xyz="0 0 0.05"', 'xyz="0 0 0.07"')
        done = rsp_ws.run("param", "set", "/arm1/robot_state_publisher", "robot_description",
                          changed)
        assert done.returncode == 0, done.stderr
        static = rsp_ws.run("topic", "echo", "/tf_static", "--once")
        assert "z: 0.07" in static.stdout, static.stdout
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130


@pytest.mark.parametrize("args, expected", [
    ([], "parameter robot_description is missing or empty"),
    (["-p", "robot_description:=<robot name='r'><link name='a'>"], "invalid URDF: not valid XML"),
    (["-p", "robot_description:=<robot name='r'><link name='a'/><link name='b'/></robot>"],
     "2 root links"),
    (["-p", "publish_frequency:=2000.0", "-p", "robot_description:=<robot name='r'>"
      "<link name='a'/></robot>"], "parameter 'publish_frequency': expected a number ≤ 1000, "
     "got 2000.0"),
    (["-p", "ignore_timestamp:=often", "-p", "robot_description:=<robot name='r'>"
      "<link name='a'/></robot>"], "parameter 'ignore_timestamp': expected true or false, "
     "got 'often'"),
])
def test_bad_parameters_exit_1_with_a_clear_message(rsp_ws, args, expected):
    done = subprocess.run([PY, "-m", "launcher.nodes.robot_state_publisher", "--ros-args",
                           *args], cwd=rsp_ws.root, env=rsp_ws.env, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 1 and expected in done.stderr, done.stderr
    assert "Traceback" not in done.stderr


SDF_LAUNCH = """
launch:
  - node:
      pkg: robot_state_publisher
      exec: robot_state_publisher
      output: screen
      param:
        - {name: robot_description, value: "$(command 'cat pendulum.sdf')"}
"""


def test_an_sdf_model_with_a_ball_joint_is_taken_as_sdformat_urdf_takes_it(rsp_ws):
    """ros_gz_sim_demos' sdf_parser feeds a vehicle whose caster is a ball joint: sdformat_urdf
    makes it a floating joint, and robot_state_publisher runs with the others."""
    from tests.support.robots import SDF_ROBOT

    rsp_ws.write("pendulum.sdf", SDF_ROBOT.replace('name="hinge" type="revolute"',
                                                   'name="hinge" type="ball"'))
    rsp_ws.write("rsp.launch.yaml", SDF_LAUNCH)
    proc = rsp_ws.start("launch", "rsp.launch.yaml", output="launch.out")
    try:
        said = rsp_ws.wait_for_output("robot 'pendulum': 1 moving joints", 60, "launch.out")
        assert "[ERROR]" not in said, said
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130


def test_an_sdf_robot_description_drives_robot_state_publisher(rsp_ws):
    """As ros_gz's demos feed it (sdformat_urdf in ROS 2): the SDF model's links and joints."""
    from tests.support.robots import SDF_ROBOT

    rsp_ws.write("pendulum.sdf", SDF_ROBOT)
    rsp_ws.write("rsp.launch.yaml", SDF_LAUNCH)
    proc = rsp_ws.start("launch", "rsp.launch.yaml", output="launch.out")
    try:
        rsp_ws.wait_for_output("robot 'pendulum': 2 moving joints", 60, "launch.out")
        rsp_ws.write("probe.py", PROBE.replace("/arm1/joint_states", "/joint_states")
                     .replace('["j1", "fa"], [0.1, 0.02]', '["hinge", "spin"], [0.3, 0.0]'))
        probe = subprocess.run([PY, "probe.py"], cwd=rsp_ws.root, env=rsp_ws.env,
                               capture_output=True, text=True, timeout=60)
        assert probe.returncode == 0, probe.stderr
        frames = json.loads(probe.stdout.split("RESULT", 1)[1])
        by_child = {child: (parent, y) for parent, child, y, _ in frames}
        assert by_child["arm"] == ("base", pytest.approx(0.2))
        assert by_child["tip"][0] == "arm"
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130

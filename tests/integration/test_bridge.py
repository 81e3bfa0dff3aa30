"""parameter_bridge between a live sim and ROS-typed topics: real processes, real Zenoh."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
from pathlib import Path

import pytest

PY = sys.executable
ROBOT = str(Path(__file__).resolve().parent.parent / "data" / "diffbot.urdf")
BRIDGE = """
- ros_topic_name: "/clock"
  gz_topic_name: "/clock"
  ros_type_name: "rosgraph_msgs/msg/Clock"
  gz_type_name: "gz.msgs.Clock"
  direction: GZ_TO_ROS
- ros_topic_name: "cmd_vel"
  gz_topic_name: "/model/{{ robot }}/cmd_vel"
  ros_type_name: "geometry_msgs/msg/Twist"
  gz_type_name: "gz.msgs.Twist"
  direction: ROS_TO_GZ
- ros_topic_name: "odom"
  gz_topic_name: "/model/{{ robot }}/odometry"
  ros_type_name: "nav_msgs/msg/Odometry"
  gz_type_name: "gz.msgs.Odometry"
  direction: GZ_TO_ROS
- ros_topic_name: "/tf"
  gz_topic_name: "/model/{{ robot }}/tf"
  ros_type_name: "tf2_msgs/msg/TFMessage"
  gz_type_name: "gz.msgs.Pose_V"
  direction: GZ_TO_ROS
  lazy: true
- ros_topic_name: "joint_states"
  sim_topic_name: "/world/empty/model/{{ robot }}/joint_state"
  ros_type_name: "sensor_msgs/msg/JointState"
  sim_type_name: "gz.msgs.Model"
  direction: GZ_TO_ROS
- service_name: "/world/empty/control"
  ros_type_name: "ros_gz_interfaces/srv/ControlWorld"
  gz_req_type_name: "gz.msgs.WorldControl"
  gz_rep_type_name: "gz.msgs.Boolean"
- service_name: "/world/empty/remove"
  ros_type_name: "ros_gz_interfaces/srv/DeleteEntity"
  gz_req_type_name: "gz.msgs.Entity"
  gz_rep_type_name: "gz.msgs.Boolean"
- service_name: "/world/empty/create"
  ros_type_name: "ros_gz_interfaces/srv/SpawnEntity"
  gz_req_type_name: "gz.msgs.EntityFactory"
  gz_rep_type_name: "gz.msgs.Boolean"
- service_name: "/world/empty/set_pose"
  ros_type_name: "ros_gz_interfaces/srv/SetEntityPose"
  gz_req_type_name: "gz.msgs.Pose"
  gz_rep_type_name: "gz.msgs.Boolean"
- ros_topic_name: "/broken"
  gz_topic_name: "/broken"
  ros_type_name: "nav_msgs/msg/Odometry"
  gz_type_name: "gz.msgs.Twist"
"""
LAUNCH = f"""
launch:
  - node: {{pkg: mujoco_sim, exec: sim, args: "-r -v 3", output: screen}}
  - node: {{pkg: mujoco_sim, exec: create, output: screen,
           args: "-name bot -file {ROBOT} -z 0.06"}}
  - node:
      pkg: mujoco_bridge
      exec: parameter_bridge
      namespace: bot
      output: screen
      param:
        - {{name: config_file, value: bridge.yaml.j2}}
        - {{name: robot, value: bot}}
"""
PROBE = """
import json, time
from launcher.bus.node import Node
node = Node("probe")
clocks, odom = [], []
node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", clocks.append)
node.create_subscription("nav_msgs/msg/Odometry", "/bot/odom", odom.append)
joints = []
node.create_subscription("sensor_msgs/msg/JointState", "/bot/joint_states", joints.append)
cmd = node.create_publisher("geometry_msgs/msg/Twist", "/bot/cmd_vel")
deadline = time.monotonic() + 30
while not (odom and clocks) and time.monotonic() < deadline:
    node.spin(0.1)
start = odom[-1].pose.pose.position.x
end = time.monotonic() + 2.0
while time.monotonic() < end:
    cmd.publish(node.message("geometry_msgs/msg/Twist", linear={"x": 0.5}))
    node.spin(0.1)
print("RESULT", json.dumps({
    "clock": clocks[-1].clock.sec + clocks[-1].clock.nanosec * 1e-9,
    "moved": odom[-1].pose.pose.position.x - start,
    "frame": odom[-1].header.frame_id,
    "joints": list(joints[-1].name) if joints else []}), flush=True)
node.destroy_node()
"""


@pytest.fixture
def bridge_ws(ws):
    ws.own_bus()
    ws.write("bridge.yaml.j2", BRIDGE)
    ws.write("sim.launch.yaml", LAUNCH)
    return ws


def subscriber_count(ws, topic: str) -> int:
    """Subscriptions to a topic of the sim's own side (the bridge's, when it listens)."""
    info = ws.run("topic", "info", "--sim", topic)
    line = next((x for x in info.stdout.splitlines() if x.startswith("Subscription count")), "")
    return int(line.split(":")[1]) if line else 0


def test_the_bridge_carries_clock_cmd_vel_odom_and_is_lazy_where_asked(bridge_ws):
    proc = bridge_ws.start("launch", "sim.launch.yaml", output="launch.out")
    try:
        out = bridge_ws.wait_for_output("bridging 9 of 10 entries", 60, "launch.out")
        assert "bridge.yaml.j2:43: entry 10: no conversion between nav_msgs/msg/Odometry and " \
            "gz.msgs.Twist; nav_msgs/msg/Odometry pairs with: gz.msgs.Odometry; skipped" in out
        bridge_ws.wait_for_output("spawned 'bot'", 60, "launch.out")
        assert subscriber_count(bridge_ws, "/model/bot/tf") == 0  # lazy: nobody on /tf yet
        watcher = subprocess.Popen([*_launcher(), "topic", "echo", "/tf"], cwd=bridge_ws.root,
                                   env=bridge_ws.env, stdout=subprocess.PIPE, text=True)
        try:
            assert "child_frame_id: bot/base_link" in _read_until(watcher, "child_frame_id")
            assert subscriber_count(bridge_ws, "/model/bot/tf") == 1
        finally:
            watcher.send_signal(signal.SIGINT)
            watcher.wait(10)
        bridge_ws.write("probe.py", PROBE)
        probe = subprocess.run([PY, "probe.py"], cwd=bridge_ws.root, env=bridge_ws.env,
                               capture_output=True, text=True, timeout=90)
        assert probe.returncode == 0, probe.stderr
        result = json.loads(probe.stdout.split("RESULT", 1)[1])
        assert result["clock"] > 0 and result["moved"] > 0.3
        assert result["frame"] == "bot/odom"
        assert result["joints"] == ["left_wheel_joint", "right_wheel_joint"]
        paused = bridge_ws.run("service", "call", "/world/empty/control",
                               "ros_gz_interfaces/srv/ControlWorld",
                               "{world_control: {pause: true}}")
        assert "success: true" in paused.stdout, paused.stderr
        clock = bridge_ws.run("topic", "echo", "--sim", "/world/empty/clock", "--once", "--field",
                              "paused")
        assert clock.stdout.strip().lower().startswith("true"), clock.stdout
        spawned = bridge_ws.run("service", "call", "/world/empty/create",
                                "ros_gz_interfaces/srv/SpawnEntity",
                                f"{{entity_factory: {{name: two, sdf_filename: '{ROBOT}', "
                                "pose: {position: {y: 2.0, z: 0.06}}}}")
        assert "success: true" in spawned.stdout, spawned.stderr
        moved = bridge_ws.run("service", "call", "/world/empty/set_pose",
                              "ros_gz_interfaces/srv/SetEntityPose",
                              "{entity: {name: two}, pose: {position: {x: 3.0, z: 0.06}}}")
        assert "success: true" in moved.stdout, moved.stderr
        for expected in ("true", "false"):  # the second time there is nothing to remove
            removed = bridge_ws.run("service", "call", "/world/empty/remove",
                                    "ros_gz_interfaces/srv/DeleteEntity",
                                    "{entity: {name: bot}}")
            assert f"success: {expected}" in removed.stdout, removed.stderr
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130


def _launcher() -> list[str]:
    from tests.support.processes import launcher_argv

    return launcher_argv()


def _read_until(proc, needle: str) -> str:
    seen = []
    for line in proc.stdout:
        seen.append(line)
        if needle in line:
            return line
    return "".join(seen)


@pytest.mark.parametrize("text, expected", [
    ("", "the bridge config is empty"),
    ("topic_name: /clock\n", "the top level must be a list of entries"),
    ("- topic_name: /a\n  ros_type_name: std_msgs/msg/Bool\n  gz_type_name: gz.msgs.Boolean\n"
     "  directon: GZ_TO_ROS\n", "entry 1: unknown key 'directon' (did you mean 'direction'"),
    ("- topic_name: /a\n  ros_type_name: std_msgs/msg/Bol\n  gz_type_name: gz.msgs.Boolean\n",
     "bad.yaml:2:18: entry 1: ros_type_name: unknown message type 'std_msgs/msg/Bol' (did you "
     "mean 'std_msgs/msg/Bool'"),
    ("- topic_name: /a\n  ros_type_name: std_msgs/msg/Bool\n  gz_type_name: gz.msgs.Bool\n",
     "bad.yaml:3:17: entry 1: gz_type_name: unknown sim type 'gz.msgs.Bool' (did you mean "
     "'gz.msgs.Boolean'"),
    ("- service_name: /s\n  ros_type_name: std_srvs/srv/Empty\n  gz_req_type_name: gz.msgs.Emty\n"
     "  gz_rep_type_name: gz.msgs.Empty\n", "bad.yaml:3:21: entry 1: gz_req_type_name: the sim "
     "has no service taking 'gz.msgs.Emty'"),
    ("- topic_name: /a\n  ros_type_name: std_msgs/msg/Bool\n",
     "entry 1: gz_type_name is required"),
    ("- topic_name: /a\n  ros_topic_name: /b\n  ros_type_name: std_msgs/msg/Bool\n"
     "  gz_type_name: gz.msgs.Boolean\n", "cannot be combined with ros_topic_name"),
    ("- topic_name: /a\n  ros_type_name: std_msgs/msg/Bool\n  gz_type_name: gz.msgs.Boolean\n"
     "  direction: SIDEWAYS\n",
     "direction: expected one of BIDIRECTIONAL, GZ_TO_ROS, ROS_TO_GZ, got 'SIDEWAYS'"),
    ("- topic_name: /a\n  ros_type_name: std_msgs/msg/Bool\n  gz_type_name: gz.msgs.Boolean\n"
     "  lazy: maybe\n", "entry 1: lazy: expected true or false, got 'maybe'"),
    ("- topic_name: /a\n  ros_type_name: std_msgs/msg/Bool\n  gz_type_name: gz.msgs.Boolean\n"
     "  publisher_queue: 0\n", "entry 1: publisher_queue: expected a number ≥ 1, got 0"),
    ("- topic_name: /a\n  ros_type_name: tf2_msgs/msg/TFMessage\n"
     "  gz_type_name: gz.msgs.Pose_V\n  direction: ROS_TO_GZ\n", "ROS_TO_GZ is not supported"),
    ("- [1, 2]\n", "an entry must be a mapping"),
])
def test_bad_config_entries_are_reported_with_file_line_and_number(bridge_ws, text, expected):
    bridge_ws.write("bad.yaml", text)
    done = subprocess.run([PY, "-m", "launcher.nodes.parameter_bridge", "--ros-args", "-p",
                           "config_file:=bad.yaml"], cwd=bridge_ws.root, env=bridge_ws.env,
                          capture_output=True, text=True, timeout=5 + 25, input="") \
        if expected.startswith(("the bridge config", "the top level")) else \
        _run_briefly(bridge_ws, ["config_file:=bad.yaml"])
    assert expected in done.stderr, done.stderr
    assert "Traceback" not in done.stderr


def test_a_config_file_that_is_no_path_is_refused_by_name(bridge_ws):
    done = subprocess.run([PY, "-m", "launcher.nodes.parameter_bridge", "--ros-args", "-p",
                           "config_file:=5"], cwd=bridge_ws.root, env=bridge_ws.env,
                          capture_output=True, text=True, timeout=30, input="")
    assert done.returncode == 1, done.stderr
    assert "parameter 'config_file': expected text, got 5" in done.stderr, done.stderr
    assert "Traceback" not in done.stderr


def test_a_bad_type_skips_its_entry_and_the_rest_is_bridged(bridge_ws):
    bridge_ws.write("bad.yaml", """- topic_name: /a
  ros_type_name: std_msgs/msg/Bool
  gz_type_name: gz.msgs.Boolean
- topic_name: /b
  ros_type_name: geometry_msgs/msg/Twst
  gz_type_name: gz.msgs.Twist
""")
    done = _run_briefly(bridge_ws, ["config_file:=bad.yaml"])
    assert "bad.yaml:5:18: entry 2: ros_type_name: unknown message type " \
        "'geometry_msgs/msg/Twst' (did you mean 'geometry_msgs/msg/Twist'" in done.stderr, \
        done.stderr
    assert "bridging 1 of 2 entries" in done.stdout + done.stderr


def _run_briefly(ws, params: list[str]):
    """Start a bridge, wait until it has read its config, stop it; its output."""
    proc = subprocess.Popen([PY, "-m", "launcher.nodes.parameter_bridge", "--ros-args",
                             *sum((["-p", p] for p in params), [])], cwd=ws.root, env=ws.env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        proc.wait(3)
    except subprocess.TimeoutExpired:
        proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=30)
    return subprocess.CompletedProcess(proc.args, proc.returncode, out, err)


def test_missing_config_file_and_cli_form_errors(bridge_ws):
    done = subprocess.run([PY, "-m", "launcher.nodes.parameter_bridge", "--ros-args", "-p",
                           "config_file:=nope.yaml"], cwd=bridge_ws.root, env=bridge_ws.env,
                          capture_output=True, text=True, timeout=30)
    assert done.returncode == 1 and "bridge config file 'nope.yaml' does not exist" in \
        done.stderr
    bad = subprocess.run([PY, "-m", "launcher.nodes.parameter_bridge", "/clock-rosgraph"],
                         cwd=bridge_ws.root, env=bridge_ws.env, capture_output=True, text=True,
                         timeout=30)
    assert bad.returncode == 1 and "expected TOPIC@ROS_TYPE@SIM_TYPE" in bad.stderr

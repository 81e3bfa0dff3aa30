"""mujoco_ros2_control's demos unchanged on launcher: its ros2_control_node runs the MJCF scene
in launcher's sim with controller_manager inside; real spawners, real `launcher topic`,
`service` and `control` against real processes on a real router. And the bad inputs."""

from __future__ import annotations

import json
import math
import re
import time

import pytest

from tests.support.environment import shared
from tests.support.nodes import node_package, stop
from tests.support.waiting import wait_until

DEMOS = ("external", "mujoco_ros2_control", "mujoco_ros2_control_demos")
SERVICES = "/mujoco_ros2_control_node"


@pytest.fixture
def demos(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared(*DEMOS))
    return ws


@pytest.fixture
def cloned(ws):
    """A colcon workspace whose src/ holds the whole mujoco_ros2_control repository, cloned
    and never built (a link to the copy in ../shared: its packages only as source)."""
    src = ws.root / "colcon_ws" / "src"
    src.mkdir(parents=True)
    (src / "mujoco_ros2_control").symlink_to(shared(*DEMOS[:2]), target_is_directory=True)
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(src)
    return ws


def numbers(text: str) -> list[float]:
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", text)]


def joints(ws) -> dict[str, float]:
    done = ws.run("topic", "echo", "/joint_states", "sensor_msgs/msg/JointState", "--once",
                  timeout=30)
    assert done.returncode == 0, done.stderr
    names = re.findall(r"^- (\w+)$", done.stdout.split("position:")[0], re.M)
    positions = numbers(done.stdout.split("position:")[1].split("velocity:")[0])
    return dict(zip(names, positions, strict=True))


def launch(ws, demo: str, ready: str = "Configured and activated position_controller",
           *arguments: str):
    proc = ws.start("launch", "mujoco_ros2_control_demos", demo, "headless:=true", *arguments,
                    output="demo.out")
    ws.wait_for_output(ready, 90, "demo.out")
    return proc


def sim_time(ws) -> float:
    done = ws.run("topic", "echo", "/clock", "rosgraph_msgs/msg/Clock", "--once", timeout=30)
    assert done.returncode == 0, done.stderr
    sec, nanosec = numbers(done.stdout)[:2]
    return sec + nanosec * 1e-9


def call(ws, name: str, type_name: str, request: str) -> str:
    # (the answer waited for as long as `ros2 service call` waits: a loaded machine steps
    # 250 steps of the paused sim in more than the CLI's default 5 s)
    done = ws.run("service", "call", f"{SERVICES}/{name}",
                  f"mujoco_ros2_control_msgs/srv/{type_name}", request, "--timeout", "50",
                  timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_basic_robot_demo_runs_unchanged_and_its_docstring_command_moves_the_arm(demos):
    proc = launch(demos, "01_basic_robot.launch.py")
    try:
        demos.wait_for_output("Configured and activated pose_broadcaster", 60, "demo.out")
        listed = demos.run("control", "list_controllers", timeout=30).stdout
        for name in ("joint_state_broadcaster", "position_controller", "gripper_controller",
                     "pose_broadcaster"):
            assert re.search(rf"{name}\s+\S+\s+active", listed), listed
        sent = demos.run("topic", "pub", "--once", "/position_controller/commands",
                         "std_msgs/msg/Float64MultiArray", "data: [0.5, -0.5]")
        assert sent.returncode == 0, sent.stderr
        assert wait_until(lambda: abs(joints(demos)["joint1"] - 0.5) < 0.02 and
                          abs(joints(demos)["joint2"] + 0.5) < 0.02), joints(demos)
    finally:
        assert stop(proc) == 130


@pytest.mark.parametrize("arguments", [(), ("use_urdf_inputs:=true",)],
                         ids=["inputs-files", "inputs-in-the-urdf"])
def test_mjcf_generation_demo_converts_at_run_time_and_its_arm_moves(demos, arguments):
    proc = launch(demos, "02_mjcf_generation.launch.py",
                  "Configured and activated position_controller", *arguments)
    try:
        mjcf = demos.run("topic", "echo", "/mujoco_robot_description", "std_msgs/msg/String",
                         "--once", "--full-length", timeout=30)
        assert re.search(r'<camera [^>]*name=\\"camera\\"', mjcf.stdout), mjcf.stdout[:2000]
        sent = demos.run("topic", "pub", "--once", "/position_controller/commands",
                         "std_msgs/msg/Float64MultiArray", "data: [0.5, -0.5]")
        assert sent.returncode == 0, sent.stderr
        assert wait_until(lambda: abs(joints(demos)["joint1"] - 0.5) < 0.02 and
                          abs(joints(demos)["joint2"] + 0.5) < 0.02), joints(demos)
    finally:
        assert stop(proc) == 130


def test_basic_robot_publishes_clock_actuator_states_heartbeat_and_pose(demos):
    proc = launch(demos, "01_basic_robot.launch.py")
    try:
        first = sim_time(demos)
        time.sleep(1.0)
        assert sim_time(demos) > first + 0.5  # sim time runs at about real time
        states = demos.run("topic", "echo", "/mujoco_actuators_states",
                           "sensor_msgs/msg/JointState", "--once", timeout=30)
        assert "gripper_right_finger_joint" in states.stdout, states  # a passive joint too
        beat = demos.run("topic", "echo", "/heart_beat_plugin/mujoco_heartbeat",
                         "std_msgs/msg/String", "--once", timeout=30)
        assert "MuJoCo ROS2 Control Heartbeat #" in beat.stdout, beat
        demos.wait_for_output("Configured and activated pose_broadcaster", 60, "demo.out")
        pose = demos.run("topic", "echo", "/pose_broadcaster/pose",
                         "geometry_msgs/msg/PoseStamped", "--once", timeout=30)
        assert "frame_id: ee_link" in pose.stdout, pose
    finally:
        assert stop(proc) == 130


def test_step_simulation_steps_a_paused_sim_exactly_and_is_refused_while_running(demos):
    proc = launch(demos, "01_basic_robot.launch.py")
    try:
        refused = call(demos, "step_simulation", "StepSimulation", "{steps: 10}")
        assert "success: false" in refused and "pause" in refused, refused
        assert "success: true" in call(demos, "set_pause", "SetPause", "{paused: true}")
        before = sim_time(demos)
        time.sleep(0.5)
        assert sim_time(demos) == before  # paused: time stands still
        stepped = call(demos, "step_simulation", "StepSimulation", "{steps: 250}")
        assert "success: true" in stepped, stepped
        assert sim_time(demos) == pytest.approx(before + 250 * 0.002, abs=1e-6)
        zero = call(demos, "step_simulation", "StepSimulation", "{steps: 0}")
        assert "success: false" in zero, zero
        assert "success: true" in call(demos, "set_pause", "SetPause", "{paused: false}")
    finally:
        assert stop(proc) == 130


def test_reset_world_returns_to_the_start_and_to_a_keyframe(demos):
    proc = launch(demos, "01_basic_robot.launch.py")
    try:
        demos.run("control", "set_controller_state", "position_controller", "inactive",
                  timeout=30)
        moved = call(demos, "reset_world", "ResetWorld",
                     "{keyframe: start_90}")
        assert "success: true" in moved, moved
        assert wait_until(lambda: abs(joints(demos)["joint1"] - 1.57) < 0.05), joints(demos)
        back = call(demos, "reset_world", "ResetWorld", "{}")
        assert "success: true" in back, back
        assert wait_until(lambda: abs(joints(demos)["joint1"]) < 0.05), joints(demos)
        unknown = call(demos, "reset_world", "ResetWorld", "{keyframe: start_9}")
        assert "success: false" in unknown and "did you mean ''start_90''" in unknown, unknown
    finally:
        assert stop(proc) == 130


def test_pid_demo_moves_motor_actuators_through_their_pids(demos):
    proc = launch(demos, "03_pid_control.launch.py")
    try:
        sent = demos.run("topic", "pub", "--once", "/position_controller/commands",
                         "std_msgs/msg/Float64MultiArray", "data: [0.5, -0.5]")
        assert sent.returncode == 0, sent.stderr
        assert wait_until(lambda: abs(joints(demos)["joint1"] - 0.5) < 0.05 and
                          abs(joints(demos)["joint2"] + 0.5) < 0.05), joints(demos)
    finally:
        assert stop(proc) == 130


def test_transmissions_demo_moves_the_joints_through_the_differential(demos):
    proc = launch(demos, "04_transmissions.launch.py")
    try:
        sent = demos.run("topic", "pub", "--once", "/position_controller/commands",
                         "std_msgs/msg/Float64MultiArray", "data: [0.3, -0.2]")
        assert sent.returncode == 0, sent.stderr
        assert wait_until(lambda: abs(joints(demos)["joint1"] - 0.3) < 0.05 and
                          abs(joints(demos)["joint2"] + 0.2) < 0.05), joints(demos)
    finally:
        assert stop(proc) == 130


def test_base_velocity_demo_drives_the_floating_base(demos):
    proc = launch(demos, "05_base_velocity_plugin.launch.py",
                  "Configured and activated arm_position_controller")
    try:
        odom = ("/simulator/floating_base_state", "nav_msgs/msg/Odometry")
        start = numbers(demos.run("topic", "echo", *odom, "--once", "--field",
                                  "pose.pose.position.x", timeout=30).stdout)[0]
        sent = demos.run("topic", "pub", "-r", "10", "-t", "15", "/cmd_vel",
                         "geometry_msgs/msg/Twist", "{linear: {x: 0.5}}", timeout=30)
        assert sent.returncode == 0, sent.stderr
        moved = numbers(demos.run("topic", "echo", *odom, "--once", "--field",
                                  "pose.pose.position.x", timeout=30).stdout)[0]
        assert moved > start + 0.3, (start, moved)
    finally:
        assert stop(proc) == 130


def test_a_cloned_unbuilt_repository_runs_launchers_ros2_control_node_and_says_so_once(cloned):
    proc = launch(cloned, "01_basic_robot.launch.py")
    try:
        out = cloned.wait_for_output("Configured and activated pose_broadcaster", 60, "demo.out")
    finally:
        assert stop(proc) == 130
    source = cloned.root / "colcon_ws" / "src" / "mujoco_ros2_control" / "mujoco_ros2_control"
    said = [line for line in out.splitlines() if "source only" in line]
    assert said == [f"[INFO] [launch]: package 'mujoco_ros2_control' at {source} is source "
                    "only (a compiled ament_cmake package, never built): launcher runs its own "
                    "implementation of it"], out
    assert "has no executable" not in out and f"found twice: {source} (used)" not in out, out


def settled_end_pose(scene, command: dict[str, float]) -> list[float]:
    """Where the demo arm's ee_link comes to rest under `command`, derived from the model.

    mujoco_ros2_control writes a position command straight into the ctrl of a position
    actuator (MujocoSystemInterface::write), so each arm joint is a servo that stops where
    its pull kp·(ctrl − q) balances the joint's gravity load less its passive forces (the
    forearm's gravcomp="1"): q = ctrl − (qfrc_bias − qfrc_passive) / kp at rest. Solved by
    fixed-point iteration (it contracts: the load changes little with q), the fingers held at
    their commands, then the site's forward kinematics. joint1's frictionloss (1 N·m against
    kp 25000 N·m/rad: at most 4e-5 rad) is left out. The commanded joints' kinematics alone
    (z -0.479) would miss the sag by 9 mm."""
    import mujoco

    model = mujoco.MjModel.from_xml_path(str(scene))
    data = mujoco.MjData(model)
    for joint, value in command.items():
        data.joint(joint).qpos = value
    for _ in range(30):
        mujoco.mj_forward(model, data)
        for joint in ("joint1", "joint2"):
            dof, kp = model.joint(joint).dofadr[0], model.actuator(joint).gainprm[0]
            data.joint(joint).qpos = command[joint] - \
                (data.qfrc_bias[dof] - data.qfrc_passive[dof]) / kp
    mujoco.mj_forward(model, data)
    return [float(v) for v in data.site("ee_link").xpos]


def test_the_arms_end_pose_after_the_demo_trajectory_is_where_the_servos_settle(demos):
    """mujoco_ros2_control's own launch test sends [0.5, -0.5] to the arm and closes the
    gripper, then reads /pose_broadcaster/pose: (1.8753, 0, -0.4885) with a MuJoCo of 3.5 or
    later, (1.8678, 0, -0.5162) with the older one of the ROS binaries, whose gravcomp left out
    the forearm's compensation at joint1 (fixed in MuJoCo 3.5, issue 3066). launcher runs
    the MuJoCo that is installed; the expected pose is derived from the model with it."""
    proc = launch(demos, "01_basic_robot.launch.py")
    try:
        demos.wait_for_output("Configured and activated pose_broadcaster", 60, "demo.out")
        for topic, data in (("/position_controller/commands", "[0.5, -0.5]"),
                            ("/gripper_controller/commands", "[-0.04]")):
            sent = demos.run("topic", "pub", "--once", topic, "std_msgs/msg/Float64MultiArray",
                             f"data: {data}")
            assert sent.returncode == 0, sent.stderr
        assert wait_until(lambda: abs(joints(demos)["joint1"] - 0.5) < 0.01 and
                          abs(joints(demos)["gripper_left_finger_joint"] + 0.04) < 0.002,
                          30), joints(demos)
        time.sleep(1.0)  # (then settled: the arm's servos are critically damped)
        pose = demos.run("topic", "echo", "/pose_broadcaster/pose",
                         "geometry_msgs/msg/PoseStamped", "--once", timeout=30)
    finally:
        assert stop(proc) == 130
    assert pose.returncode == 0, pose.stderr
    position = numbers(pose.stdout.split("position:")[1].split("orientation:")[0])
    expected = settled_end_pose(shared(*DEMOS, "demo_resources", "scenes", "scene.xml"),
                                {"joint1": 0.5, "joint2": -0.5,
                                 "gripper_left_finger_joint": -0.04,
                                 "gripper_right_finger_joint": 0.04})
    print(f"end pose: {position} (expected {expected})")
    assert position == pytest.approx(expected, abs=0.01)


# --- bad inputs: ros2_control_node says where and what, and exits -----------------------------
ARM = """<mujoco model="arm">
  <worldbody>
    <body name="link">
      <joint name="j1" axis="0 1 0"/>
      <geom type="box" size="0.1 0.1 0.5" pos="0 0 0.5"/>
    </body>
  </worldbody>
  <actuator><position name="j1" joint="j1" kp="100"/></actuator>
</mujoco>
"""


def robot(model: str, command: str = "position", extra: str = "") -> str:
    return f"""<robot name="arm">
  <link name="world"/><link name="link"/>
  <joint name="j1" type="revolute"><parent link="world"/><child link="link"/>
    <axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="100" velocity="3"/></joint>
  <ros2_control name="MujocoSystem" type="system">
    <hardware><plugin>mujoco_ros2_control/MujocoSystemInterface</plugin>
      <param name="mujoco_model">{model}</param>{extra}</hardware>
    <joint name="j1"><command_interface name="{command}"/><state_interface name="position"/>
    </joint>
  </ros2_control>
</robot>"""


def node_args(ws, description: str, *files: str) -> list[str]:
    import yaml

    params = ws.write("description.yaml", yaml.safe_dump(
        {"/**": {"ros__parameters": {"robot_description": description}}}))
    args = ["run", "mujoco_ros2_control", "ros2_control_node", "--ros-args"]
    for path in (params, *files):
        args += ["--params-file", str(path)]
    return args


def node_run(ws, description: str, *files: str):
    return ws.run(*node_args(ws, description, *files), timeout=60)


def test_an_mjcf_that_does_not_compile_is_named_with_its_line(ws):
    ws.own_bus()
    bad = ws.write("arm.xml", ARM.replace('<joint name="j1" axis="0 1 0"/>',
                                          '<joint name="j1" axis="0 1 0" kind="x"/>'))
    done = node_run(ws, robot(str(bad)))
    assert done.returncode == 1
    assert f"{bad}: MuJoCo could not read it" in done.stderr and "line 4" in done.stderr, \
        done.stderr
    assert "Traceback" not in done.stderr


def test_a_missing_mujoco_model_is_refused(ws):
    ws.own_bus()
    done = node_run(ws, robot("/nowhere/scene.xml"))
    assert done.returncode == 1
    assert "mujoco_model '/nowhere/scene.xml' does not exist" in done.stderr, done.stderr


def test_an_unknown_plugin_type_is_refused_with_the_nearest_one(ws):
    ws.own_bus()
    model = ws.write("arm.xml", ARM)
    plugins = ws.write("plugins.yaml", "/**:\n  ros__parameters:\n    mujoco_plugins:\n"
                       "      beat:\n        type: mujoco_ros2_control_plugins/"
                       "HeartbeatPublisherPlugn\n")
    done = node_run(ws, robot(str(model)), str(plugins))
    assert done.returncode == 1
    assert "unknown plugin 'mujoco_ros2_control_plugins/HeartbeatPublisherPlugn'" in \
        done.stderr and "did you mean 'mujoco_ros2_control_plugins/HeartbeatPublisher" \
        "Plugin'" in done.stderr, done.stderr


def test_a_command_interface_the_actuator_cannot_follow_is_refused(ws):
    ws.own_bus()
    model = ws.write("arm.xml", ARM)
    done = node_run(ws, robot(str(model), command="effort"))
    assert done.returncode == 1
    assert "joint 'j1': its 'effort' command interface needs a motor" in done.stderr and \
        "'j1' is a position actuator" in done.stderr, done.stderr


def test_a_pid_for_a_joint_the_model_lacks_is_said_at_its_line(ws):
    ws.own_bus()
    model = ws.write("arm.xml", ARM)
    pids = ws.write("pids.yaml", "/**:\n  ros__parameters:\n    pid_gains:\n      position:\n"
                    "        jl:\n          p: 10.0\n")
    extra = f'<param name="pids_config_file">{pids}</param>'
    proc = ws.start(*node_args(ws, robot(str(model), extra=extra)), output="node.out")
    try:
        ws.wait_for_output("this PID drives nothing", 30, "node.out")
        out = ws.output("node.out")
        assert f"{pids}:5: pid_gains.position.jl: the MuJoCo model has no joint" in out, out
    finally:
        assert stop(proc) in (0, 130)


# A node that waits for one message on each topic it is given and prints what it saw.
PICTURES = """
import json, sys
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image
rclpy.init()
node = Node("camera_probe")
seen = {}
def keep(topic):
    def heard(message):
        if topic in seen:
            return
        if isinstance(message, CameraInfo):
            seen[topic] = {"frame": message.header.frame_id, "k": list(message.k),
                           "size": [message.width, message.height]}
            return
        width, height = message.width, message.height
        summary = {"frame": message.header.frame_id, "encoding": message.encoding,
                   "size": [width, height], "bytes": len(bytes(message.data))}
        if message.encoding == "32FC1":
            import array
            values = array.array("f", bytes(message.data))
            summary["nearest"], summary["farthest"] = min(values), max(values)
            summary["finite"] = all(v == v and abs(v) != float("inf") for v in values)
        seen[topic] = summary
    return heard
for spec in sys.argv[1:]:
    topic, kind = spec.split("=")
    node.create_subscription(CameraInfo if kind == "info" else Image, topic, keep(topic), 1)
while len(seen) < len(sys.argv) - 1:
    rclpy.spin_once(node, timeout_sec=0.1)
print("SEEN " + json.dumps(seen), flush=True)
"""


def pictures(ws, *topics: str, trigger: str = "") -> dict:
    """One message of each `TOPIC=image|info`, summed up (a `trigger` service called once
    the probe listens)."""
    node_package(ws, "camera_probe", {"probe.py": PICTURES})
    probe = ws.start("run", "camera_probe", "probe.py", *topics, output="probe.out")
    try:
        if trigger:
            time.sleep(2.0)
            done = ws.run("service", "call", trigger, "std_srvs/srv/Trigger", timeout=30)
            assert done.returncode == 0 and "success: true" in done.stdout, done.stderr
        assert probe.wait(90) == 0, ws.output("probe.out")
    finally:
        if probe.poll() is None:
            probe.kill()
    line = next(x for x in ws.output("probe.out").splitlines() if x.startswith("SEEN "))
    return json.loads(line[5:])


def test_the_camera_plugin_gives_colour_aligned_depth_and_camera_info(demos):
    proc = launch(demos, "01_basic_robot.launch.py")
    try:
        seen = pictures(demos, "/camera/color/image_raw=image",
                        "/camera/aligned_depth_to_color/image_raw=image",
                        "/camera/color/camera_info=info")
    finally:
        assert stop(proc) in (0, 130)
    colour = seen["/camera/color/image_raw"]
    depth = seen["/camera/aligned_depth_to_color/image_raw"]
    info = seen["/camera/color/camera_info"]
    assert colour == {"frame": "camera_color_optical_frame", "encoding": "rgb8",
                      "size": [640, 480], "bytes": 640 * 480 * 3}
    assert depth["encoding"] == "32FC1" and depth["size"] == [640, 480] and depth["finite"]
    # the floor in metres, up to the far clip where the camera sees nothing
    assert 0.05 < depth["nearest"] < depth["farthest"] == pytest.approx(50.0, rel=1e-3)
    focal = 240 / math.tan(math.radians(58) / 2)  # the camera's fovy: 58°
    assert info["size"] == [640, 480] and info["frame"] == "camera_color_optical_frame"
    assert info["k"] == pytest.approx([focal, 0, 320, 0, focal, 240, 0, 0, 1])


def test_a_late_subscriber_gets_colour_depth_and_info_from_drawers_made_before_it_came(demos):
    """As mujoco_ros2_control's test_camera_topics (all three within 5 s of subscribing): the
    renderer makes its GL drawers when the model comes, so a subscriber waits for no GL
    start-up. The time is printed, not asserted (a loaded machine stretches it)."""
    proc = launch(demos, "01_basic_robot.launch.py")
    try:
        # said when the first drawer is made: here while nobody watches the camera
        demos.wait_for_output("drawing the cameras of world 'scene'", 60, "demo.out")
        began = time.monotonic()
        seen = pictures(demos, "/camera/color/image_raw=image",
                        "/camera/aligned_depth_to_color/image_raw=image",
                        "/camera/color/camera_info=info")
        took = time.monotonic() - began
    finally:
        assert stop(proc) in (0, 130)
    print(f"bench: colour, depth and camera_info {took:.2f} s after the probe started")
    assert set(seen) == {"/camera/color/image_raw", "/camera/aligned_depth_to_color/image_raw",
                         "/camera/color/camera_info"}, seen


EYE = ARM.replace('<body name="link">', '<camera name="eye" pos="2 0 0.5" xyaxes="0 1 0 0 0 1"'
                  ' resolution="64 48"/>\n    <body name="link">')
CAMERA_PLUGIN = """/**:
  ros__parameters:
    mujoco_plugins:
      mujoco_camera_plugin:
        type: mujoco_ros2_control_plugins/CameraPlugin
        camera_publish_rate: 5.0
        {camera}:
          policy: polled
          image_topic: /eye/image
          depth_topic: /eye/depth
          info_topic: /eye/info
"""


def test_a_polled_camera_draws_once_per_trigger(ws):
    ws.own_bus()
    model = ws.write("arm.xml", EYE)
    plugins = ws.write("plugins.yaml", CAMERA_PLUGIN.format(camera="eye"))
    proc = ws.start(*node_args(ws, robot(str(model)), str(plugins)), output="node.out")
    try:
        ws.wait_for_output("camera 'eye' (polled, 64x48)", 60, "node.out")
        seen = pictures(ws, "/eye/image=image", trigger="/mujoco_camera_plugin/eye/trigger")
    finally:
        assert stop(proc) in (0, 130)
    assert seen["/eye/image"]["size"] == [64, 48]


def test_camera_settings_for_a_camera_the_model_lacks_are_said_at_their_line(ws):
    ws.own_bus()
    model = ws.write("arm.xml", EYE)
    plugins = ws.write("plugins.yaml", CAMERA_PLUGIN.format(camera="eyes"))
    proc = ws.start(*node_args(ws, robot(str(model)), str(plugins)), output="node.out")
    try:
        out = ws.wait_for_output("these settings are unused", 60, "node.out")
        assert f"{plugins}:8: mujoco_plugins.mujoco_camera_plugin.eyes: the MuJoCo model has " \
               "no camera 'eyes' (did you mean 'eye'?)" in out, out
        ws.wait_for_output("camera 'eye' (streaming, 64x48)", 30, "node.out")  # runs on
    finally:
        assert stop(proc) in (0, 130)


WRENCH_PLUGIN = """/**:
  ros__parameters:
    mujoco_plugins:
      push:
        type: mujoco_ros2_control_plugins/ExternalWrenchPlugin
"""


def wrench(body: str, seconds: int) -> str:
    return ("{wrenches: {external_wrenches: [{wrench: {header: {frame_id: " + body + "}, "
            "wrench: {force: {x: 400.0}}}, application_point: {z: 1.0}, "
            "duration: {sec: " + str(seconds) + "}}]}}")


def wrench_node(ws):
    """mujoco_ros2_control's node with the ExternalWrenchPlugin `push`, ready."""
    ws.own_bus()
    model = ws.write("arm.xml", ARM)
    plugins = ws.write("plugins.yaml", WRENCH_PLUGIN)
    proc = ws.start(*node_args(ws, robot(str(model)), str(plugins)), output="node.out")
    try:
        ws.wait_for_output("ExternalWrenchPlugin: /push/apply_wrench", 60, "node.out")
    except AssertionError:
        stop(proc)
        raise
    return proc


def test_the_external_wrench_plugin_pushes_a_body_for_its_duration(ws):
    proc = wrench_node(ws)
    try:
        before = sim_time(ws)
        pushing = ws.start("service", "call", "/push/apply_wrench",
                           "mujoco_ros2_control_msgs/srv/ApplyExternalWrench", wrench("link", 3),
                           output="call.out")
        tilted = wait_until(lambda: abs(actuator_position(ws, "j1")) > 0.05, 20)
        assert pushing.wait(60) == 0, ws.output("call.out")
        answered = sim_time(ws)
    finally:
        assert stop(proc) in (0, 130)
    assert tilted, "the pushed link did not tilt"
    assert "success: true" in ws.output("call.out") and answered - before >= 3.0


def test_a_live_wrench_is_shown_as_arrow_markers_in_its_bodys_frame(ws):
    proc = wrench_node(ws)
    try:
        pushing = ws.start("service", "call", "/push/apply_wrench",
                           "mujoco_ros2_control_msgs/srv/ApplyExternalWrench", wrench("link", 3),
                           output="call.out")
        shown = wait_until(lambda: "external_wrench/force" in ws.run(
            "topic", "echo", "/mujoco_ros2_control_node/wrench_markers",
            "visualization_msgs/msg/MarkerArray", "--once", timeout=30).stdout, 20)
        markers = ws.run("topic", "echo", "/mujoco_ros2_control_node/wrench_markers",
                         "visualization_msgs/msg/MarkerArray", "--once", timeout=30).stdout
        assert pushing.wait(60) == 0, ws.output("call.out")
    finally:
        assert stop(proc) in (0, 130)
    assert shown, markers
    assert "frame_id: link" in markers and "x: 4.0" in markers, markers  # 400 N * 0.01 m/N


def test_a_wrench_on_a_body_the_model_lacks_is_refused_whole(ws):
    proc = wrench_node(ws)
    try:
        done = ws.run("service", "call", "/push/apply_wrench",
                      "mujoco_ros2_control_msgs/srv/ApplyExternalWrench", wrench("lnk", 1),
                      timeout=60)
    finally:
        assert stop(proc) in (0, 130)
    assert "success: false" in done.stdout, done.stdout
    assert "Body 'lnk' not found in MuJoCo model (did you mean 'link'?)" in done.stdout


def actuator_position(ws, joint: str) -> float:
    done = ws.run("topic", "echo", "/mujoco_actuators_states", "sensor_msgs/msg/JointState",
                  "--once", timeout=30)
    assert done.returncode == 0, done.stderr
    names = re.findall(r"^- (\w+)$", done.stdout.split("position:")[0], re.M)
    positions = numbers(done.stdout.split("position:")[1].split("velocity:")[0])
    return dict(zip(names, positions, strict=True))[joint]


def actuator_states(ws) -> dict[str, list]:
    """One /mujoco_actuators_states message: its names and each array, in order."""
    done = ws.run("topic", "echo", "/mujoco_actuators_states", "sensor_msgs/msg/JointState",
                  "--once", timeout=30)
    assert done.returncode == 0, done.stderr
    text = done.stdout.split("name:")[1]
    names, rest = text.split("position:")
    position, rest = rest.split("velocity:")
    velocity, effort = rest.split("effort:")
    return {"name": re.findall(r"^- (\w+)$", names, re.M), "position": numbers(position),
            "velocity": numbers(velocity), "effort": numbers(effort)}


# --- site transmissions: an actuator on a site drives the joint named as it ------------------
# mujoco_ros2_control_tests' site_velocity_robot: a slider pushed by a velocity servo on a site
# of its body (upstream's <velocity kv="1">, spelled as the general actuator it is)
SLIDER = """<mujoco model="site_velocity_robot">
  <option gravity="0 0 0" timestep="0.002"/>
  <worldbody>
    <body name="slider">
      <inertial pos="0 0 0" mass="1.0" diaginertia="0.01 0.01 0.01"/>
      <joint name="slider_joint" type="slide" axis="1 0 0" range="-2 2" damping="0.2"/>
      <geom type="box" size="0.05 0.05 0.05"/>
      <site name="drive_site" size="0.02"/>
    </body>
  </worldbody>
  <actuator>
    <general name="slider_joint" site="drive_site" gainprm="1" biastype="affine"
             biasprm="0 0 -1" ctrlrange="-1 1"/>
  </actuator>
</mujoco>
"""
SLIDER_ROBOT = """<robot name="site_velocity_robot">
  <link name="world"/><link name="slider"/>
  <joint name="slider_joint" type="prismatic"><parent link="world"/><child link="slider"/>
    <axis xyz="1 0 0"/><limit lower="-2" upper="2" effort="100" velocity="1"/></joint>
  <ros2_control name="MujocoSystem" type="system">
    <hardware><plugin>mujoco_ros2_control/MujocoSystemInterface</plugin>
      <param name="mujoco_model">{model}</param></hardware>
    <joint name="slider_joint"><command_interface name="velocity"/>
      <state_interface name="position"/><state_interface name="velocity"/>
      <state_interface name="effort"/></joint>
  </ros2_control>
</robot>"""
SLIDER_CONTROLLERS = """controller_manager:
  ros__parameters:
    update_rate: 100
joint_state_broadcaster:
  ros__parameters:
    type: joint_state_broadcaster/JointStateBroadcaster
site_velocity_controller:
  ros__parameters:
    type: forward_command_controller/ForwardCommandController
    interface_name: velocity
    joints: [slider_joint]
"""


def test_a_site_actuator_moves_the_joint_named_as_it_when_commanded(ws):
    ws.own_bus()
    model = ws.write("slider.xml", SLIDER)
    controllers = ws.write("controllers.yaml", SLIDER_CONTROLLERS)
    proc = ws.start(*node_args(ws, SLIDER_ROBOT.format(model=model), str(controllers)),
                    output="node.out")
    try:
        ws.wait_for_output("controller_manager at", 60, "node.out")
        spawned = ws.run("run", "controller_manager", "spawner", "joint_state_broadcaster",
                         "site_velocity_controller", "--param-file", str(controllers),
                         timeout=60)
        assert spawned.returncode == 0, spawned.stderr
        start = joints(ws)["slider_joint"]
        sent = ws.run("topic", "pub", "--once", "/site_velocity_controller/commands",
                      "std_msgs/msg/Float64MultiArray", "data: [0.25]")
        assert sent.returncode == 0, sent.stderr
        # the servo pushes at kv·(0.25 − v) against the damping 0.2·v: 0.25 / 1.2 m/s once
        # steady (its time constant: 1 kg / 1.2 N·s/m), 2 m of travel lasting 10 s
        steady = wait_until(lambda: abs(actuator_states(ws)["velocity"][0] - 0.25 / 1.2)
                            < 0.005, 30)
        moved = joints(ws)["slider_joint"] - start
        states = actuator_states(ws)
    finally:
        assert stop(proc) in (0, 130)
    assert steady and states["name"] == ["slider_joint"], states
    assert moved > 0.3, (start, moved)


def test_a_site_actuator_named_as_no_joint_of_the_model_is_said_at_its_block(ws):
    ws.own_bus()
    model = ws.write("slider.xml", SLIDER.replace('<general name="slider_joint"',
                                                  '<general name="pusher"'))
    robot = SLIDER_ROBOT.format(model=model).replace("slider_joint", "pusher")
    proc = ws.start(*node_args(ws, robot), output="node.out")
    try:
        out = ws.wait_for_output("controller_manager at", 60, "node.out")
    finally:
        assert stop(proc) in (0, 130)
    assert "robot_description:5: joint 'pusher': actuator 'pusher' pushes on a site and the " \
           "MuJoCo model has no joint 'pusher' to read its state from" in out, out


# Every kind of entry /mujoco_actuators_states has, as mujoco_ros2_control registers them: an
# actuator on a joint (named by its joint), one on a site (by its own name, the joint it
# drives), a joint no actuator drives (passive), and a free joint (never listed)
KINDS = """<mujoco model="kinds">
  <option gravity="0 0 0"/>
  <worldbody>
    <body name="base">
      <joint name="turn" axis="0 0 1" damping="1"/>
      <geom type="cylinder" size="0.1 0.05" mass="1"/>
      <body name="carriage" pos="0.3 0 0">
        <joint name="slide" type="slide" axis="1 0 0" damping="1"/>
        <geom type="box" size="0.05 0.05 0.05" mass="1"/>
        <site name="push"/>
        <body name="flap" pos="0.1 0 0">
          <joint name="flap" axis="0 1 0"/>
          <geom type="box" size="0.05 0.01 0.05" mass="0.1"/>
        </body>
      </body>
    </body>
    <body name="crate" pos="2 0 0"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>
  </worldbody>
  <actuator>
    <motor name="turn_motor" joint="turn"/>
    <general name="slide" site="push" gainprm="1" biastype="affine" biasprm="0 0 -1"/>
  </actuator>
</mujoco>
"""
KINDS_ROBOT = """<robot name="kinds">
  <link name="world"/><link name="base"/><link name="carriage"/>
  <joint name="turn" type="continuous"><parent link="world"/><child link="base"/>
    <axis xyz="0 0 1"/></joint>
  <joint name="slide" type="prismatic"><parent link="base"/><child link="carriage"/>
    <axis xyz="1 0 0"/><limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <ros2_control name="MujocoSystem" type="system">
    <hardware><plugin>mujoco_ros2_control/MujocoSystemInterface</plugin>
      <param name="mujoco_model">{model}</param></hardware>
    <joint name="turn"><command_interface name="effort"/><state_interface name="position"/>
    </joint>
    <joint name="slide"><command_interface name="velocity"/><state_interface name="position"/>
    </joint>
  </ros2_control>
</robot>"""


def test_actuator_states_have_one_entry_per_actuator_and_passive_joint_named_as_upstream(ws):
    ws.own_bus()
    model = ws.write("kinds.xml", KINDS)
    proc = ws.start(*node_args(ws, KINDS_ROBOT.format(model=model)), output="node.out")
    try:
        ws.wait_for_output("controller_manager at", 60, "node.out")
        states = actuator_states(ws)
    finally:
        assert stop(proc) in (0, 130)
    assert states["name"] == ["turn", "slide", "flap"], states
    assert all(len(states[k]) == 3 for k in ("position", "velocity", "effort")), states


# --- the 3D lidar plugin over MJCF lidar sensors (mujoco_ros2_control's extension) -----------
LIDAR_ARM = """<mujoco model="arm">
  <extension>
    <plugin plugin="mujoco.plugin.lidar">
      <instance name="flat">
        <config key="resolution" value="{resolution}"/>
        <config key="azimuth_range" value="-0.2 0.2"/>
        <config key="elevation_range" value="0.0"/>
        <config key="max_range" value="10.0"/>
        <config key="update_rate" value="10"/>
      </instance>
    </plugin>
  </extension>
  <worldbody>
    <geom name="wall" type="box" size="0.1 5 5" pos="2.1 0 0"/>
    <body name="link">
      <joint name="j1" axis="0 0 1"/>
      <geom type="cylinder" size="0.05 0.05" mass="1"/>
      <site name="lidar_site" pos="0 0 0.2"/>
    </body>
  </worldbody>
  <actuator><position name="j1" joint="j1" kp="100"/></actuator>
  <sensor>
    <plugin name="scan2d" instance="flat" objtype="site" objname="lidar_site"/>
    <plugin name="cloud3d" plugin="mujoco.plugin.lidar" objtype="site" objname="lidar_site">
      <config key="resolution" value="4 3"/>
      <config key="azimuth_range" value="-0.3 0.3"/>
      <config key="elevation_range" value="-0.1 0.1"/>
      <config key="max_range" value="{reach}"/>
      <config key="update_rate" value="0"/>
    </plugin>
  </sensor>
</mujoco>
"""
LIDAR_PLUGIN = """/**:
  ros__parameters:
    mujoco_plugins:
      mujoco_3d_lidar_plugin:
        type: mujoco_ros2_control_plugins/Mujoco3dLidarPlugin
        scan2d:
          frame_name: lidar_frame
          topic: /flat_scan
"""


def lidar_node(ws, resolution: str = "5 1", reach: str = "10"):
    ws.own_bus()
    model = ws.write("arm.xml", LIDAR_ARM.replace("{resolution}", resolution)
                     .replace("{reach}", reach))
    plugins = ws.write("plugins.yaml", LIDAR_PLUGIN)
    return ws.start(*node_args(ws, robot(str(model)), str(plugins)), output="node.out")


def test_a_one_row_mjcf_lidar_is_a_laser_scan_of_the_wall(ws):
    proc = lidar_node(ws)
    try:
        ws.wait_for_output("Adding lidar sensor: 'scan2d'", 60, "node.out")
        scan = ws.run("topic", "echo", "/flat_scan", "sensor_msgs/msg/LaserScan", "--once",
                      timeout=30)
    finally:
        assert stop(proc) in (0, 130)
    assert scan.returncode == 0, scan.stderr
    assert "frame_id: lidar_frame" in scan.stdout, scan.stdout
    ranges = numbers(scan.stdout.split("ranges:")[1].split("intensities:")[0])
    expected = [2.0 / math.cos(a) for a in (-0.2, -0.1, 0.0, 0.1, 0.2)]
    assert ranges == pytest.approx(expected, abs=1e-4)


def cloud_points(ws, reach: str):
    import numpy as np

    proc = lidar_node(ws, reach=reach)
    try:
        ws.wait_for_output("Adding lidar sensor: 'cloud3d'", 60, "node.out")
        cloud = ws.run("topic", "echo", "/points", "sensor_msgs/msg/PointCloud2", "--once",
                       "--full-length", timeout=30)
    finally:
        assert stop(proc) in (0, 130)
    assert cloud.returncode == 0, cloud.stderr
    assert re.search(r"^height: 3$", cloud.stdout, re.M) and \
        re.search(r"^width: 4$", cloud.stdout, re.M), cloud.stdout[:500]
    raw = bytes(int(v) for v in numbers(cloud.stdout.split("data:")[1].split("is_dense")[0]))
    return np.frombuffer(raw, "<f4").reshape(3, 4, 3)


def test_a_several_row_mjcf_lidar_is_a_point_cloud_on_the_wall(ws):
    points = cloud_points(ws, "10")
    assert points[..., 0] == pytest.approx(2.0, abs=1e-4)  # every ray ends on the wall, x = 2
    low_row = [2.0 * math.tan(-0.1) / math.cos(a) for a in (-0.3, -0.1, 0.1, 0.3)]
    assert points[0, :, 2] == pytest.approx(low_row, abs=1e-4)  # elevation -0.1, azimuths


def test_a_point_cloud_is_nan_where_nothing_is_in_range(ws):
    import numpy as np

    assert np.isnan(cloud_points(ws, "1.5")).all()  # the wall is 2 m away


def test_a_wrong_lidar_setting_is_said_at_the_sensor_line_and_the_sim_runs_on(ws):
    proc = lidar_node(ws, resolution="5")
    try:
        out = ws.wait_for_output("Adding lidar sensor: 'cloud3d'", 60, "node.out")
        assert "arm.xml:23: lidar sensor 'scan2d': Both horizontal and vertical resolutions " \
               "must be specified" in out, out
        assert wait_until(lambda: sim_time(ws) > 0.0, 20)  # the sim runs, without that lidar
    finally:
        assert stop(proc) in (0, 130)


def test_its_mjcf_sensors_stay_with_its_hardware_not_on_topics_of_their_own(ws):
    ws.own_bus()
    model = ws.write("arm.xml", ARM.replace(
        '<geom type="box" size="0.1 0.1 0.5" pos="0 0 0.5"/>',
        '<geom type="box" size="0.1 0.1 0.5" pos="0 0 0.5"/><site name="imu"/>').replace(
        "</mujoco>", '<sensor><accelerometer name="acc" site="imu"/></sensor></mujoco>'))
    proc = ws.start(*node_args(ws, robot(str(model))), output="node.out")
    try:
        ws.wait_for_output("controller_manager at", 60, "node.out")
        assert wait_until(lambda: sim_time(ws) > 0.0, 20)
        listed = ws.run("topic", "list", timeout=30).stdout
    finally:
        assert stop(proc) in (0, 130)
    assert "/clock" in listed and "/imu/imu" not in listed, listed

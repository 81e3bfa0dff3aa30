"""ros2_control in the sim: gz_ros2_control_demos' launch files unchanged, every controller
through a real spawner against the real sim, `launcher control`, ros2_control_node with mock
hardware, and the bad inputs the issue lists. Real processes on a real router."""

from __future__ import annotations

import re
import time

import pytest

from tests.support.environment import shared
from tests.support.nodes import stop
from tests.support.robots import ARM, LINK, arm_links
from tests.support.waiting import wait_until

DEMOS = ("external", "gz_ros2_control_demos")


@pytest.fixture
def demos(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared(*DEMOS))
    return ws


def field(ws, topic: str, type_name: str, path: str) -> list[float]:
    done = ws.run("topic", "echo", topic, type_name, "--once", "--field", path, timeout=30)
    assert done.returncode == 0, done.stderr
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", done.stdout)]


def controllers(ws, *extra: str) -> str:
    done = ws.run("control", "list_controllers", *extra, timeout=30)
    assert done.returncode == 0, done.stderr
    return done.stdout


def cart_position(ws) -> float:
    return field(ws, "/joint_states", "sensor_msgs/msg/JointState", "position")[0]


def test_cart_example_position_runs_unchanged_and_follows_trajectories(demos):
    proc = demos.start("launch", "gz_ros2_control_demos", "cart_example_position.launch.py",
                       output="demo.out")
    try:
        demos.wait_for_output("Activating controllers: [ joint_trajectory_controller ]", 90,
                              "demo.out")
        listed = controllers(demos)
        assert re.search(r"joint_state_broadcaster\s+joint_state_broadcaster/"
                         r"JointStateBroadcaster\s+active", listed), listed
        assert re.search(r"joint_trajectory_controller\s+joint_trajectory_controller/"
                         r"JointTrajectoryController\s+active", listed), listed
        # the state interface's initial_value (5.0) placed the cart
        assert abs(cart_position(demos) - 5.0) < 0.05
        sent = demos.run("topic", "pub", "--once", "/joint_trajectory_controller/joint_trajectory",
                         "trajectory_msgs/msg/JointTrajectory",
                         "{joint_names: [slider_to_cart], points: [{positions: [1.0], "
                         "time_from_start: {sec: 1}}, {positions: [-2.0], time_from_start: "
                         "{sec: 2}}]}")
        assert sent.returncode == 0, sent.stderr
        assert wait_until(lambda: abs(cart_position(demos) + 2.0) < 0.02), cart_position(demos)
        goal = demos.run("action", "send_goal", "/joint_trajectory_controller/"
                         "follow_joint_trajectory", "control_msgs/action/FollowJointTrajectory",
                         "{trajectory: {joint_names: [slider_to_cart], points: [{positions: "
                         "[3.0], velocities: [0.0], time_from_start: {sec: 1}}]}}", timeout=60)
        assert goal.returncode == 0, goal.stderr
        assert "SUCCEEDED" in goal.stdout and "error_code: 0" in goal.stdout, goal.stdout
        assert abs(cart_position(demos) - 3.0) < 0.02
        # refused trajectories: the cart holds where it is
        for bad in ("{joint_names: [elbow], points: [{positions: [0.0], time_from_start: "
                    "{sec: 1}}]}",
                    "{joint_names: [slider_to_cart], points: [{positions: [0.0], "
                    "time_from_start: {sec: 2}}, {positions: [1.0], time_from_start: "
                    "{sec: 1}}]}",
                    "{joint_names: [slider_to_cart], points: [{positions: [.nan], "
                    "time_from_start: {sec: 1}}]}"):
            demos.run("topic", "pub", "--once", "/joint_trajectory_controller/joint_trajectory",
                      "trajectory_msgs/msg/JointTrajectory", bad)
        time.sleep(1.5)
        assert abs(cart_position(demos) - 3.0) < 0.02
        # a goal's own path tolerance, broken: aborted, and the cart stops where it is
        strict = demos.run("action", "send_goal", "/joint_trajectory_controller/"
                           "follow_joint_trajectory", "control_msgs/action/FollowJointTrajectory",
                           "{trajectory: {joint_names: [slider_to_cart], points: [{positions: "
                           "[-3.0], time_from_start: {sec: 1}}]}, path_tolerance: [{name: "
                           "slider_to_cart, position: 0.000001}]}", timeout=60)
        assert "ABORTED" in strict.stdout and "error_code: -4" in strict.stdout, strict.stdout
        assert cart_position(demos) > 2.0
        refused = demos.run("action", "send_goal", "/joint_trajectory_controller/"
                            "follow_joint_trajectory",
                            "control_msgs/action/FollowJointTrajectory",
                            "{trajectory: {joint_names: [elbow], points: [{positions: [1.0], "
                            "time_from_start: {sec: 1}}]}}", timeout=60)
        assert "rejected" in (refused.stdout + refused.stderr).lower(), refused
        out = demos.output("demo.out")
        assert "not controlled by this controller" in out
        assert "times must increase" in out and "NaN" in out
    finally:
        assert stop(proc) == 130


def test_diff_drive_example_runs_unchanged_and_twist_stamped_moves_odometry(demos):
    proc = demos.start("launch", "gz_ros2_control_demos", "diff_drive_example.launch.py",
                       output="demo.out")
    try:
        demos.wait_for_output("Activating controllers: [ diff_drive_base_controller ]", 90,
                              "demo.out")
        odom = "/diff_drive_base_controller/odom"
        start = field(demos, odom, "nav_msgs/msg/Odometry", "pose.pose.position.x")[0]
        sent = demos.run("topic", "pub", "-r", "20", "-t", "40",
                         "/diff_drive_base_controller/cmd_vel", "geometry_msgs/msg/TwistStamped",
                         "{twist: {linear: {x: 0.8}}}", timeout=30)
        assert sent.returncode == 0, sent.stderr
        moved = field(demos, odom, "nav_msgs/msg/Odometry", "pose.pose.position.x")[0]
        assert moved > start + 0.8, (start, moved)
        def odom_on_tf() -> bool:  # robot_state_publisher's wheel transforms share /tf
            tf = demos.run("topic", "echo", "/tf", "tf2_msgs/msg/TFMessage", "--once")
            return "frame_id: odom" in tf.stdout and "child_frame_id: chassis" in tf.stdout

        assert wait_until(odom_on_tf, every=0.0)
        # cmd_vel_timeout (0.5 s): without commands the robot stops
        time.sleep(1.5)
        still = field(demos, odom, "nav_msgs/msg/Odometry", "twist.twist.linear.x")[0]
        assert abs(still) < 0.05, still
        rest = field(demos, odom, "nav_msgs/msg/Odometry", "pose.pose.position.x")[0]
        demos.run("topic", "pub", "--once", "/diff_drive_base_controller/cmd_vel",
                  "geometry_msgs/msg/TwistStamped", "{twist: {linear: {x: .inf}}}")
        time.sleep(0.5)
        assert "NaN or an infinite value" in demos.output("demo.out")
        after = field(demos, odom, "nav_msgs/msg/Odometry", "pose.pose.position.x")  # sane
        assert after and abs(after[0] - rest) < 0.01, (rest, after)
    finally:
        assert stop(proc) == 130


EFFORT_BLOCK = """effort_group:
  ros__parameters:
    joints: [j4]
"""
ARM_YAML = """
controller_manager:
  ros__parameters:
    update_rate: 500
    joint_state_broadcaster: {type: joint_state_broadcaster/JointStateBroadcaster}
    arm_controller: {type: joint_trajectory_controller/JointTrajectoryController}
    forward: {type: forward_command_controller/ForwardCommandController}
    position_group: {type: position_controllers/JointGroupPositionController}
    velocity_group: {type: velocity_controllers/JointGroupVelocityController}
    effort_group: {type: effort_controllers/JointGroupEffortController}
    few_states: {type: joint_state_broadcaster/JointStateBroadcaster}
    no_such_joint: {type: position_controllers/JointGroupPositionController}
    typo_type: {type: joint_trajectory_controler/JointTrajectoryController}
    bad_rate: {type: joint_trajectory_controller/JointTrajectoryController}
bad_rate:
  ros__parameters:
    joints: [j1, j2]
    command_interfaces: [position]
    state_interfaces: [position]
    action_monitor_rate: fast
arm_controller:
  ros__parameters:
    joints: [j1, j2]
    command_interfaces: [position]
    state_interfaces: [position, velocity]
forward:
  ros__parameters:
    joints: [j1]
    interface_name: position
position_group:
  ros__parameters:
    joints: [j2]
velocity_group:
  ros__parameters:
    joints: [j3]
few_states:
  ros__parameters:
    joints: [j1]
    interfaces: [position]
    use_local_topics: true
no_such_joint:
  ros__parameters:
    joints: [elbow]
untyped:
  ros__parameters:
    joints: [j1]
"""


@pytest.fixture
def arm(ws):
    ws.own_bus()
    yaml = ws.write("arm_controllers.yaml", ARM_YAML)
    # a second <parameters> file: effort_group's parameters are only there
    effort = ws.write("arm_effort.yaml", f"""
    {EFFORT_BLOCK.replace(chr(10), chr(10) + "    ")}""")
    links = arm_links(4)
    ws.write("arm.urdf", ARM.format(links=links, yaml=f"{yaml}</parameters><parameters>{effort}"))
    proc = ws.start("gz", "sim", "-r", "-s", "-v", "3", "empty.sdf", output="sim.out")
    ws.wait_for_output("running", 60, "sim.out")
    spawned = ws.run("run", "ros_gz_sim", "create", "-file", "arm.urdf", "-name", "arm")
    assert spawned.returncode == 0, spawned.stderr
    ws.wait_for_output("controller_manager of entity 'arm'", 30, "sim.out")
    yield ws
    assert stop(proc) in (0, 130)


def spawner(ws, *args: str):
    return ws.run("run", "controller_manager", "spawner", *args, timeout=60)


def joint(ws, name: str, kind: str = "position") -> float:
    message = ws.run("topic", "echo", "/joint_states", "sensor_msgs/msg/JointState", "--once",
                     timeout=30).stdout
    order = re.search(r"name:\n((?:- .*\n)+)", message).group(1).split("\n")
    joints = [line[2:] for line in order if line]
    values = re.search(rf"{kind}:\n((?:- .*\n)+)", message).group(1).split("\n")
    return float(values[joints.index(name)][2:])


def test_every_controller_through_a_real_spawner_against_the_sim(arm):
    assert spawner(arm, "joint_state_broadcaster").returncode == 0
    listed = arm.run("topic", "echo", "/joint_states", "sensor_msgs/msg/JointState", "--once",
                     timeout=30).stdout
    assert all(f"- j{n}" in listed for n in range(1, 5)), listed
    dynamic = arm.run("topic", "echo", "/dynamic_joint_states",
                      "control_msgs/msg/DynamicJointState", "--once", timeout=30).stdout
    assert "- effort" in dynamic and "- j4" in dynamic, dynamic
    # joints/interfaces filters and local topics
    assert spawner(arm, "few_states").returncode == 0
    few = arm.run("topic", "echo", "/few_states/joint_states", "sensor_msgs/msg/JointState",
                  "--once", timeout=30).stdout
    assert "- j1" in few and "- j2" not in few, few
    # the trajectory controller and the JointGroup controllers, all at once
    done = spawner(arm, "arm_controller", "velocity_group", "effort_group",
                   "--activate-as-group")
    assert done.returncode == 0, done.stderr
    arm.run("topic", "pub", "--once", "/arm_controller/joint_trajectory",
            "trajectory_msgs/msg/JointTrajectory",
            "{joint_names: [j2, j1], points: [{positions: [-0.4, 0.8], velocities: [0, 0], "
            "time_from_start: {sec: 1}}]}")
    arm.run("topic", "pub", "--once", "/velocity_group/commands",
            "std_msgs/msg/Float64MultiArray", "{data: [0.5]}")
    assert wait_until(lambda: abs(joint(arm, "j1") - 0.8) < 0.02 and
                      abs(joint(arm, "j2") + 0.4) < 0.02)
    assert abs(joint(arm, "j3", "velocity") - 0.5) < 0.05
    before = joint(arm, "j4", "velocity")
    arm.run("topic", "pub", "--once", "/effort_group/commands",
            "std_msgs/msg/Float64MultiArray", "{data: [2.0]}")
    assert wait_until(lambda: joint(arm, "j4", "velocity") > before + 0.5)
    # a wrong-sized or NaN command is refused
    arm.run("topic", "pub", "--once", "/velocity_group/commands",
            "std_msgs/msg/Float64MultiArray", "{data: [0.1, 0.2]}")
    arm.run("topic", "pub", "--once", "/velocity_group/commands",
            "std_msgs/msg/Float64MultiArray", "{data: [.nan]}")
    time.sleep(0.5)
    assert abs(joint(arm, "j3", "velocity") - 0.5) < 0.05
    out = arm.output("sim.out")
    assert "command size (2) does not match number of interfaces (1)" in out
    assert "NaN or an infinite value" in out
    # two controllers claiming j1/position: refused, the running one keeps running
    refused = spawner(arm, "forward")
    assert refused.returncode == 1
    assert "currently claimed by another controller ('arm_controller')" in \
        refused.stdout + refused.stderr
    assert re.search(r"arm_controller\s+\S+\s+active", controllers(arm))
    assert re.search(r"forward\s+\S+\s+inactive", controllers(arm))
    loaded = arm.run("control", "load_controller", "position_group", "--set-state", "inactive")
    assert loaded.returncode == 0, loaded.stderr
    assert "Successfully loaded controller position_group into state inactive" in loaded.stdout
    # switch: arm_controller out, forward and position_group in, in one step
    switched = arm.run("control", "switch_controllers", "--deactivate", "arm_controller",
                       "--activate", "forward", "position_group", "--strict")
    assert switched.returncode == 0, switched.stderr
    arm.run("topic", "pub", "--once", "/forward/commands", "std_msgs/msg/Float64MultiArray",
            "{data: [5.0]}")  # beyond the interface's max (2): clamped
    arm.run("topic", "pub", "--once", "/position_group/commands",
            "std_msgs/msg/Float64MultiArray", "{data: [0.3]}")
    assert wait_until(lambda: abs(joint(arm, "j1") - 2.0) < 0.03 and
                      abs(joint(arm, "j2") - 0.3) < 0.03), (joint(arm, "j1"), joint(arm, "j2"))
    interfaces = arm.run("control", "list_hardware_interfaces").stdout
    assert "\tj1/position [available] [claimed]" in interfaces, interfaces
    assert "\tj3/velocity [available] [claimed]" in interfaces
    verbose = controllers(arm, "-v")
    assert "\tclaimed interfaces:\n\t\tj2/position" in verbose, verbose
    components = arm.run("control", "list_hardware_components").stdout
    assert "name: ArmSystem" in components and "gz_ros2_control/GazeboSimSystem" in components
    types = arm.run("control", "list_controller_types").stdout
    assert "diff_drive_controller/DiffDriveController" in types
    # lifecycle through launcher control: deactivate, clean up, configure, activate
    for state, said in (("inactive", "Successfully deactivated position_group"),
                        ("unconfigured", "successfully cleaned up position_group"),
                        ("inactive", "Successfully configured position_group"),
                        ("active", "Successfully activated position_group")):
        changed = arm.run("control", "set_controller_state", "position_group", state)
        assert changed.returncode == 0 and said in changed.stdout, changed.stdout + changed.stderr
    wrong = arm.run("control", "set_controller_state", "nothing_here", "active")
    assert wrong.returncode == 1 and "does not seem to be loaded" in wrong.stderr
    # the hardware component taken down stops the controllers on it; back up, they can start
    down = arm.run("control", "set_hardware_component_state", "ArmSystem", "inactive")
    assert down.returncode == 0, down.stderr
    assert not re.search(r"position_group\s+\S+\s+active", controllers(arm))
    assert "[unavailable]" in arm.run("control", "list_hardware_interfaces").stdout
    assert arm.run("control", "set_hardware_component_state", "ArmSystem",
                   "active").returncode == 0
    assert arm.run("control", "switch_controllers", "--activate", "position_group",
                   "velocity_group").returncode == 0
    # unspawner: deactivated and unloaded
    gone = arm.run("run", "controller_manager", "unspawner", "velocity_group")
    assert gone.returncode == 0, gone.stderr
    assert "velocity_group" not in controllers(arm)
    # --inactive: loaded and configured, not started; unload_controller takes it away
    inactive = spawner(arm, "velocity_group", "--inactive")
    assert inactive.returncode == 0, inactive.stderr
    assert re.search(r"velocity_group\s+\S+\s+inactive", controllers(arm))
    unloaded = arm.run("control", "unload_controller", "velocity_group")
    assert unloaded.returncode == 0 and "Successfully unloaded" in unloaded.stdout
    drawn = arm.run("control", "view_controller_chains")
    assert drawn.returncode == 0, drawn.stderr
    assert (arm.root / "controller_diagram.gv.pdf").stat().st_size > 0


def test_bad_controller_configurations_are_refused_with_where_and_why(arm):
    yaml = str(arm.root / "arm_controllers.yaml")
    # not in the YAML at all: spawner.py's message, non-zero exit
    missing = spawner(arm, "nonexistent_controller")
    assert missing.returncode == 1
    assert "Failed loading controller nonexistent_controller" in missing.stderr + missing.stdout
    # a block with no type
    untyped = spawner(arm, "untyped")
    assert untyped.returncode == 1
    out = arm.wait_for_output("The 'type' param was not defined for 'untyped'", 10, "sim.out")
    assert re.search(rf"{re.escape(yaml)}:\d+: The 'type' param", out), out
    # an unknown type: the known ones, and the likely one
    typo = spawner(arm, "typo_type")
    assert typo.returncode == 1
    out = arm.wait_for_output("Loader for controller 'typo_type'", 10, "sim.out")
    assert "did you mean 'joint_trajectory_controller/JointTrajectoryController'" in out
    assert re.search(rf"{re.escape(yaml)}:\d+: Loader", out), out
    # a joint the hardware does not have
    elbow = spawner(arm, "no_such_joint")
    assert elbow.returncode == 1
    text = elbow.stdout + elbow.stderr
    assert "command interface 'elbow/position' is not available" in text, text
    assert "j1/position" in text  # what the hardware exports
    lines = (arm.root / "arm_controllers.yaml").read_text().splitlines()
    row = lines.index("    joints: [elbow]") + 1  # the joint the hardware lacks, where it is named
    column = lines[row - 1].index("elbow") + 1
    assert f"{yaml}:{row}:{column}: Unable to activate controller 'no_such_joint'" in text, text
    # nothing above left a controller active
    assert not re.search(r"\sactive", controllers(arm))


def test_a_controller_parameter_of_the_wrong_type_is_refused_at_its_line(arm):
    yaml = str(arm.root / "arm_controllers.yaml")
    assert spawner(arm, "bad_rate").returncode == 1
    out = arm.wait_for_output("parameter 'action_monitor_rate': expected", 10, "sim.out")
    lines = (arm.root / "arm_controllers.yaml").read_text().splitlines()
    row = lines.index("    action_monitor_rate: fast") + 1
    assert f"{yaml}:{row}: /bad_rate: parameter 'action_monitor_rate': expected a number, " \
           f"got 'fast'" in out, out


def test_a_controllers_parameters_are_listed_with_defaults_and_described(arm):
    assert spawner(arm, "arm_controller").returncode == 0
    listed = arm.run("param", "list", "/arm_controller").stdout
    assert "allow_partial_joints_goal" in listed and "gains.j2.ff_velocity_scale" in listed
    described = arm.run("param", "describe", "/arm_controller", "action_monitor_rate").stdout
    assert "Type: double" in described and "Description: goal checks a second" in described
    assert "Min value: 0.1" in described and "Read only: true" in described, described


def test_a_read_only_controller_parameter_is_refused_as_rclcpp_refuses_it(arm):
    assert spawner(arm, "arm_controller").returncode == 0
    refused = arm.run("param", "set", "/arm_controller", "joints", "[j1]").stdout
    assert "Setting parameter failed: parameter 'joints' cannot be set because it is " \
           "read-only" in refused, refused
    assert "j2" in arm.run("param", "get", "/arm_controller", "joints").stdout


def test_an_unknown_hardware_plugin_is_refused_at_its_line(ws):
    ws.own_bus()
    yaml = ws.write("c.yaml", "controller_manager:\n  ros__parameters:\n    update_rate: 100\n")
    links = LINK.format(n=1, parent="base")
    text = ARM.format(links=links, yaml=yaml).replace(
        "gz_ros2_control/GazeboSimSystem", "my_robot_hardware/RealArm")
    path = ws.write("bad.urdf", text)
    line = text.splitlines().index('  <ros2_control name="ArmSystem" type="system">') + 1
    proc = ws.start("gz", "sim", "-r", "-s", "-v", "3", "empty.sdf", output="sim.out")
    try:
        ws.wait_for_output("running", 60, "sim.out")
        spawned = ws.run("run", "ros_gz_sim", "create", "-file", str(path), "-name", "arm")
        assert spawned.returncode != 0
        message = spawned.stderr + ws.output("sim.out")
        assert f"bad.urdf:{line}: <ros2_control name=\"ArmSystem\">: unknown hardware " \
               f"plugin 'my_robot_hardware/RealArm'" in message, message
        assert "mock_components/GenericSystem" in message
        assert "Traceback" not in message
    finally:
        assert stop(proc) in (0, 130)


def test_ros2_control_node_runs_the_manager_on_mock_hardware(ws):
    ws.own_bus()
    yaml = ws.write("arm_controllers.yaml", ARM_YAML)
    links = arm_links(4)
    ws.write("arm.urdf", ARM.format(links=links, yaml=yaml).replace(
        "gz_ros2_control/GazeboSimSystem", "mock_components/GenericSystem"))
    ws.write("mock.launch.yaml", f"""
    launch:
      - node:
          pkg: robot_state_publisher
          exec: robot_state_publisher
          param: [{{name: robot_description, value: "$(command 'cat arm.urdf')"}}]
      - node:
          pkg: controller_manager
          exec: ros2_control_node
          output: screen
          param: [{{from: {yaml}}}]
    """)
    proc = ws.start("launch", "mock.launch.yaml", output="mock.out")
    try:
        ws.wait_for_output("Received robot description from topic.", 60, "mock.out")
        assert spawner(ws, "joint_state_broadcaster").returncode == 0
        done = spawner(ws, "arm_controller")
        assert done.returncode == 0, done.stderr
        ws.run("topic", "pub", "--once", "/arm_controller/joint_trajectory",
               "trajectory_msgs/msg/JointTrajectory",
               "{joint_names: [j1, j2], points: [{positions: [0.5, -0.5], "
               "time_from_start: {sec: 1}}]}")
        # mock hardware: the state follows the command exactly
        assert wait_until(lambda: joint(ws, "j1") == 0.5 and joint(ws, "j2") == -0.5)
        assert "runs as mock_components/GenericSystem" not in ws.output("mock.out")
    finally:
        assert stop(proc) == 130


def wheel(name: str, parent: str, xyz: str, kind: str = "continuous", radius: float = 0.15,
          axis: str = "0 0 1", rpy: str = "-1.5707963 0 0") -> str:
    return f"""<link name="{name}"><collision><geometry><sphere radius="{radius}"/></geometry>
  </collision><inertial><mass value="0.5"/><inertia ixx="0.005" iyy="0.005" izz="0.005"
  ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="{name}_joint" type="{kind}"><parent link="{parent}"/><child link="{name}"/>
  <origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="{axis}"/>
  <limit lower="-0.8" upper="0.8" effort="50" velocity="5"/></joint>"""


def pivot(name: str, xyz: str) -> str:
    """A steering knuckle: a small body turning about z."""
    return f"""<link name="{name}"><inertial><mass value="0.2"/><inertia ixx="0.001"
  iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="{name}_joint" type="revolute"><parent link="chassis"/><child link="{name}"/>
  <origin xyz="{xyz}"/><axis xyz="0 0 1"/>
  <limit lower="-0.8" upper="0.8" effort="50" velocity="5"/></joint>"""


def base(name: str, parts: str, control: str, yaml: str) -> str:
    return f"""<?xml version="1.0"?><robot name="{name}">
  <link name="chassis"><collision><origin xyz="0 0 0.4"/><geometry><box size="1.2 0.6 0.1"/>
  </geometry></collision><inertial><origin xyz="0 0 0.25"/><mass value="4"/><inertia
  ixx="0.2" iyy="0.5" izz="0.6" ixy="0" ixz="0" iyz="0"/></inertial></link>
  {parts}
  <ros2_control name="{name}_hw" type="system"><hardware>
  <plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>{control}</ros2_control>
  <gazebo><plugin filename="ign_ros2_control-system"
  name="ign_ros2_control::IgnitionROS2ControlPlugin"><parameters>{yaml}</parameters>
  <ros><namespace>{name}</namespace></ros></plugin></gazebo></robot>"""


def joint_block(name: str, command: str, *states: str) -> str:
    return f'<joint name="{name}"><command_interface name="{command}"/>' + "".join(
        f'<state_interface name="{s}"/>' for s in states) + "</joint>"


def test_steered_bases_grippers_and_sensor_broadcasters_in_the_sim(ws):
    ws.own_bus()
    tri_yaml = ws.write("tricycle.yaml", """
    /tricycle/controller_manager:
      ros__parameters:
        update_rate: 100
        tricycle_controller: {type: tricycle_controller/TricycleController}
    /tricycle/tricycle_controller:
      ros__parameters:
        traction_joint_name: front_wheel_joint
        steering_joint_name: knuckle_joint
        wheel_radius: 0.15
        wheelbase: 0.8
        base_frame_id: chassis
    """)
    tricycle = base("tricycle", pivot("knuckle", "0.4 0 0.15")
                    + wheel("front_wheel", "knuckle", "0 0 0")
                    + wheel("left_rear", "chassis", "-0.4 0.35 0.15")
                    + wheel("right_rear", "chassis", "-0.4 -0.35 0.15"),
                    joint_block("front_wheel_joint", "velocity", "velocity", "position")
                    + joint_block("knuckle_joint", "position", "position"), tri_yaml)
    ack_yaml = ws.write("ackermann.yaml", """
    /car/controller_manager:
      ros__parameters:
        update_rate: 100
        ackermann: {type: ackermann_steering_controller/AckermannSteeringController}
    /car/ackermann:
      ros__parameters:
        rear_wheels_names: [left_rear_joint, right_rear_joint]
        front_wheels_names: [left_knuckle_joint, right_knuckle_joint]
        wheelbase: 0.8
        front_wheel_track: 0.7
        rear_wheel_track: 0.7
        front_wheels_radius: 0.15
        rear_wheels_radius: 0.15
        base_frame_id: chassis
    """)
    car = base("car", pivot("left_knuckle", "0.4 0.35 0.15") + pivot("right_knuckle",
                                                                      "0.4 -0.35 0.15")
               + wheel("left_front", "left_knuckle", "0 0 0")
               + wheel("right_front", "right_knuckle", "0 0 0")
               + wheel("left_rear", "chassis", "-0.4 0.35 0.15")
               + wheel("right_rear", "chassis", "-0.4 -0.35 0.15"),
               joint_block("left_rear_joint", "velocity", "velocity", "position")
               + joint_block("right_rear_joint", "velocity", "velocity", "position")
               + joint_block("left_knuckle_joint", "position", "position")
               + joint_block("right_knuckle_joint", "position", "position"), ack_yaml)
    hand_yaml = ws.write("hand.yaml", """
    /hand/controller_manager:
      ros__parameters:
        update_rate: 200
        gripper: {type: position_controllers/GripperActionController}
        parallel: {type: parallel_gripper_action_controller/GripperActionController}
        imu: {type: imu_sensor_broadcaster/IMUSensorBroadcaster}
        wrench: {type: force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster}
        states: {type: joint_state_broadcaster/JointStateBroadcaster}
    /hand/gripper:
      ros__parameters: {joint: finger_a_joint}
    /hand/parallel:
      ros__parameters: {joint: finger_b_joint}
    /hand/imu:
      ros__parameters: {sensor_name: palm_imu, frame_id: palm}
    /hand/wrench:
      ros__parameters: {sensor_name: wrist_ft, frame_id: palm}
    """)
    finger = """<link name="finger_{s}"><inertial><mass value="0.1"/><inertia ixx="0.001"
      iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
      <joint name="finger_{s}_joint" type="prismatic"><parent link="palm"/>
      <child link="finger_{s}"/><axis xyz="0 1 0"/>
      <limit lower="0" upper="0.05" effort="20" velocity="0.5"/></joint>"""
    imu = [f"orientation.{a}" for a in "xyzw"] + [f"angular_velocity.{a}" for a in "xyz"] + \
        [f"linear_acceleration.{a}" for a in "xyz"]
    ft = [f"{p}.{a}" for p in ("force", "torque") for a in "xyz"]
    hand = f"""<?xml version="1.0"?><robot name="hand"><link name="world"/>
      <link name="palm"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01"
      ixy="0" ixz="0" iyz="0"/></inertial></link>
      <joint name="wrist" type="fixed"><parent link="world"/><child link="palm"/>
      <origin xyz="0 0 1"/></joint>
      {finger.format(s="a")}{finger.format(s="b")}
      {finger.format(s="c").replace('velocity="0.5"/>',
                                    'velocity="0.5"/><mimic joint="finger_a_joint"/>')}
      <gazebo reference="palm"><sensor name="palm_imu" type="imu">
        <update_rate>100</update_rate></sensor></gazebo>
      <gazebo reference="finger_a_joint"><sensor name="wrist_ft" type="force_torque">
        <update_rate>100</update_rate></sensor></gazebo>
      <ros2_control name="hand_hw" type="system"><hardware>
      <plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
      {joint_block("finger_a_joint", "position", "position", "velocity")}
      {joint_block("finger_b_joint", "position", "position", "velocity")}
      <joint name="finger_c_joint"><state_interface name="position"/></joint>
      <sensor name="palm_imu">{"".join(f'<state_interface name="{i}"/>' for i in imu)}</sensor>
      <sensor name="wrist_ft">{"".join(f'<state_interface name="{i}"/>' for i in ft)}</sensor>
      </ros2_control>
      <gazebo><plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">
      <parameters>{hand_yaml}</parameters><ros><namespace>/hand</namespace></ros></plugin>
      </gazebo></robot>"""
    for name, text in (("tricycle", tricycle), ("car", car), ("hand", hand)):
        ws.write(f"{name}.urdf", text)
    proc = ws.start("gz", "sim", "-r", "-s", "-v", "3", "empty.sdf", output="sim.out")
    try:
        ws.wait_for_output("running", 60, "sim.out")
        for name, y in (("tricycle", "0"), ("car", "5"), ("hand", "-5")):
            done = ws.run("run", "ros_gz_sim", "create", "-file", f"{name}.urdf", "-name", name,
                          "-y", y, "-z", "0.02")
            assert done.returncode == 0, done.stderr
        for manager, names in (("/tricycle/controller_manager", ["tricycle_controller"]),
                               ("/car/controller_manager", ["ackermann"]),
                               ("/hand/controller_manager",
                                ["gripper", "parallel", "imu", "wrench", "states"])):
            done = spawner(ws, *names, "-c", manager)
            assert done.returncode == 0, done.stdout + done.stderr
        # the sensors, through their broadcasters
        imu_out = field(ws, "/hand/imu/imu", "sensor_msgs/msg/Imu", "linear_acceleration.z")
        assert imu_out[0] == pytest.approx(9.8, abs=0.3)
        frame = ws.run("topic", "echo", "/hand/imu/imu", "sensor_msgs/msg/Imu", "--once",
                       "--field", "header.frame_id").stdout
        assert "palm" in frame
        force = field(ws, "/hand/wrench/wrench", "geometry_msgs/msg/WrenchStamped",
                      "wrench.force")
        assert len(force) == 3 and any(abs(v) > 0.1 for v in force), force  # holds the finger
        # grippers: GripperCommand and ParallelGripperCommand goals
        goal = ws.run("action", "send_goal", "/hand/gripper/gripper_cmd",
                      "control_msgs/action/GripperCommand",
                      "{command: {position: 0.03, max_effort: 10.0}}", timeout=60)
        assert "SUCCEEDED" in goal.stdout and "reached_goal: true" in goal.stdout, goal.stdout
        # finger c mimics finger a (<mimic> in the URDF), as gz_ros2_control makes it
        hand_states = ws.run("topic", "echo", "/hand/joint_states", "sensor_msgs/msg/JointState",
                             "--once").stdout
        names = re.findall(r"^- (finger_\w+)", hand_states, re.M)
        positions = [float(v) for v in re.search(r"position:\n((?:- .*\n)+)",
                                                 hand_states).group(1).replace("- ", "").split()]
        mimic = dict(zip(names, positions, strict=True))
        assert mimic["finger_c_joint"] == pytest.approx(mimic["finger_a_joint"], abs=0.003)
        assert mimic["finger_a_joint"] == pytest.approx(0.03, abs=0.011)
        goal = ws.run("action", "send_goal", "/hand/parallel/gripper_cmd",
                      "control_msgs/action/ParallelGripperCommand",
                      "{command: {name: [finger_b_joint], position: [0.02]}}", timeout=60)
        assert "SUCCEEDED" in goal.stdout and "reached_goal: true" in goal.stdout, goal.stdout
        refused = ws.run("action", "send_goal", "/hand/gripper/gripper_cmd",
                         "control_msgs/action/GripperCommand",
                         "{command: {position: .nan}}", timeout=60)
        assert "rejected" in (refused.stdout + refused.stderr).lower()
        # the tricycle and the car drive forward and turn left
        for topic, command, odom in (
                ("/tricycle/tricycle_controller/cmd_vel", "geometry_msgs/msg/TwistStamped",
                 "/tricycle/tricycle_controller/odom"),
                ("/car/ackermann/reference", "geometry_msgs/msg/TwistStamped",
                 "/car/ackermann/odometry")):
            sent = ws.run("topic", "pub", "-r", "20", "-t", "40", topic, command,
                          "{twist: {linear: {x: 0.6}, angular: {z: 0.3}}}", timeout=30)
            assert sent.returncode == 0, sent.stderr
            x, y = field(ws, odom, "nav_msgs/msg/Odometry", "pose.pose.position")[:2]
            assert x > 0.5 and y > 0.05, (odom, x, y)
    finally:
        assert stop(proc) in (0, 130)

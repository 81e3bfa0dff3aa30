"""ros_gz_sim_demos' other demos as a user's project has them: sdf_parser (a model SDF fed to
robot_state_publisher and merged into a world by `package://`), robot_description_publisher
(create from the description topic with a pose) and gz-sim's joint position controller world
behind the bridge. The files are the test's own text, shaped as the upstream ones; real
processes (the sim, the bridge, robot_state_publisher, the CLI) on a real router."""

from __future__ import annotations

import math
import re
import signal
import time

import pytest

PACKAGE = """<?xml version="1.0"?><package format="3"><name>rover_demos</name>
<version>0.0.0</version><description>demos</description>
<maintainer email="m@example.com">m</maintainer><license>Apache-2.0</license></package>
"""

MODEL_CONFIG = """<?xml version="1.0"?>
<model><name>rover</name><version>1.0</version><sdf version="1.8">model.sdf</sdf></model>
"""

WHEEL = """
    <link name="{side}_wheel">
      <pose>0.5 {y} 0.3 -1.5707 0 0</pose>
      <inertial><mass>2</mass><inertia><ixx>0.15</ixx><iyy>0.15</iyy><izz>0.12</izz></inertia>
      </inertial>
      <collision name="collision_{side}_wheel"><geometry><sphere><radius>0.3</radius></sphere>
      </geometry></collision>
    </link>
    <joint name="{side}_wheel_joint" type="revolute">
      <parent>chassis</parent><child>{side}_wheel</child>
      <axis><xyz>0 0 1</xyz><limit><lower>-1.79769e+308</lower><upper>1.79769e+308</upper>
      </limit></axis>
    </joint>"""

# a model as sdformat_urdf reads it: its links, two wheels, a ball-jointed caster, a DiffDrive
MODEL_SDF = f"""<?xml version="1.0" ?>
<sdf version="1.8">
  <model name="rover">
    <link name="chassis">
      <pose>-0.15 0 0.4 0 0 0</pose>
      <inertial><mass>1.2</mass><inertia><ixx>0.13</ixx><iyy>0.42</iyy><izz>0.48</izz>
      </inertia></inertial>
      <collision name="collision_chassis"><geometry><box><size>2 1 0.5</size></box></geometry>
      </collision>
    </link>
    {WHEEL.format(side="left", y=0.625)}
    {WHEEL.format(side="right", y=-0.625)}
    <link name="caster">
      <pose>-0.95 0 0.2 0 0 0</pose>
      <inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia>
      </inertial>
      <collision name="collision_caster"><geometry><sphere><radius>0.2</radius></sphere>
      </geometry></collision>
    </link>
    <joint name="caster_wheel" type="ball"><parent>chassis</parent><child>caster</child></joint>
    <plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">
      <left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint</right_joint>
      <wheel_separation>1.25</wheel_separation><wheel_radius>0.3</wheel_radius>
      <odom_publish_frequency>1</odom_publish_frequency>
    </plugin>
  </model>
</sdf>
"""

# the world merges the model in by package:// and adds the state publishers to it
ROVER_WORLD = """<?xml version="1.0" ?>
<sdf version="1.8">
  <world name="demo">
    <model name="ground_plane"><static>true</static><link name="link">
      <collision name="collision"><geometry><plane><normal>0 0 1</normal><size>100 100</size>
      </plane></geometry></collision></link></model>
    <model name="rover">
      <self_collide>true</self_collide>
      <pose>0 0 0 0 0 0</pose>
      <include merge="true"><uri>package://rover_demos/models/rover</uri></include>
      <plugin filename="gz-sim-joint-state-publisher-system"
              name="gz::sim::systems::JointStatePublisher"/>
      <plugin filename="gz-sim-pose-publisher-system" name="gz::sim::systems::PosePublisher">
        <publish_link_pose>true</publish_link_pose>
        <use_pose_vector_msg>true</use_pose_vector_msg>
        <static_publisher>true</static_publisher>
        <static_update_frequency>1</static_update_frequency>
      </plugin>
      <plugin filename="gz-sim-odometry-publisher-system"
              name="gz::sim::systems::OdometryPublisher">
        <odom_frame>rover/odom</odom_frame><robot_base_frame>rover</robot_base_frame>
      </plugin>
    </model>
  </world>
</sdf>
"""

# sdf_parser.launch.py's shape: the world without -r (Gazebo opens it paused), the bridge
# of the state topics remapped to /joint_states and /tf, robot_state_publisher fed the SDF
SDF_PARSER_LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    demos = get_package_share_directory('rover_demos')
    with open(os.path.join(demos, 'models', 'rover', 'model.sdf')) as infp:
        robot_desc = infp.read()
    gazebo = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('ros_gz_sim'), 'launch', 'gz_sim.launch.py')),
        launch_arguments={'gz_args': PathJoinSubstitution([demos, 'worlds', 'rover.sdf'])
                          }.items())
    joint_state = '/world/demo/model/rover/joint_state'
    bridge = Node(
        package='ros_gz_bridge', executable='parameter_bridge',
        arguments=['/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock',
                   joint_state + '@sensor_msgs/msg/JointState[gz.msgs.Model',
                   '/model/rover/pose@tf2_msgs/msg/TFMessage[gz.msgs.Pose_V',
                   '/model/rover/pose_static@tf2_msgs/msg/TFMessage[gz.msgs.Pose_V',
                   '/model/rover/cmd_vel@geometry_msgs/msg/Twist@gz.msgs.Twist',
                   '/model/rover/odometry@nav_msgs/msg/Odometry@gz.msgs.Odometry'],
        remappings=[(joint_state, 'joint_states'), ('/model/rover/pose', '/tf'),
                    ('/model/rover/pose_static', '/tf_static')],
        parameters=[{'qos_overrides./tf_static.publisher.durability': 'transient_local'}],
        output='screen')
    robot_state_publisher = Node(
        package='robot_state_publisher', executable='robot_state_publisher',
        name='robot_state_publisher', output='both',
        parameters=[{'use_sim_time': True}, {'robot_description': robot_desc}])
    return LaunchDescription([gazebo, bridge, robot_state_publisher])
"""

# robot_description_publisher.launch.py's shape: a sphere's URDF to robot_state_publisher, an
# empty world running, and create taking the description from its topic, posed by parameters
# (the upstream's) and by flags from a string (the older upstream's form)
SPHERE_URDF = ('<?xml version="1.0" ?><robot name="will_be_ignored"><link name="link">'
               '<visual><geometry><sphere radius="1.0"/></geometry></visual>'
               '<collision><geometry><sphere radius="1.0"/></geometry></collision>'
               '<inertial><mass value="1"/><inertia ixx="1" ixy="0.0" ixz="0.0" iyy="1" '
               'iyz="0.0" izz="1"/></inertial></link></robot>')
DESCRIPTION_LAUNCH = f"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    robot_desc = '{SPHERE_URDF}'
    robot_state_publisher = Node(
        package='robot_state_publisher', executable='robot_state_publisher',
        name='robot_state_publisher', output='screen',
        parameters=[{{'use_sim_time': True, 'robot_description': robot_desc}}])
    gazebo = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('ros_gz_sim'), 'launch', 'gz_sim.launch.py')),
        launch_arguments={{'gz_args': '-r empty.sdf'}}.items())
    spawn = Node(package='ros_gz_sim', executable='create', output='screen',
                 parameters=[{{'name': 'my_custom_model', 'x': 1.2, 'z': 2.3,
                              'Y': LaunchConfiguration('Y'), 'topic': '/robot_description'}}])
    flags = Node(package='ros_gz_sim', executable='create', output='screen',
                 arguments=['-name', 'by_flags', '-string', robot_desc, '-x', '-3', '-y', '4',
                            '-z', '1', '-R', '0', '-P', '0', '-Y', LaunchConfiguration('Y')])
    return LaunchDescription([DeclareLaunchArgument('Y', default_value='3.4'), gazebo,
                              robot_state_publisher, spawn, flags])
"""

# gz-sim's joint position controller world: a rotor on a base held to the world by a fixed
# joint (the model is not static: its rotor turns), and here a static ground beside it
JPC_WORLD = """<?xml version="1.0" ?>
<sdf version="1.6">
  <world name="default">
    <plugin filename="gz-sim-physics-system" name="gz::sim::systems::Physics"/>
    <plugin filename="gz-sim-scene-broadcaster-system"
            name="gz::sim::systems::SceneBroadcaster"/>
    <light type="directional" name="sun"><pose>0 0 10 0 0 0</pose></light>
    <model name="ground_plane"><static>true</static><pose>0 0 -1 0 0 0</pose>
      <link name="link"><collision name="collision"><geometry><plane><normal>0 0 1</normal>
      <size>20 20</size></plane></geometry></collision></link></model>
    <model name="joint_position_controller_demo">
      <pose>0 0 0 0 1.57 0</pose>
      <link name="base_link">
        <inertial><mass>120</mass><inertia><ixx>2.5</ixx><iyy>2.5</iyy><izz>5</izz>
        </inertia></inertial>
        <collision name="base_collision"><geometry><box><size>0.5 0.5 0.01</size></box>
        </geometry></collision>
      </link>
      <link name="rotor">
        <pose>0 0 0.1 0 0 0</pose>
        <inertial><mass>0.6</mass><inertia><ixx>0.032</ixx><iyy>0.032</iyy>
        <izz>0.00012</izz></inertia></inertial>
        <collision name="collision"><geometry><box><size>0.25 0.1 0.05</size></box>
        </geometry></collision>
      </link>
      <joint name="world_fixed" type="fixed"><parent>world</parent><child>base_link</child>
      </joint>
      <joint name="j1" type="revolute">
        <pose>0 0 -0.5 0 0 0</pose><parent>base_link</parent><child>rotor</child>
        <axis><xyz>0 0 1</xyz><dynamics><damping>0.5</damping></dynamics></axis>
      </joint>
      <plugin filename="gz-sim-joint-position-controller-system"
              name="gz::sim::systems::JointPositionController">
        <joint_name>j1</joint_name><topic>rotor_cmd</topic>
        <p_gain>1</p_gain><i_gain>0.1</i_gain><d_gain>0.01</d_gain>
        <i_max>1</i_max><i_min>-1</i_min><cmd_max>1000</cmd_max><cmd_min>-1000</cmd_min>
      </plugin>
    </model>
  </world>
</sdf>
"""

# the world behind the bridge: its command in, the scene broadcaster's poses out
JPC_LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    world = os.path.join(get_package_share_directory('rover_demos'), 'worlds',
                         'joint_position_controller.sdf')
    gazebo = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('ros_gz_sim'), 'launch', 'gz_sim.launch.py')),
        launch_arguments={'gz_args': '-r ' + world}.items())
    bridge = Node(
        package='ros_gz_bridge', executable='parameter_bridge', output='screen',
        arguments=['/rotor_cmd@std_msgs/msg/Float64]gz.msgs.Double',
                   '/world/default/pose/info@tf2_msgs/msg/TFMessage[gz.msgs.Pose_V',
                   '/world/default/dynamic_pose/info@tf2_msgs/msg/TFMessage[gz.msgs.Pose_V'])
    return LaunchDescription([gazebo, bridge])
"""


@pytest.fixture
def demos_ws(ws):
    """A workspace whose package rover_demos holds the demos' launch files, model and world."""
    ws.own_bus()
    package = ws.root / "pkgs" / "rover_demos"
    for name, text in (("package.xml", PACKAGE), ("models/rover/model.config", MODEL_CONFIG),
                       ("models/rover/model.sdf", MODEL_SDF), ("worlds/rover.sdf", ROVER_WORLD),
                       ("launch/sdf_parser.launch.py", SDF_PARSER_LAUNCH),
                       ("launch/robot_description_publisher.launch.py", DESCRIPTION_LAUNCH),
                       ("worlds/joint_position_controller.sdf", JPC_WORLD),
                       ("launch/joint_position_controller.launch.py", JPC_LAUNCH)):
        (package / name).parent.mkdir(parents=True, exist_ok=True)
        (package / name).write_text(text)
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "pkgs")
    return ws


def stop(proc) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(30)


def echo(ws, topic: str, type_name: str, *args: str) -> str:
    done = ws.run("topic", "echo", topic, type_name, "--once", "--timeout", "30", *args,
                  timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def start_sdf_parser(ws):
    proc = ws.start("launch", "rover_demos", "sdf_parser.launch.py", output="demo.out")
    ws.wait_for_output("bridging 6 of 6 entries", 60, "demo.out")
    return proc


def test_sdf_parser_demo_paused_as_gazebo_opens_it_gives_joint_states_and_tf(demos_ws):
    """Gazebo opens the demo's world paused (no -r), and its JointStatePublisher publishes
    while paused: /joint_states flows and robot_state_publisher, fed the model's SDF, gives the
    wheels' transforms before anyone presses play."""
    proc = start_sdf_parser(demos_ws)
    try:
        states = echo(demos_ws, "/joint_states", "sensor_msgs/msg/JointState")
        assert re.search(r"name:\n- left_wheel_joint\n- right_wheel_joint\n", states), states
        assert "sec: 0\n    nanosec: 0\n" in states, states  # paused at time 0
        tf = echo(demos_ws, "/tf", "tf2_msgs/msg/TFMessage")  # (the bridge's poses wait)
        assert "frame_id: chassis\n  child_frame_id: left_wheel" in tf, tf
        said = demos_ws.output("demo.out")
        assert "robot 'rover': 2 moving joints" in said, said
        assert "[ERROR]" not in said and "Traceback" not in said, said
    finally:
        assert stop(proc) == 130


def test_sdf_parser_demo_after_play_drives_on_cmd_vel_through_the_bridge(demos_ws):
    """Play pressed (the world's control service, as Gazebo's play button): the DiffDrive the
    model file brings answers the bridged cmd_vel, and the odometry says it went forward."""
    proc = start_sdf_parser(demos_ws)
    try:
        played = demos_ws.run("gz", "service", "-s", "/world/demo/control", "--reqtype",
                              "gz.msgs.WorldControl", "--reptype", "gz.msgs.Boolean",
                              "--timeout", "5000", "--req", "pause: false")
        assert "data: true" in played.stdout, played.stdout + played.stderr
        sent = demos_ws.run("topic", "pub", "/model/rover/cmd_vel", "geometry_msgs/msg/Twist",
                            "{linear: {x: 0.5}}", "-r", "10", "-t", "25", timeout=60)
        assert sent.returncode == 0, sent.stderr
        deadline, x = time.monotonic() + 30, 0.0  # it drives on: the command stands
        while x <= 0.5 and time.monotonic() < deadline:
            x = float(echo(demos_ws, "/model/rover/odometry", "nav_msgs/msg/Odometry",
                           "--field", "pose.pose.position.x").split()[0])
        assert x > 0.5, x
        turning = echo(demos_ws, "/joint_states", "sensor_msgs/msg/JointState", "--field",
                       "velocity")
        assert all(float(v) > 1.0 for v in re.findall(r"- (\S+)", turning)), turning
    finally:
        assert stop(proc) == 130


def test_robot_description_publisher_spawns_keep_their_yaw(demos_ws):
    """Y:=3.4, by create's parameter and by its -Y flag: each model's yaw is 3.4 rad, which
    Gazebo's pose says as 3.4 - 2π."""
    proc = demos_ws.start("launch", "rover_demos", "robot_description_publisher.launch.py",
                          "Y:=3.4", output="demo.out")
    try:
        for name in ("my_custom_model", "by_flags"):
            demos_ws.wait_for_output(f"spawned '{name}' into world 'empty'", 60, "demo.out")
            pose = demos_ws.run("gz", "model", "-m", name, "-p").stdout
            rpy = [float(v) for v in re.findall(r"\[(\S+) (\S+) (\S+)\]", pose)[1]]
            assert rpy[2] == pytest.approx(3.4 - 2 * math.pi, abs=1e-3), pose
            assert rpy[:2] == pytest.approx([0, 0], abs=1e-3), pose
        info = demos_ws.run("gz", "topic", "-e", "-t", "/world/empty/pose/info", "-n", "1")
        found = re.search(r'name: "my_custom_model"\n  position \{[^}]*\}\n  orientation '
                          r'\{([^}]*)\}', info.stdout)
        assert found, info.stdout
        quat = {k: float(v) for k, v in re.findall(r"(\w): (\S+)", found.group(1))}
        yaw = 2 * math.atan2(quat.get("z", 0.0), quat.get("w", 0.0))  # (x, y: about 0)
        assert yaw % (2 * math.pi) == pytest.approx(3.4, abs=1e-3), info.stdout
    finally:
        assert stop(proc) == 130


def test_joint_position_controller_world_dynamic_poses_keep_the_model_held_by_a_joint(demos_ws):
    """The scene broadcaster's dynamic_pose/info, bridged: the rotor's model, which a fixed
    joint holds to the world and so has no free joint, is not static and is there; the static
    ground is only in pose/info."""
    proc = demos_ws.start("launch", "rover_demos", "joint_position_controller.launch.py",
                          output="demo.out")
    try:
        demos_ws.wait_for_output("bridging 3 of 3 entries", 60, "demo.out")
        every = echo(demos_ws, "/world/default/pose/info", "tf2_msgs/msg/TFMessage")
        assert re.findall(r"child_frame_id: (\w+)", every) == [
            "ground_plane", "joint_position_controller_demo"], every
        moving = echo(demos_ws, "/world/default/dynamic_pose/info", "tf2_msgs/msg/TFMessage")
        assert re.findall(r"child_frame_id: (\w+)", moving) == [
            "joint_position_controller_demo"], moving
        assert "frame_id: world" in moving and "y: 0.70" in moving, moving  # pitched 1.57
    finally:
        assert stop(proc) == 130


def test_joint_position_controller_model_is_a_robot_for_the_standard_api(demos_ws):
    """simulation_interfaces' GetEntities by category: the model a fixed joint holds to the
    world, with a controller in it, is among the robots, not with the static ground."""
    proc = demos_ws.start("launch", "rover_demos", "joint_position_controller.launch.py",
                          output="demo.out")
    try:
        demos_ws.wait_for_output("bridging 3 of 3 entries", 60, "demo.out")
        listed = {}
        for category, label in ((1, "robots"), (5, "static")):
            done = demos_ws.run("service", "call", "/gzserver/get_entities",
                                "simulation_interfaces/srv/GetEntities",
                                f"{{filters: {{categories: [{{category: {category}}}]}}}}",
                                timeout=60)
            assert done.returncode == 0, done.stdout + done.stderr
            listed[label] = re.findall(r"^- (\w+)$", done.stdout, re.M)
        assert listed == {"robots": ["joint_position_controller_demo"],
                          "static": ["ground_plane"]}, listed
    finally:
        assert stop(proc) == 130

"""Gazebo's systems in a real sim, seen through ros_gz's bridge as the ros_gz demos see them:
joint states from a URDF naming the system by its ignition name (joint_states.launch.py's
bridge, remapped), a battery's state (battery.launch.py), model poses as TF (tf_bridge), and
gz-sim's joint trajectory controller fed trajectory_msgs through the bridge."""

from __future__ import annotations

import re
import signal
import time

WORLD = """<?xml version="1.0"?><sdf version="1.9"><world name="systems">
<physics name="1ms" type="ignored"><max_step_size>0.001</max_step_size></physics>
<model name="ground"><static>true</static><link name="l"><collision name="c"><geometry><plane>
<normal>0 0 1</normal><size>40 40</size></plane></geometry></collision></link></model>
<model name="rover"><pose>0 0 0.2 0 0 0</pose>
  <link name="chassis"><inertial><mass>5</mass><inertia><ixx>0.1</ixx><iyy>0.2</iyy>
  <izz>0.2</izz></inertia></inertial><collision name="c"><pose>0 0 0.15 0 0 0</pose><geometry>
  <box><size>0.8 0.5 0.1</size></box></geometry></collision></link>
  {wheels}
  <link name="caster"><pose>-0.3 0 -0.1 0 0 0</pose><inertial><mass>0.1</mass><inertia>
  <ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial><collision name="c">
  <geometry><sphere><radius>0.1</radius></sphere></geometry><surface><friction><ode><mu>0</mu>
  <mu2>0</mu2></ode></friction></surface></collision></link>
  <joint name="caster_fix" type="fixed"><parent>chassis</parent><child>caster</child></joint>
  <plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">
    <left_joint>left</left_joint><right_joint>right</right_joint>
    <wheel_separation>0.6</wheel_separation><wheel_radius>0.1</wheel_radius></plugin>
  <plugin filename="gz-sim-linearbatteryplugin-system"
    name="gz::sim::systems::LinearBatteryPlugin">
    <battery_name>linear_battery</battery_name><voltage>4.2</voltage>
    <open_circuit_voltage_constant_coef>4.2</open_circuit_voltage_constant_coef>
    <open_circuit_voltage_linear_coef>-2.0</open_circuit_voltage_linear_coef>
    <initial_charge>0.01</initial_charge><capacity>0.01</capacity>
    <resistance>0.07</resistance><smooth_current_tau>0.5</smooth_current_tau>
    <power_load>20</power_load></plugin>
  <plugin filename="ignition-gazebo-pose-publisher-system"
    name="ignition::gazebo::systems::PosePublisher">
    <publish_link_pose>true</publish_link_pose><publish_model_pose>true</publish_model_pose>
    <use_pose_vector_msg>true</use_pose_vector_msg><update_frequency>20</update_frequency>
  </plugin>
</model>
<model name="arm"><pose>3 0 0 0 0 0</pose>
  <link name="base"><inertial><mass>50</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz>
  </inertia></inertial></link>
  <joint name="anchor" type="fixed"><parent>world</parent><child>base</child></joint>
  <link name="upper"><pose>0 0 0.3 0 0 0</pose><inertial><mass>1</mass><inertia><ixx>0.02</ixx>
  <iyy>0.02</iyy><izz>0.02</izz></inertia></inertial></link>
  <joint name="shoulder" type="revolute"><parent>base</parent><child>upper</child>
  <axis><xyz>0 0 1</xyz></axis></joint>
  <plugin filename="libignition-gazebo-joint-trajectory-controller-system.so"
    name="ignition::gazebo::systems::JointTrajectoryController">
    <joint_name>shoulder</joint_name><position_p_gain>40</position_p_gain>
    <position_d_gain>4</position_d_gain></plugin>
  <plugin filename="gz-sim-joint-state-publisher-system"
    name="gz::sim::systems::JointStatePublisher"/>
</model>
</world></sdf>"""
WHEEL = """<link name="{side}_wheel"><pose>0.15 {y} 0 -1.5708 0 0</pose><inertial><mass>0.5</mass>
  <inertia><ixx>0.003</ixx><iyy>0.003</iyy><izz>0.003</izz></inertia></inertial>
  <collision name="c"><geometry><cylinder><radius>0.1</radius><length>0.05</length></cylinder>
  </geometry></collision></link>
  <joint name="{side}" type="revolute"><parent>chassis</parent><child>{side}_wheel</child>
  <axis><xyz>0 0 1</xyz></axis></joint>"""
RRBOT = """<?xml version="1.0"?><robot name="rrbot"><link name="world"/>
  <link name="link1"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01"
  ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="fixed" type="fixed"><parent link="world"/><child link="link1"/></joint>
  <link name="link2"><inertial><origin xyz="0 0 0.5"/><mass value="1"/><inertia ixx="0.01"
  iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="joint1" type="continuous"><parent link="link1"/><child link="link2"/>
  <origin xyz="0 0.1 1.95"/><axis xyz="0 1 0"/><dynamics damping="0.7"/></joint>
  <gazebo><plugin filename="ignition-gazebo-joint-state-publisher-system"
    name="ignition::gazebo::systems::JointStatePublisher"/></gazebo>
</robot>"""
LAUNCH = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['gz', 'sim', '-r', '-s', '-v', '3', '{world}'], output='screen'),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{{'robot_description': open('{urdf}').read()}}]),
        Node(package='ros_gz_sim', executable='create',
             parameters=[{{'name': 'rrbot', 'topic': 'robot_description'}}], output='screen'),
        Node(package='ros_gz_bridge', executable='parameter_bridge', output='screen',
             arguments=[
                 '/world/systems/model/rrbot/joint_state@sensor_msgs/msg/JointState'
                 '[gz.msgs.Model',
                 '/model/rover/cmd_vel@geometry_msgs/msg/Twist@gz.msgs.Twist',
                 '/model/rover/battery/linear_battery/state@sensor_msgs/msg/BatteryState'
                 '@gz.msgs.BatteryState',
                 '/model/rover/pose@tf2_msgs/msg/TFMessage[gz.msgs.Pose_V',
                 '/model/arm/joint_trajectory@trajectory_msgs/msg/JointTrajectory'
                 ']gz.msgs.JointTrajectory',
             ],
             remappings=[('/world/systems/model/rrbot/joint_state', 'joint_states')]),
    ])
"""


def echo(ws, topic: str, type_name: str, *extra: str) -> str:
    done = ws.run("topic", "echo", topic, type_name, "--once", *extra, timeout=30)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_gazebo_systems_through_the_bridge_as_the_ros_gz_demos_use_them(ws):
    ws.own_bus()
    world = ws.write("systems.sdf", WORLD.format(wheels="".join(
        WHEEL.format(side=s, y=y) for s, y in (("left", 0.3), ("right", -0.3)))))
    urdf = ws.write("rrbot.urdf", RRBOT)
    launch = ws.write("systems.launch.py", LAUNCH.format(world=world, urdf=urdf))
    proc = ws.start("launch", str(launch), output="launch.out")
    try:
        ws.wait_for_output("bridging 5 of 5 entries", 60, "launch.out")
        ws.wait_for_output("spawned 'rrbot'", 60, "launch.out")
        # joint states: the ignition-named system, bridged and remapped to /joint_states
        states = echo(ws, "/joint_states", "sensor_msgs/msg/JointState")
        assert "- joint1" in states, states
        # the battery: full and idle, then draining once the rover drives
        topic = "/model/rover/battery/linear_battery/state"
        idle = echo(ws, topic, "sensor_msgs/msg/BatteryState")
        assert "percentage: 1.0" in idle and "power_supply_status: 4" in idle, idle
        sent = ws.run("topic", "pub", "-r", "10", "-t", "20", "/model/rover/cmd_vel",
                      "geometry_msgs/msg/Twist", "{linear: {x: 0.5}}", timeout=30)
        assert sent.returncode == 0, sent.stderr
        draining = echo(ws, topic, "sensor_msgs/msg/BatteryState")
        percentage = float(re.search(r"percentage: ([\d.e-]+)", draining).group(1))
        assert percentage < 1.0 and "power_supply_status: 2" in draining, draining
        gz_text = ws.run("gz", "topic", "-e", "-t", topic, "-n", "1", timeout=30).stdout
        assert "power_supply_status: DISCHARGING" in gz_text, gz_text
        # the rover's poses as TF: the model in the world, its links in the model
        tf = echo(ws, "/model/rover/pose", "tf2_msgs/msg/TFMessage")
        assert "frame_id: systems" in tf and "child_frame_id: rover" in tf, tf
        assert "child_frame_id: left_wheel" in tf
        # gz-sim's joint trajectory controller, from trajectory_msgs through the bridge
        ws.run("topic", "pub", "--once", "/model/arm/joint_trajectory",
               "trajectory_msgs/msg/JointTrajectory",
               "{joint_names: [shoulder], points: [{positions: [0.8], time_from_start: "
               "{nanosec: 100000000}}]}")
        deadline = time.monotonic() + 20
        angle = None
        while time.monotonic() < deadline:
            model = ws.run("gz", "topic", "-e", "-t", "/world/systems/model/arm/joint_state",
                           "-n", "1", timeout=30).stdout
            found = re.search(r'name: "shoulder"\s*\n\s*axis1 \{\s*position: ([-\d.e]+)',
                              model)
            angle = float(found.group(1)) if found else None
            if angle is not None and abs(angle - 0.8) < 0.02:
                break
            time.sleep(0.3)
        assert angle is not None and abs(angle - 0.8) < 0.02, model
        assert "[ERROR]" not in ws.output("launch.out")
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130

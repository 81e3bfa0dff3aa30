"""ros2_control benchmarks (issue 33), each against its reference in the same run.

Cost: a six-joint arm in a real sim at real time (1 kHz physics), its controller_manager at
1 kHz running joint_trajectory_controller (following a long trajectory) and
joint_state_broadcaster (subscribed); the sim's RTF and its CPU, against the same arm in the
same sim with no ros2_control, interleaved.

Spawner chain: a launch file starting the sim, spawning the arm and chaining three spawners on
OnProcessExit (as gz_ros2_control_demos' launch files do): the time from the launch's start
to the third controller active, and from the robot spawned to it.

Latency: a diff-drive robot under diff_drive_controller (100 Hz, as the demo's YAML): a
TwistStamped published, then the first odometry that shows motion (measured from the wheels):
the sim steps between the command's arrival time (the sim's clock when it was sent) and that
odometry's stamp.
"""

from __future__ import annotations

import math
import os
import statistics
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import psutil
from _harness import launcher_cmd, start_router, summary, table

JOINTS = 6
ARM = """<?xml version="1.0"?><robot name="arm"><link name="world"/>
<link name="base"><inertial><mass value="5"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0"
iyz="0"/></inertial></link><joint name="fix" type="fixed"><parent link="world"/>
<child link="base"/><origin xyz="0 0 0.3"/></joint>{links}{control}</robot>"""
LINK = """<link name="l{n}"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01"
ixy="0" ixz="0" iyz="0"/></inertial><collision><geometry><box size="0.05 0.05 0.1"/></geometry>
</collision></link><joint name="j{n}" type="revolute"><parent link="{parent}"/>
<child link="l{n}"/><origin xyz="0 0 0.1"/><axis xyz="{axis}"/><limit lower="-3" upper="3"
effort="100" velocity="5"/><dynamics damping="0.1"/></joint>"""
CONTROL = """<ros2_control name="Arm" type="system"><hardware>
<plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>{joints}</ros2_control>
<gazebo><plugin filename="gz_ros2_control-system"
name="gz_ros2_control::GazeboSimROS2ControlPlugin"><parameters>{yaml}</parameters></plugin>
</gazebo>"""
JOINT = """<joint name="j{n}"><command_interface name="position"/>
<state_interface name="position"/><state_interface name="velocity"/></joint>"""
YAML = """controller_manager:
  ros__parameters:
    update_rate: 1000
    joint_state_broadcaster: {{type: joint_state_broadcaster/JointStateBroadcaster}}
    arm_controller: {{type: joint_trajectory_controller/JointTrajectoryController}}
    wrist_states: {{type: joint_state_broadcaster/JointStateBroadcaster}}
arm_controller:
  ros__parameters:
    joints: [{joints}]
    command_interfaces: [position]
    state_interfaces: [position, velocity]
wrist_states:
  ros__parameters:
    joints: [j6]
    interfaces: [position]
    use_local_topics: true
"""
DIFF = """<?xml version="1.0"?><robot name="rover">
<link name="chassis"><collision><origin xyz="0 0 0.3"/><geometry><box size="1 0.6 0.2"/>
</geometry></collision><inertial><origin xyz="0 0 0.3"/><mass value="5"/><inertia ixx="0.2"
iyy="0.5" izz="0.6" ixy="0" ixz="0" iyz="0"/></inertial></link>
{wheels}
<link name="caster"><collision><geometry><sphere radius="0.1"/></geometry></collision>
<inertial><mass value="0.1"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0"
iyz="0"/></inertial></link><joint name="caster_joint" type="fixed"><parent link="chassis"/>
<child link="caster"/><origin xyz="-0.4 0 0.1"/></joint>
<ros2_control name="Base" type="system"><hardware>
<plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
<joint name="left"><command_interface name="velocity"/><state_interface name="position"/>
<state_interface name="velocity"/></joint><joint name="right">
<command_interface name="velocity"/><state_interface name="position"/>
<state_interface name="velocity"/></joint></ros2_control>
<gazebo><plugin filename="gz_ros2_control-system"
name="gz_ros2_control::GazeboSimROS2ControlPlugin"><parameters>{yaml}</parameters></plugin>
</gazebo></robot>"""
WHEEL = """<link name="{side}_wheel"><collision><geometry><sphere radius="0.2"/></geometry>
</collision><inertial><mass value="1"/><inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0"
ixz="0" iyz="0"/></inertial></link><joint name="{side}" type="continuous">
<parent link="chassis"/><child link="{side}_wheel"/><origin xyz="0.3 {y} 0.2"
rpy="-1.5707963 0 0"/><axis xyz="0 0 1"/></joint>"""
DIFF_YAML = """controller_manager:
  ros__parameters:
    update_rate: 100
    base: {type: diff_drive_controller/DiffDriveController}
base:
  ros__parameters:
    left_wheel_names: [left]
    right_wheel_names: [right]
    wheel_separation: 0.8
    wheel_radius: 0.2
    base_frame_id: chassis
    publish_rate: 50.0
"""
CLOCK = struct.Struct("<4xiI")


def arm(folder: Path, control: bool) -> Path:
    yaml = folder / "arm.yaml"
    yaml.write_text(YAML.format(joints=", ".join(f"j{n}" for n in range(1, JOINTS + 1))))
    links = "".join(LINK.format(n=n, parent="base" if n == 1 else f"l{n - 1}",
                                axis="0 0 1" if n % 2 else "0 1 0")
                    for n in range(1, JOINTS + 1))
    block = CONTROL.format(joints="".join(JOINT.format(n=n) for n in range(1, JOINTS + 1)),
                           yaml=yaml) if control else ""
    path = folder / f"arm_{'control' if control else 'plain'}.urdf"
    path.write_text(ARM.format(links=links, control=block))
    return path


def launcher(*args: str, env: dict, **kwargs) -> subprocess.CompletedProcess:
    return subprocess.run(launcher_cmd() + list(args), env=env, capture_output=True, text=True,
                          timeout=120, **kwargs)


def start_sim(env: dict, folder: Path) -> subprocess.Popen:
    sim = subprocess.Popen(launcher_cmd() + ["gz", "sim", "-r", "-s", "-v", "3", "empty.sdf"],
                           env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           cwd=folder)
    for line in sim.stdout:
        if "running" in line:
            break
    return sim


def trajectory(node, seconds: float):
    """A long trajectory (a sine on every joint, 10 points a second)."""
    message = node.message("trajectory_msgs/msg/JointTrajectory",
                           joint_names=[f"j{n}" for n in range(1, JOINTS + 1)])
    for k in range(1, int(seconds * 10)):
        t = k / 10
        point = node.message("trajectory_msgs/msg/JointTrajectoryPoint",
                             positions=[0.5 * math.sin(t + n) for n in range(JOINTS)])
        point.time_from_start.sec, point.time_from_start.nanosec = int(t), int(t % 1 * 1e9)
        message.points.append(point)
    return message


def cost(env: dict, folder: Path, control: bool, seconds: float) -> tuple[float, float]:
    """(RTF, CPU seconds per second) of the sim with the arm, with or without control."""
    from launcher.bus import keys
    from launcher.bus.node import Node

    sim = start_sim(env, folder)
    node = Node("bench_control", argv=[])
    try:
        done = launcher("run", "ros_gz_sim", "create", "-file", str(arm(folder, control)),
                        "-name", "arm", env=env)
        assert done.returncode == 0, done.stderr
        if control:
            done = launcher("run", "controller_manager", "spawner", "joint_state_broadcaster",
                            "arm_controller", "--activate-as-group", env=env)
            assert done.returncode == 0, done.stderr
        clocks: list[tuple[float, float]] = []

        def on_clock(payload: bytes) -> None:
            sec, nanosec = CLOCK.unpack_from(payload)
            clocks.append((time.monotonic(), sec + nanosec * 1e-9))

        node.create_subscription("mujoco_sim/msg/Clock", "/clock", on_clock, raw=True,
                                 inline=True, space=keys.SIM)
        states: list[float] = []
        node.create_subscription("sensor_msgs/msg/JointState", "/joint_states",
                                 lambda payload: states.append(1.0), raw=True, inline=True)
        if control:
            publisher = node.create_publisher("trajectory_msgs/msg/JointTrajectory",
                                              "/arm_controller/joint_trajectory")
            node.spin(1.0)
            publisher.publish(trajectory(node, seconds + 10))
        node.spin(2.0)
        process = psutil.Process(sim.pid)
        clocks.clear()
        states.clear()
        cpu = process.cpu_times()
        node.spin(seconds)
        used = sum(process.cpu_times()[:2]) - sum(cpu[:2])
        (wall0, sim0), (wall1, sim1) = clocks[0], clocks[-1]
        if control:
            assert len(states) > 0.9 * seconds * 1000, len(states)  # 1 kHz joint states
        return (sim1 - sim0) / (wall1 - wall0), used / seconds
    finally:
        node.destroy_node()
        sim.terminate()
        sim.wait(10)


CHAIN = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def generate_launch_description():
    sim = ExecuteProcess(cmd=['gz', 'sim', '-r', '-s', '-v', '3', 'empty.sdf'], output='screen')
    create = Node(package='ros_gz_sim', executable='create',
                  arguments=['-file', '{urdf}', '-name', 'arm'], output='screen')
    spawners = [Node(package='controller_manager', executable='spawner', arguments=[name],
                     output='screen')
                for name in ('joint_state_broadcaster', 'arm_controller', 'wrist_states')]
    chain = [RegisterEventHandler(OnProcessExit(target_action=a, on_exit=[b]))
             for a, b in zip([create] + spawners[:-1], spawners)]
    return LaunchDescription([sim, create, *chain])
"""


def spawner_chain(env: dict, folder: Path) -> tuple[float, float]:
    """(launch start → third controller active, robot spawned → third active), seconds."""
    launch = folder / "chain.launch.py"
    launch.write_text(CHAIN.format(urdf=arm(folder, True)))
    start = time.monotonic()
    proc = subprocess.Popen(launcher_cmd() + ["launch", str(launch)], env=env, cwd=folder,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    spawned = math.nan
    try:
        for line in proc.stdout:
            if "spawned 'arm' into world" in line:
                spawned = time.monotonic()
            if "Activating controllers: [ wrist_states ]" in line:
                end = time.monotonic()
                return end - start, end - spawned
        raise RuntimeError("the chain never finished")
    finally:
        proc.send_signal(2)
        proc.wait(30)


def latency(env: dict, folder: Path, trials: int) -> list[float]:
    from launcher.bus import keys
    from launcher.bus.node import Node

    yaml = folder / "diff.yaml"
    yaml.write_text(DIFF_YAML)
    urdf = folder / "rover.urdf"
    urdf.write_text(DIFF.format(yaml=yaml, wheels="".join(
        WHEEL.format(side=s, y=y) for s, y in (("left", 0.4), ("right", -0.4)))))
    sim = start_sim(env, folder)
    node = Node("bench_latency", argv=[])
    try:
        assert launcher("run", "ros_gz_sim", "create", "-file", str(urdf), "-name", "rover",
                        "-z", "0.05", env=env).returncode == 0
        assert launcher("run", "controller_manager", "spawner", "base",
                        env=env).returncode == 0
        now = [0.0]

        def on_clock(payload: bytes) -> None:
            sec, nanosec = CLOCK.unpack_from(payload)
            now[0] = sec + nanosec * 1e-9

        node.create_subscription("mujoco_sim/msg/Clock", "/clock", on_clock, raw=True,
                                 inline=True, space=keys.SIM)
        moving: list[float] = []

        def on_odom(message) -> None:
            if abs(message.twist.twist.linear.x) > 0.01:
                stamp = message.header.stamp
                moving.append(stamp.sec + stamp.nanosec * 1e-9)

        node.create_subscription("nav_msgs/msg/Odometry", "/base/odom", on_odom)
        command = node.create_publisher("geometry_msgs/msg/TwistStamped", "/base/cmd_vel")
        twist = node.message("geometry_msgs/msg/TwistStamped")
        twist.twist.linear.x = 0.5
        node.spin(2.0)
        steps = []
        for _ in range(trials):
            moving.clear()
            node.spin(1.5)  # stopped (cmd_vel_timeout 0.5 s)
            moving.clear()
            sent = now[0]
            command.publish(twist)
            deadline = time.monotonic() + 5
            while not [t for t in moving if t > sent] and time.monotonic() < deadline:
                node.spin_once(0.01)
            first = min((t for t in moving if t > sent), default=math.nan)
            steps.append((first - sent) / 0.001)
        return steps
    finally:
        node.destroy_node()
        sim.terminate()
        sim.wait(10)


def main() -> None:
    env, router = start_router()
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-control-"))
    seconds = float(os.environ.get("BENCH_CONTROL_SECONDS", "10"))
    try:
        plain, controlled = [], []
        for _ in range(2):  # interleaved: no control, then control
            plain.append(cost(env, folder, False, seconds))
            controlled.append(cost(env, folder, True, seconds))
        extra = [c[1] - p[1] for p, c in zip(plain, controlled, strict=True)]
        chains = [spawner_chain(env, folder) for _ in range(3)]
        steps = latency(env, folder, 12)
        table("ros2_control (1 kHz physics, real time)", [
            ("RTF, arm with no ros2_control", "report", summary([p[0] for p in plain])),
            ("RTF, 6-joint JTC + JSB at 1 kHz", "1.0", summary([c[0] for c in controlled])),
            ("sim CPU, no ros2_control (cores)", "report", summary([p[1] for p in plain])),
            ("sim CPU, with controllers (cores)", "report", summary([c[1] for c in controlled])),
            ("extra CPU of control (cores, same run)", "<= 0.15", summary(extra)),
            ("spawner chain of 3: launch start -> all active, s", "report",
             summary([c[0] for c in chains])),
            ("spawner chain of 3: robot spawned -> all active, s", "report",
             summary([c[1] for c in chains])),
            ("TwistStamped -> odometry moving, sim steps (p50)", "report",
             f"p50 {statistics.median(steps):.0f}  min {min(steps):.0f}  max {max(steps):.0f}"
             f"  (n={len(steps)})"),
        ])
    finally:
        router.terminate()
        router.wait(10)


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    main()

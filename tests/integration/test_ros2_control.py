"""ros2_control in the sim: gz_ros2_control_demos' launch files unchanged, every controller
through a real spawner against the real sim, `launcher control`, ros2_control_node with mock
hardware, and the bad inputs the issue lists. Real processes on a real router."""

from __future__ import annotations

import re
import signal
import time

import pytest

from tests.conftest import shared

DEMOS = ("external", "gz_ros2_control_demos")


@pytest.fixture
def demos(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared(*DEMOS))
    return ws


def stop(proc) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(30)


def field(ws, topic: str, type_name: str, path: str) -> list[float]:
    done = ws.run("topic", "echo", topic, type_name, "--once", "--field", path, timeout=30)
    assert done.returncode == 0, done.stderr
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", done.stdout)]


def wait_until(check, timeout: float = 20.0, every: float = 0.3):
    deadline = time.monotonic() + timeout
    while True:
        value = check()
        if value or time.monotonic() > deadline:
            return value
        time.sleep(every)


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

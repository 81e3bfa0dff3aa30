"""A launch test of the demo in lockstep (launch_files/robot_lockstep.launch.yaml): the robot is
driven 2 m from where it starts, and the test prints the sim time that took against the wall
time (bench/testing.py reads the line). Run by `launcher test`, as a user's launch test is."""

import math
import os
import threading
import time
import unittest

import launch
import launch_testing.actions
import rclpy
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from nav_msgs.msg import Odometry

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DISTANCE = 2.0  # m from the start


def generate_test_description():
    demo = os.path.join(REPO, "launch_files", "robot_lockstep.launch.yaml")
    return launch.LaunchDescription([
        IncludeLaunchDescription(AnyLaunchDescriptionSource(demo)),
        launch_testing.actions.ReadyToTest(),
    ])


class TestDrivenTwoMetres(unittest.TestCase):
    def test_the_robot_is_driven_two_metres(self):
        rclpy.init()
        node = rclpy.create_node("bench_lockstep")
        marks: list[tuple[float, float]] = []  # (sim s, wall s) at the start and at 2 m
        done = threading.Event()
        start: list[tuple[float, float]] = []

        def on_odom(message):
            stamp = message.header.stamp.sec + message.header.stamp.nanosec / 1e9
            p = message.pose.pose.position
            if not start:
                start.append((p.x, p.y))
                marks.append((stamp, time.monotonic()))
            elif math.dist(start[0], (p.x, p.y)) >= DISTANCE and not done.is_set():
                marks.append((stamp, time.monotonic()))
                done.set()

        node.create_subscription(Odometry, "/odom", on_odom, 100)
        deadline = time.monotonic() + 120
        while not done.is_set() and time.monotonic() < deadline:
            rclpy.spin_once(node, timeout_sec=0.1)
        node.destroy_node()
        rclpy.shutdown()
        self.assertTrue(done.is_set(), "the robot was not driven 2 m within 120 s")
        sim = marks[1][0] - marks[0][0]
        wall = marks[1][1] - marks[0][1]
        print(f"LOCKSTEP sim={sim:.3f} wall={wall:.3f}", flush=True)

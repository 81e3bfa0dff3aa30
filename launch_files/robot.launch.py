"""The demo from ROS 2's Python launch API: the same as robot.launch.yaml.
    launcher launch launch_files/robot.launch.py [world_name:=world.sdf] [drive:=false]
The stack itself is robot_bringup's robot.launch.py; this file passes its arguments on."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration

ARGS = {"world_name": "robot.world", "drive": "true", "speed": "0.5"}


def generate_launch_description():
    stack = IncludeLaunchDescription(
        PythonLaunchDescriptionSource([os.path.join(
            get_package_share_directory("robot_bringup"), "launch", "robot.launch.py")]),
        launch_arguments={name: LaunchConfiguration(name) for name in ARGS}.items())
    return LaunchDescription([
        *(DeclareLaunchArgument(name, default_value=value) for name, value in ARGS.items()),
        stack,
    ])

"""The demo stack from ROS 2's Python launch API: the same as robot.launch.yaml.

Shaped like a ROS 2 Gazebo project's gazebo.launch.py: the simulator comes from an
IncludeLaunchDescription of ros_gz_sim's gz_sim.launch.py with `gz_args`.
    launcher launch robot_bringup robot.launch.py world_name:=world.sdf
"""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (
    AppendEnvironmentVariable,
    DeclareLaunchArgument,
    IncludeLaunchDescription,
)
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import Command, LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    bringup = get_package_share_directory("robot_bringup")
    xacro_file = os.path.join(get_package_share_directory("robot_description"), "urdf",
                              "robot.xacro")
    worlds = os.path.join(get_package_share_directory("robot_gazebo"), "worlds")

    sim = IncludeLaunchDescription(
        PythonLaunchDescriptionSource([os.path.join(
            get_package_share_directory("ros_gz_sim"), "launch", "gz_sim.launch.py")]),
        launch_arguments={"gz_args": ["-r -v 4 ", LaunchConfiguration("world_name")],
                          "on_exit_shutdown": "true"}.items())

    robot_state_publisher = Node(
        package="robot_state_publisher", executable="robot_state_publisher", output="screen",
        parameters=[{"robot_description": ParameterValue(Command(["xacro ", xacro_file]),
                                                         value_type=str)}])

    bridge = Node(
        package="ros_gz_bridge", executable="parameter_bridge",
        output="screen",
        parameters=[{"config_file": LaunchConfiguration("bridge_config_file")}])

    create = Node(
        package="ros_gz_sim", executable="create", output="screen",
        arguments=["-entity", "my_robot", "-topic", "robot_description"])

    driver = Node(
        package="robot_application", executable="driver", output="screen",
        parameters=[{"speed": ParameterValue(LaunchConfiguration("speed"), value_type=float)}],
        condition=IfCondition(LaunchConfiguration("drive")))

    return LaunchDescription([
        DeclareLaunchArgument("bridge_config_file",
                              default_value=os.path.join(bringup, "config", "bridge.yaml")),
        DeclareLaunchArgument("world_name", default_value="robot.world"),
        DeclareLaunchArgument("drive", default_value="true",
                              description="start the driver node"),
        DeclareLaunchArgument("speed", default_value="0.5", description="the driver's speed, m/s"),
        AppendEnvironmentVariable("GZ_SIM_RESOURCE_PATH", worlds),
        sim,
        robot_state_publisher,
        bridge,
        create,
        driver,
    ])

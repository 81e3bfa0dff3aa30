"""ros_gz_sim's gz_sim.launch.py over the MuJoCo sim: `gz_args` are `gz sim`'s command line
(`-r -v 4 robot.world`: the web viewer too, as Gazebo's GUI; `-s`: the server alone),
`on_exit_shutdown:=true` ends the launch when the sim exits."""

import shlex

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, OpaqueFunction, Shutdown
from launch.substitutions import LaunchConfiguration


def _sim(context):
    gz_args = LaunchConfiguration("gz_args").perform(context)
    shutdown = LaunchConfiguration("on_exit_shutdown").perform(context).lower() == "true"
    return [ExecuteProcess(cmd=["launcher", "gz", "sim", *shlex.split(gz_args)], name="sim",
                           output="screen", on_exit=Shutdown() if shutdown else None)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("gz_args", default_value="",
                              description="the sim's arguments, as for `gz sim`"),
        DeclareLaunchArgument("on_exit_shutdown", default_value="false",
                              description="end the launch when the sim exits"),
        OpaqueFunction(function=_sim),
    ])

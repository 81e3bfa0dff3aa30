"""ROS 1's command-line tools as the course types them (`rostopic echo`, `rosservice call`,
`roslaunch pkg file.launch`, …), each over launcher's graph with ROS 1's flags and output.

The shell reaches them through launcher's `rostopic`, `roslaunch`, … (compat/bin), which the
setup file puts last on PATH: a real ROS 1 tool earlier on PATH is the one that runs. Each
module here is one tool, with `main(argv) -> int`.
"""

from __future__ import annotations

TOOLS = {  # the tool's name → its module
    "roscore": "launcher.cli.ros1.roscore",
    "roslaunch": "launcher.cli.ros1.roslaunch",
    "rosrun": "launcher.cli.ros1.rosrun",
    "rostopic": "launcher.cli.ros1.rostopic",
    "rosservice": "launcher.cli.ros1.rosservice",
    "rosnode": "launcher.cli.ros1.rosnode",
    "rosmsg": "launcher.cli.ros1.rosmsg",
    "rossrv": "launcher.cli.ros1.rosmsg",
    "rospack": "launcher.cli.ros1.rospack",
    "catkin_make": "launcher.cli.ros1.catkin_make",
    "catkin": "launcher.cli.ros1.catkin",
    "rosbag": "launcher.cli.ros1.rosbag",
}


"""ROS 1's command-line tools as the course types them (`rostopic echo`, `rosservice call`,
`roslaunch pkg file.launch`, …), each over launcher's graph with ROS 1's flags and output.

The shell reaches them through launcher's `rostopic`, `roslaunch`, … (compat/bin), which the
setup file puts last on PATH: a real ROS 1 tool earlier on PATH is the one that runs. Each
module here is one tool, with `main(argv) -> int`; each package, one tool's verbs.
"""

from __future__ import annotations

TOOLS = {  # the tool's name → its module (the tools with verbs: cli/commands.py's ROS1)
    "roscore": "launcher.cli.ros1.roscore",
    "roslaunch": "launcher.cli.ros1.roslaunch",
    "rosrun": "launcher.cli.ros1.rosrun",
    "catkin_make": "launcher.cli.ros1.catkin_make",
    "rostest": "launcher.cli.ros1.rostest",
    "catkin_test_results": "launcher.cli.ros1.catkin_test_results",
}


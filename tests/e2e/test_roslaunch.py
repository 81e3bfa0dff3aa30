"""A ROS 1 workspace as the course writes it, run unchanged: roslaunch XML (`gazebo.launch`
including gazebo_ros's `empty_world.launch` and `spawn.launch`), `<param command="$(find
xacro)/xacro …">`, gazebo_ros's `spawn_model`, the course's rospy publisher.py, and a second
shell's `roslaunch robot_description spawn.launch x:=6 model_name:=second_model` spawning into
the running sim. Real sim, xacro, nodes and Zenoh router.

Expectations follow roslaunch's documented behaviour (wiki.ros.org/roslaunch/XML): `arg`
defaults overridden from the command line, `param command=` taking the command's output, a
node-level `param` private to the node, `include` passing only its `arg` children."""

from __future__ import annotations

import re
import signal
import time

import pytest

from tests.support.course import course_publisher
from tests.support.robots import CLASSIC_ROBOT, WHEEL

DIFF_DRIVE = ("<leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>"
              "<wheelSeparation>0.3</wheelSeparation><wheelDiameter>0.1</wheelDiameter>"
              "<commandTopic>cmd_vel</commandTopic><odometryTopic>odom</odometryTopic>"
              "<odometryFrame>odom</odometryFrame><robotBaseFrame>base_link</robotBaseFrame>"
              "<updateRate>50</updateRate>")
MANIFEST = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.0.1</version><description>{name}
</description><maintainer email="a@b.c">a</maintainer><license>MIT</license></package>
"""
SPAWN = """<launch>
  <arg name="x" default="0"/>
  <arg name="y" default="0"/>
  <arg name="z" default="0.1"/>
  <arg name="model_name" default="robot"/>
  <param name="robot_description"
         command="$(find xacro)/xacro '$(find robot_description)/urdf/robot.xacro'"/>
  <node name="$(arg model_name)_spawner" pkg="gazebo_ros" type="spawn_model" output="screen"
        args="-urdf -param robot_description -model $(arg model_name) -x $(arg x) -y $(arg y) -z $(arg z)"/>
</launch>
"""
GAZEBO = """<launch>
  <include file="$(find gazebo_ros)/launch/empty_world.launch">
    <arg name="world_name" value="$(find world_plugin)/worlds/gazebo.world"/>
    <arg name="paused" value="false"/>
    <arg name="gui" value="false"/>
  </include>
  <include file="$(find robot_description)/launch/spawn.launch"/>
  <node name="publisher" pkg="course_nodes" type="publisher.py" output="screen"/>
</launch>
"""
WORLD = """<?xml version="1.0"?>
<sdf version="1.4">
  <world name="default">
    <plugin name="my_gazebo_world_plugin" filename="libmy_gazebo_world_plugin.so"/>
    <model name="ground"><static>true</static><link name="l"><collision name="c"><geometry>
      <plane><normal>0 0 1</normal><size>100 100</size></plane></geometry></collision></link>
    </model>
  </world>
</sdf>
"""


@pytest.fixture
def catkin(ws):
    """The course's catkin workspace: robot_description, world_plugin, course_nodes."""
    ws.own_bus()
    wheels = WHEEL.format(side="left", y=0.15) + WHEEL.format(side="right", y=-0.15)
    robot = CLASSIC_ROBOT.format(wheels=wheels, params=DIFF_DRIVE).replace(
        '<robot name="bot">', '<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">')
    files = {
        "robot_description/package.xml": MANIFEST.format(name="robot_description"),
        "robot_description/urdf/robot.xacro": robot,
        "robot_description/launch/spawn.launch": SPAWN,
        "world_plugin/package.xml": MANIFEST.format(name="world_plugin"),
        "world_plugin/worlds/gazebo.world": WORLD,
        "world_plugin/launch/gazebo.launch": GAZEBO,
        "course_nodes/package.xml": MANIFEST.format(name="course_nodes"),
        "course_nodes/scripts/publisher.py": course_publisher(),
    }
    for name, text in files.items():
        ws.write(f"catkin_ws/src/{name}", text)
    (ws.root / "catkin_ws/src/course_nodes/scripts/publisher.py").chmod(0o755)
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "catkin_ws/src")
    return ws


def test_the_course_roslaunch_files_spawn_and_drive(catkin):
    proc = catkin.start("launch", "world_plugin", "gazebo.launch", output="gazebo.out")
    try:
        catkin.wait_for_output("spawned 'robot' into world 'default'", 120, "gazebo.out")
        deadline = time.monotonic() + 90
        points: list[tuple[float, float]] = []
        while not points or points[-1][0] < 0.5:  # the course's publisher drives it
            assert time.monotonic() < deadline, catkin.output("gazebo.out")[-3000:]
            time.sleep(0.3)
            points = [(float(x), float(y)) for x, y in re.findall(
                r"X: (-?[\d.e+-]+), Y: (-?[\d.e+-]+)", catkin.output("gazebo.out"))]
        assert "my_gazebo_world_plugin" in catkin.output("gazebo.out")  # said: a C++ library
        second = catkin.run("launch", "robot_description", "spawn.launch", "x:=6",
                            "model_name:=second_model", timeout=120)
        assert second.returncode == 0, second.stdout + second.stderr
        assert "spawned 'second_model' into world 'default'" in second.stdout
        # its robot_description is on the graph's parameter server, for any shell to read
        description = catkin.run("rosparam", "get", "-p", "/robot_description")
        assert '<robot name="bot"' in description.stdout, description.stdout + description.stderr
        state = catkin.run("service", "call", "/gazebo/get_model_state",
                           "gazebo_msgs/srv/GetModelState", "{model_name: second_model}")
        found = re.search(r"x: (-?[\d.e+-]+)", state.stdout)
        # spawned at x = 6; the course's publisher drives every robot on /cmd_vel, this one too
        assert found and 6.0 <= float(found.group(1)) < 7.5, state.stdout
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130


def course_world_plugin_cmake() -> str:
    """world_plugin's CMakeLists.txt as the course prints it (on one line, as its text has)."""
    from tests.support.course import course_text

    text = course_text()
    start = text.index("cmake_minimum_required(VERSION 3.0.2) project(world_plugin)")
    end = text.index("${GAZEBO_LIBRARIES})", start) + len("${GAZEBO_LIBRARIES})")
    return text[start:end] + "\n"


def test_the_course_command_lines_verbatim_in_a_shell(catkin):
    """catkin_make, source devel/setup.bash, roslaunch, a second roslaunch, rostopic echo and
    rosservice call, typed as the course types them in a bash that sourced launcher's setup."""
    import os
    import subprocess

    from tests.support.environment import REPO

    setup = REPO / "hooks" / "setup.bash"
    cmake = catkin.write("catkin_ws/src/world_plugin/CMakeLists.txt", course_world_plugin_cmake())
    script = catkin.root / "catkin_ws/src/course_nodes/scripts/publisher.py"
    script.chmod(0o644)  # as the course's editor leaves it: catkin_make makes it runnable

    def shell(line: str, **kwargs):
        return subprocess.Popen(["bash", "-c", f". {setup} && cd catkin_ws && {line}"],
                                cwd=catkin.root, env=catkin.env, text=True, **kwargs)

    made = shell("catkin_make", stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    said = made.communicate(timeout=120)[0]
    assert made.returncode == 0, said
    line = cmake.read_text().count("\n", 0, cmake.read_text().index("add_library")) + 1
    assert f"{cmake}:{line}: warning: add_library(my_gazebo_world_plugin) of package " \
           "'world_plugin' is C++, left out: C++ Gazebo plugins" in said, said
    assert os.access(script, os.X_OK)
    assert (catkin.root / "catkin_ws/devel/setup.bash").is_file()
    out = open(catkin.root / "course.out", "w")  # noqa: SIM115
    world = shell("source devel/setup.bash && exec roslaunch world_plugin gazebo.launch",
                  stdout=out, stderr=subprocess.STDOUT)
    try:
        catkin.wait_for_output("spawned 'robot' into world 'default'", 120, "course.out")
        second = shell("source devel/setup.bash && roslaunch robot_description spawn.launch "
                       "x:=6 model_name:=second_model", stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT)
        said = second.communicate(timeout=120)[0]
        assert second.returncode == 0 and "spawned 'second_model'" in said, said
        echo = shell("rostopic echo /gazebo/model_states", stdout=subprocess.PIPE)
        try:
            seen = ""
            while "---" not in seen:
                seen += echo.stdout.readline()
            assert "second_model" in seen and "robot" in seen, seen
        finally:
            echo.send_signal(signal.SIGINT)
            echo.wait(20)
        reset = shell("rosservice call /gazebo/reset_world", stdout=subprocess.PIPE,
                      stderr=subprocess.PIPE)
        outs = reset.communicate(timeout=60)
        assert reset.returncode == 0, outs
        assert outs[0] == "", outs  # an empty response prints nothing, as in ROS 1
    finally:
        world.send_signal(signal.SIGINT)
        assert world.wait(60) in (0, 130)

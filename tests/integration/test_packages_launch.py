"""Packages, hooks, nodes, xacro and ROS 2 Python launch files, with real processes."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
import yaml

from launcher import compat
from tests.support.packages import make_tree, manifest

ROBOT_XACRO = """<?xml version="1.0"?>
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:include filename="$(find robot_description)/urdf/wheel.xacro"/>
  <link name="$(arg prefix)base"><visual><geometry><box size="0.3 0.2 0.1"/></geometry></visual></link>
  <xacro:wheel name="$(arg prefix)left" y="0.12"/>
  <xacro:wheel name="$(arg prefix)right" y="-0.12"/>
</robot>
"""
WHEEL_XACRO = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="name y">
    <link name="${name}_wheel"/>
    <joint name="${name}_joint" type="continuous">
      <parent link="base"/><child link="${name}_wheel"/><origin xyz="0 ${y} 0"/>
    </joint>
  </xacro:macro>
</robot>
"""
# A node that reports what it was given: argv, its params files' keys, and its parameters
# (params files and -p values, as YAML).
ECHO_NODE = """
import sys, yaml

def main():
    args = sys.argv[1:]
    print("ARGV", args, flush=True)
    params = {}
    for i, word in enumerate(args):
        if word == "--params-file":
            with open(args[i + 1]) as handle:
                for key, body in yaml.safe_load(handle).items():
                    print("KEY", key, flush=True)
                    params.update(body["ros__parameters"])
        elif word == "-p":
            name, _, text = args[i + 1].partition(":=")
            params[name] = yaml.safe_load(text)
    for key, value in sorted(params.items()):
        print("PARAM", key, type(value).__name__, repr(value)[:60], flush=True)
    desc = params.get("robot_description")
    if desc is not None:
        with open("received_description.xml", "w") as out:
            out.write(desc)
    return 0
"""
BRINGUP_PY = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, TimerAction, LogInfo
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import Command, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from launch_ros.parameter_descriptions import ParameterValue

def generate_launch_description():
    xacro_file = PathJoinSubstitution([FindPackageShare("robot_description"), "urdf", "robot.xacro"])
    return LaunchDescription([
        DeclareLaunchArgument("who", default_value="python"),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource([os.path.join(
                get_package_share_directory("robot_bringup"), "launch", "inner.launch.py")]),
            launch_arguments={"a": "b"}.items()),
        Node(package="robot_application", executable="echo_node", name="rsp", output="screen",
             parameters=[{"robot_description": ParameterValue(
                 Command(["xacro ", xacro_file]), value_type=str)}]),
    ])
"""
INNER_PY = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("a"),
        LogInfo(msg=["inner got a=", LaunchConfiguration("a")]),
    ])
"""


@pytest.fixture
def workspace(ws):
    make_tree(ws.root / "src", {
        "robot_sim/package.xml": manifest("robot_sim"),
        "robot_sim/worlds/arena.xml": "<mujoco/>",
        "robot_sim/hooks/robot_sim.dsv.in":
            "prepend-non-duplicate;MUJOCO_SIM_RESOURCE_PATH;"
            "@CMAKE_INSTALL_PREFIX@/share/@PROJECT_NAME@/worlds\n",
        "robot_sim/hooks/robot_sim.sh.in":
            'ament_prepend_unique_value MUJOCO_SIM_RESOURCE_PATH '
            '"$AMENT_CURRENT_PREFIX/share/@PROJECT_NAME@/worlds"\n',
        "robot_description/package.xml": manifest("robot_description"),
        "robot_description/urdf/robot.xacro": ROBOT_XACRO,
        "robot_description/urdf/wheel.xacro": WHEEL_XACRO,
        "robot_description/urdf/broken.xacro":
            '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:nosuch/></robot>',
        "robot_application/package.xml": manifest("robot_application", extra=(
            '<export><executable name="echo_node" module="robot_app.echo:main"/></export>')),
        "robot_application/robot_app/__init__.py": "",
        "robot_application/robot_app/echo.py": ECHO_NODE,
        "robot_bringup/package.xml": manifest("robot_bringup", ("robot_sim",)),
        "robot_bringup/launch/bringup.launch.py": BRINGUP_PY,
        "robot_bringup/launch/inner.launch.py": INNER_PY,
        "robot_bringup/config/params.yaml": "/**:\n  ros__parameters:\n    speed: 2.5\n",
        "robot_bringup/config/broken.yaml": "a: [1, 2\n",
    })
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    ws.env["LAUNCHER_CACHE_DIR"] = str(ws.root / "cache")
    ws.env.pop("MUJOCO_SIM_RESOURCE_PATH", None)
    return ws


def test_hooks_find_pkg_share_and_node_command_line(workspace):
    workspace.write("robot.launch.yaml", """
    launch:
      - executable:
          cmd: sh -c 'echo RESOURCE=$MUJOCO_SIM_RESOURCE_PATH'
          output: screen
      - push_ros_namespace: {namespace: fleet}
      - set_remap: {from: cmd_vel, to: /fleet/cmd}
      - set_parameter: {name: use_sim_time, value: "true"}
      - node:
          pkg: robot_application
          exec: echo_node
          name: driver
          namespace: r1
          output: screen
          args: --speed 3
          ros_args: --log-level debug
          param:
            - {name: rate, value: 10}
            - {name: rate_text, value: "10"}
            - {name: label, value: "10", type: str}
            - {name: limits, param: [{name: max, value: 1.5}]}
            - {name: robot_description, value: "$(command 'xacro $(find-pkg-share robot_description)/urdf/robot.xacro prefix:=r1_')"}
            - {from: $(find-pkg-share robot_bringup)/config/params.yaml}
          remap: [{from: odom, to: odometry}]
    """)
    result = workspace.run("launch", "robot.launch.yaml")
    out = result.stdout
    assert result.returncode == 0, out + result.stderr
    assert f"RESOURCE={workspace.root / 'src/robot_sim/worlds'}" in out
    (argv_line,) = [line for line in out.splitlines() if "ARGV" in line]
    argv = eval(argv_line.split("ARGV ", 1)[1])  # noqa: S307 - our own test node's repr
    # launch_ros's layout: the node's ros_args after their own --ros-args, then launch_ros's
    # (another --ros-args), set_parameter as -p ahead of the node's files, one params file per
    # param entry (keyed by the node's full name: name and namespace are known), in order
    head = argv[:argv.index("--params-file")]
    assert head == ["--speed", "3", "--ros-args", "--log-level", "debug", "--ros-args",
                    "-r", "__node:=driver", "-r", "__ns:=/fleet/r1", "-p", "use_sim_time:=true"]
    files = [argv[i + 1] for i, w in enumerate(argv) if w == "--params-file"]
    assert len(files) == 6 and files[5].endswith("robot_bringup/config/params.yaml")
    assert out.count("KEY /fleet/r1/driver") == 5 and "KEY /**" in out
    # launch_ros: the scope's remaps (SetRemap), then the node's own (rcl takes the first that
    # matches), as real ros2 launch orders them (tests/fidelity: ros2/xml/remap/*)
    assert argv[-4:] == ["-r", "cmd_vel:=/fleet/cmd", "-r", "odom:=odometry"]
    assert "PARAM rate int 10" in out and "PARAM label str '10'" in out
    assert "PARAM rate_text str '10'" in out  # quoted in YAML: a string, as in launch_ros
    assert "PARAM limits.max float 1.5" in out and "PARAM use_sim_time bool True" in out
    assert "PARAM robot_description str '<?xml" in out
    received = (workspace.root / "received_description.xml").read_text()
    expected = subprocess.run([os.path.join(os.path.dirname(sys.executable), "xacro"),
                               str(workspace.root / "src/robot_description/urdf/robot.xacro"),
                               "prefix:=r1_"], capture_output=True, text=True,
                              env={**workspace.env, "PYTHONPATH": compat.SHIMS},
                              check=True).stdout
    assert received == expected  # in-process xacro == the xacro command, byte for byte
    assert 'link name="r1_left_wheel"' in received


def test_ros2_python_launch_file_runs_unchanged(workspace):
    result = workspace.run("launch", "robot_bringup", "bringup.launch.py")
    out = result.stdout
    assert result.returncode == 0, out + result.stderr
    assert "inner got a=b" in out
    assert "PARAM robot_description str '<?xml" in out


def test_show_args_through_package_includes(workspace):
    workspace.write("top.launch.yaml", """
    launch:
      - include: {file: "$(find-pkg-share robot_bringup)/launch/inner.launch.py"}
    """)
    result = workspace.run("launch", "top.launch.yaml", "--show-args")
    assert result.returncode == 0 and "'a':" in result.stdout


def test_show_args_through_includes_inside_loops(workspace):
    """An include in a `for` or `for_each` body that names its file with the loop's index:
    its arguments are listed (read as the loop's first pass), once."""
    workspace.write("robot_0.launch.yaml", """
    launch:
      - arg: {name: colour, default: red, description: the robot's colour}
    """)
    workspace.write("fleet.launch.yaml", """
    launch:
      - arg: {name: count, default: "2"}
      - for:
          len: $(var count)
          name: i
          children:
            - include: {file: "robot_$(index i).launch.yaml"}
      - for_each:
          values: "{n: 0};{n: 1}"
          children:
            - include: {file: "robot_$(for-var n).launch.yaml"}
    """)
    result = workspace.run("launch", "fleet.launch.yaml", "--show-args")
    assert result.returncode == 0, result.stderr
    assert "from included" in result.stdout and "robot_0.launch.yaml" in result.stdout
    assert result.stdout.count("'colour':") == 1
    assert "the robot's colour" in result.stdout
    assert "could not be listed" not in result.stdout
    assert "encloses this $(index)" not in result.stdout


def test_duplicate_node_names_warn(workspace):
    workspace.write("dup.launch.yaml", """
    launch:
      - node: {pkg: robot_application, exec: echo_node, name: twin}
      - node: {pkg: robot_application, exec: echo_node, name: twin}
    """)
    result = workspace.run("launch", "dup.launch.yaml")
    assert result.returncode == 0
    assert "two nodes are named '/twin': at " in result.stdout
    assert "dup.launch.yaml:2:5" in result.stdout and "dup.launch.yaml:3:5" in result.stdout


@pytest.mark.parametrize("text, expected", [
    ("node: {pkg: robot_application, exec: nosuch}",
     "package 'robot_application' has no executable 'nosuch'; it has: echo_node"),
    ("log: {message: $(exec-in-pkg echo_nod robot_application)}",
     "no executable 'echo_nod' (did you mean 'echo_node'?)"),
    ("log: {message: $(find-pkg-share robot_descriptoin)}",
     "package 'robot_descriptoin' not found (did you mean 'robot_description'"),
    ("node: {pkg: robot_application, exec: echo_node, param: [{from: /no/such.yaml}]}",
     "parameters file '/no/such.yaml' does not exist"),
    ("node: {pkg: robot_application, exec: echo_node, param: [{from: "
     "$(find-pkg-share robot_bringup)/config/broken.yaml}]}",
     "broken.yaml:2:1: parameters file is not valid YAML"),
    ("log: {message: \"$(command 'xacro $(find-pkg-share robot_description)/urdf/broken.xacro')\"}",
     "xacro failed: unknown macro name: xacro:nosuch"),
    ("node: {pkg: robot_application, exec: echo_node, name: bad-name}",
     "bad.launch.yaml:2:5: node name 'bad-name' is not valid in ROS 2: it holds '-'; expected "
     "letters, digits and '_', not starting with a digit (did you mean 'bad_name'?)"),
    ("node: {pkg: robot_application, exec: echo_node, namespace: /fleet//r1}",
     "bad.launch.yaml:2:5: namespace '/fleet//r1' is not valid in ROS 2: an empty part"),
], ids=["node-missing-exec", "exec-in-pkg", "package-not-found", "params-missing",
        "params-invalid", "xacro-fails", "node-name-invalid", "namespace-invalid"])
def test_package_errors(workspace, text, expected):
    workspace.write("bad.launch.yaml", f"launch:\n  - {text}\n")
    result = workspace.run("launch", "bad.launch.yaml")
    message = result.stdout + result.stderr
    assert result.returncode == 1, message
    assert expected in message and "Traceback" not in message


def test_env_command_and_setup_script(workspace):
    result = workspace.run("env", "--shell", "json")
    assert result.returncode == 0, result.stderr
    data = yaml.safe_load(result.stdout)
    assert data["MUJOCO_SIM_RESOURCE_PATH"] == str(workspace.root / "src/robot_sim/worlds")
    exported = workspace.run("env")
    assert "export MUJOCO_SIM_RESOURCE_PATH=" in exported.stdout
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    shell = subprocess.run(["bash", "-c", f". {repo}/hooks/setup.bash && "
                                          "echo \"GOT=$MUJOCO_SIM_RESOURCE_PATH\""],
                           env=workspace.env, capture_output=True, text=True, cwd=workspace.root)
    assert f"GOT={workspace.root / 'src/robot_sim/worlds'}" in shell.stdout, shell.stderr


def test_pkg_commands(workspace):
    listing = workspace.run("pkg", "list").stdout
    assert "robot_sim" in listing and "mujoco_sim" in listing and "builtin" in listing
    share = workspace.run("pkg", "share", "robot_sim").stdout.strip()
    assert share == str(workspace.root / "src/robot_sim")
    prefix = workspace.run("pkg", "prefix", "robot_sim").stdout.strip()
    assert os.path.isdir(os.path.join(prefix, "share", "robot_sim", "worlds"))
    assert "robot_application echo_node" in workspace.run("pkg", "executables").stdout
    assert "<name>robot_sim</name>" in workspace.run("pkg", "xml", "robot_sim").stdout
    missing = workspace.run("pkg", "share", "robot_sm")
    assert missing.returncode == 1 and "did you mean 'robot_sim'" in missing.stderr


def test_pkg_create_makes_a_working_package(workspace):
    created = workspace.run("pkg", "create", "my_bot", "--dependencies", "robot_sim",
                            "--destination-directory", "src")
    assert created.returncode == 0, created.stderr
    result = workspace.run("launch", "my_bot", "my_bot.launch.yaml", "rate:=5", "--duration",
                           "1")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "my_bot_node started with ['--ros-args', '-r', '__node:=my_bot'" in result.stdout
    again = workspace.run("pkg", "create", "my_bot", "--destination-directory", "src")
    assert again.returncode == 2 and "already exists" in again.stderr
    bad = workspace.run("pkg", "create", "My-Bot")
    assert bad.returncode == 2 and "invalid package name 'My-Bot'" in bad.stderr


def test_a_node_of_a_ros2_install_runs_from_its_lib_folder(ws):
    """A package installed by colcon (AMENT_PREFIX_PATH): its executable in lib/<pkg>/."""
    prefix = make_tree(ws.root / "install", {
        "share/ament_index/resource_index/packages/ros_thing": "",
        "share/ros_thing/package.xml": manifest("ros_thing"),
        "lib/ros_thing/talker": "#!/bin/sh\necho \"talking as $*\"\n",
    }, executable=("lib/ros_thing/talker",))
    ws.env["AMENT_PREFIX_PATH"] = str(prefix)
    ws.write("installed.launch.yaml", """
    launch:
      - node: {pkg: ros_thing, exec: talker, name: chatty, output: screen}
    """)
    result = ws.run("launch", "installed.launch.yaml")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "talking as --ros-args -r __node:=chatty" in result.stdout

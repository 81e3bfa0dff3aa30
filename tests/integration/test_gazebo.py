"""A Gazebo user's files and commands, unchanged, on launcher's sim: gz-sim's worlds,
ros_gz_sim_demos' launch file, the `gz` command, the course's model and world plugin.
Real processes: the sim, the bridge and the gz clients on a real Zenoh router."""

from __future__ import annotations

import re
import signal
import time

import pytest

from tests.support.environment import REPO, shared
from tests.support.gazebo import demos_workspace

WORLDS = ("external", "gz-sim", "worlds")  # in ../shared
MODELS = REPO / "packages" / "robot_gazebo" / "models"


@pytest.fixture
def gz_ws(ws):
    ws.own_bus().env["GZ_SIM_RESOURCE_PATH"] = str(MODELS)
    return ws


@pytest.fixture
def gz_worlds(gz_ws):
    """gz_ws, with gz-sim's own example worlds (../shared/external) on the resource path."""
    gz_ws.env["GZ_SIM_RESOURCE_PATH"] += f":{shared(*WORLDS)}"
    return gz_ws


def start_world(ws, world: str, extra: str = ""):
    """`gz sim -r WORLD` from a launch file, as the seed runs it: `gz` on the child's PATH."""
    ws.write("world.launch.yaml", f"""
    launch:
      - executable: {{cmd: "gz sim -v 3 -r {world}", output: screen}}
    {extra}""")
    proc = ws.start("launch", "world.launch.yaml", output="launch.out")
    ws.wait_for_output("timestep 0.001 s, running", 60, "launch.out")
    return proc


def stop(proc) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(30)


def gz(ws, *args: str, timeout: float = 30):
    return ws.run("gz", *args, timeout=timeout)


def odometry_x(ws, vehicle: str) -> float:
    done = gz(ws, "topic", "-e", "-t", f"/model/{vehicle}/odometry", "-n", "1")
    assert done.returncode == 0, done.stderr
    assert "pose {" in done.stdout, done.stdout
    found = re.search(r"position \{\s*x: (-?[\d.e-]+)", done.stdout)
    return float(found.group(1)) if found else 0.0  # the text format leaves out a zero x


def test_diff_drive_sdf_gz_topic_drives_blue_and_not_green(gz_worlds):
    proc = start_world(gz_worlds, "diff_drive.sdf")
    try:
        listed = gz(gz_worlds, "topic", "-l").stdout.split()
        assert "/model/vehicle_blue/cmd_vel" in listed and "/model/vehicle_blue/odometry" in listed
        sent = gz(gz_worlds, "topic", "-t", "/model/vehicle_blue/cmd_vel", "-m", "gz.msgs.Twist",
                  "-p", "linear: {x: 0.5}")
        assert sent.returncode == 0, sent.stderr
        first = odometry_x(gz_worlds, "vehicle_blue")
        time.sleep(2.5)  # odometry is published at 1 Hz in this world
        second = odometry_x(gz_worlds, "vehicle_blue")
        assert second > first + 0.5, (first, second)  # one message drives on, as in Gazebo
        assert abs(odometry_x(gz_worlds, "vehicle_green")) < 0.01
        info = gz(gz_worlds, "topic", "-i", "-t", "/model/vehicle_blue/odometry").stdout
        assert "Publishers [Node, Message Type]:" in info and "gz.msgs.Odometry" in info
        models = gz(gz_worlds, "model", "--list").stdout
        assert "Requesting state for world [diff_drive]" in models
        assert all(f"    - {m}" in models for m in ("ground_plane", "vehicle_blue",
                                                       "vehicle_green"))
        moved = gz(gz_worlds, "service", "-s", "/world/diff_drive/set_pose", "--reqtype",
                   "gz.msgs.Pose", "--reptype", "gz.msgs.Boolean", "--timeout", "2000",
                   "--req", 'name: "ground_plane", position: {z: -1.0}')
        assert moved.returncode == 0 and "data: true" in moved.stdout, moved.stderr
        pose = gz(gz_worlds, "model", "-m", "ground_plane", "-p").stdout
        assert "[0.000000 0.000000 -1.000000]" in pose, pose  # a static model moves too
    finally:
        assert stop(proc) == 130


def test_shapes_and_empty_load_and_the_shapes_cdata_command_moves_the_box(gz_worlds):
    for world in ("empty.sdf", "shapes.sdf"):
        done = gz(gz_worlds, "sim", "-r", "--iterations", "300", world, timeout=60)
        assert done.returncode == 0, done.stdout + done.stderr
        assert "Traceback" not in done.stdout + done.stderr
    proc = start_world(gz_worlds, "shapes.sdf")
    try:
        source = shared(*WORLDS, "shapes.sdf").read_text()  # the command in the world's CDATA
        command = re.search(r"gz service (.*?)'\s*\]\]>", source, re.S).group(1) + "'"
        words = [w.strip("'") for w in re.findall(r"'[^']*'|\S+", command.replace("\\\n", " "))]
        done = gz(gz_worlds, "service", *words)
        assert done.returncode == 0 and "data: true" in done.stdout, done.stdout + done.stderr
        pose = gz(gz_worlds, "model", "-m", "box", "-p").stdout
        z = float(re.search(r"\[(\S+) (\S+) (\S+)\]", pose).group(3))
        assert z > 1.0, pose  # set to 5 m, falling since
    finally:
        assert stop(proc) == 130


def test_the_courses_model_config_box_and_an_sdf_string_spawn(gz_ws):
    ball = ('<sdf version="1.6"><model name="ball"><link name="l"><collision name="c">'
            '<geometry><sphere><radius>0.2</radius></sphere></geometry></collision></link>'
            '</model></sdf>')
    proc = start_world(gz_ws, "empty.sdf", f"""
      - node: {{pkg: ros_gz_sim, exec: create, output: screen,
               args: "-file model://box_model -entity second_model -x 6"}}

      - node:
          pkg: ros_gz_sim
          exec: create
          output: screen
          args: >-
            -z 1 -string '{ball}'""")
    try:
        gz_ws.wait_for_output("spawned 'second_model' into world 'empty'", 60, "launch.out")
        gz_ws.wait_for_output("spawned 'ball' into world 'empty'", 60, "launch.out")
        models = gz(gz_ws, "model", "--list").stdout
        assert "    - second_model" in models and "    - ball" in models, models
        pose = gz(gz_ws, "model", "-m", "second_model", "-p").stdout
        assert "[6.000000" in pose, pose
    finally:
        assert stop(proc) == 130


COURSE_WORLD = """<?xml version="1.0"?>
<sdf version="1.4">
  <world name="default">
    <plugin name="my_gazebo_world_plugin" filename="libmy_gazebo_world_plugin.so"/>
  </world>
</sdf>
"""


def test_the_courses_cpp_world_plugin_is_one_warning_and_the_world_runs(gz_ws):
    gz_ws.write("gazebo.world", COURSE_WORLD)
    done = gz(gz_ws, "sim", "-v", "3", "-r", "--iterations", "200", "gazebo.world", timeout=60)
    text = done.stdout + done.stderr
    assert done.returncode == 0, text
    lines = [line for line in text.splitlines() if "libmy_gazebo_world_plugin.so" in line]
    assert len(lines) == 1 and "is a C++ library: launcher loads Python plugins only" in \
        lines[0] and "gazebo.world:4" in lines[0], text
    assert "world 'default'" in text




def test_ros_gz_sim_demos_diff_drive_launch_runs_unchanged_and_its_bridge_drives(gz_worlds):
    demos_workspace(gz_worlds)
    proc = gz_worlds.start("launch", "ros_gz_sim_demos", "diff_drive.launch.py", "rviz:=false",
                       output="demo.out")
    try:
        gz_worlds.wait_for_output("bridging 4 of 4 entries", 60, "demo.out")
        start = odometry_x(gz_worlds, "vehicle_blue")  # waits for the sim's odometry
        sent = gz_worlds.run("topic", "pub", "/model/vehicle_blue/cmd_vel",
                         "geometry_msgs/msg/Twist", "{linear: {x: 0.5}}", "-r", "10", "-t",
                         "25", timeout=30)  # the ROS side of the bridge
        assert sent.returncode == 0, sent.stderr
        ros = gz_worlds.run("topic", "echo", "/model/vehicle_blue/odometry",
                        "nav_msgs/msg/Odometry", "--once", "--field", "pose.pose.position.x")
        assert float(ros.stdout.split()[0]) > start + 0.5, (start, ros.stdout)
        assert "[ERROR]" not in gz_worlds.output("demo.out")
    finally:
        assert stop(proc) == 130


def test_ros_gz_sim_demos_with_rviz_open_a_foxglove_layout_and_the_rest_runs(gz_worlds):
    """rviz:=true (the demo's default): rviz2 converts the demo's config into a Foxglove
    layout, starts the graph's foxglove bridge, says where to connect and what to import, and
    ends with the launch, its bridge with it."""
    demos = demos_workspace(gz_worlds)
    (demos / "rviz").symlink_to(shared("external", "ros_gz_sim_demos", "rviz"))
    gz_worlds.env["HOME"] = str(gz_worlds.root)  # (the layout goes to ~/.launcher/layouts)
    done = gz_worlds.run("launch", "ros_gz_sim_demos", "diff_drive.launch.py", "--duration",
                         "8", timeout=120)
    out = done.stdout + done.stderr
    assert "ERROR" not in out, out
    assert re.search(r"connect Foxglove \(the app, or app\.foxglove\.dev\) to "
                     r"ws://127\.0\.0\.1:8765/\?token=\S+", out), out
    layout = gz_worlds.root / ".launcher" / "layouts" / "diff_drive.json"
    assert f"import the layout {layout}" in out
    assert "/model/vehicle_blue/odometry" in layout.read_text()
    assert "bridging 4 of 4 entries" in out
    assert done.returncode == 0, out  # every process, the bridge rviz2 started too, ended
    assert "Traceback" not in out


# --- bad input ----------------------------------------------------------------------------
@pytest.mark.parametrize("args, expected", [
    (["tpoic", "-l"], "gz: unknown command 'tpoic' (did you mean 'topic'?)"),
    (["topic", "--ehco", "-t", "/x"], "unrecognized arguments: --ehco (did you mean '--echo'?)"),
    (["topic", "-t", "/x", "-m", "gz.msgs.Twist", "-p", "linear: {x: 0.5"],
     "-p: expected '}' at the end of: linear: {x: 0.5"),
    (["topic", "-t", "/x", "-m", "gz.msgs.Twist", "-p", "linaer: {x: 0.5}"],
     "does not fit gz.msgs.Twist: linaer: gz.msgs.Twist has no field 'linaer' "
     "(did you mean 'linear'?)"),
    (["topic", "-t", "/x", "-m", "gz.msgs.Twist", "-p", "linear: {x: \"fast\"}"],
     "expected float64, got 'fast'"),
    (["topic", "-t", "/x", "-m", "gz.msgs.Twits", "-p", "linear: {x: 1}"],
     "unknown sim type 'gz.msgs.Twits' (did you mean 'gz.msgs.Twist'"),
    (["service", "-s", "/world/w/control", "--reqtype", "gz.msgs.WorldControl",
      "--reptype", "gz.msgs.Boolean", "--req", "pause: ture"], "expected bool, got 'ture'"),
    (["model"], "give --list or -m NAME"),
])
def test_gz_usage_errors_are_one_line_with_did_you_mean(gz_ws, args, expected):
    done = gz(gz_ws, *args)
    assert done.returncode == 2, done.stdout + done.stderr
    assert expected in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and done.stderr.count("\n") == 1


@pytest.mark.parametrize("text, expected", [
    ('<sdf version="1.6"><world name="w"><model name="m"></world></sdf>',
     "bad.sdf:1:54: not valid XML: mismatched tag"),
    ('<sdf version="1.3"><world name="w"/></sdf>', "unsupported SDF version '1.3'"),
    ('<sdf version="1.6"><world name="w"><include><uri>model://nope</uri></include></world>'
     "</sdf>", "model 'nope' (model://nope) not found; searched: "),
])
def test_a_bad_world_is_one_clear_error_exit_1_and_nothing_left(gz_ws, text, expected):
    gz_ws.write("bad.sdf", text)
    done = gz(gz_ws, "sim", "-r", "bad.sdf", timeout=60)
    assert done.returncode == 1, done.stdout + done.stderr
    assert expected in done.stderr and "Traceback" not in done.stderr, done.stderr


def test_gz_is_on_launched_processes_path_last_so_a_real_gazebo_wins(gz_ws):
    fake = gz_ws.root / "realgz"
    fake.mkdir()
    (fake / "gz").write_text("#!/bin/sh\necho REAL GAZEBO $@\n")
    (fake / "gz").chmod(0o755)
    gz_ws.write("which.launch.yaml", """
    launch:
      - executable: {cmd: "gz sim --version-of-mine", output: screen}
    """)
    real = gz_ws.start("launch", "which.launch.yaml", output="real.out",
                       env={"PATH": f"{fake}:{gz_ws.env['PATH']}"})
    assert real.wait(60) == 0
    assert "REAL GAZEBO sim --version-of-mine" in gz_ws.output("real.out")


ARM_SDF = """<?xml version="1.0"?>
<sdf version="1.9">
  <model name="arm">
    <static>false</static>
    <link name="base"><inertial><mass>50</mass></inertial>
      <collision name="c"><geometry><box><size>0.4 0.4 0.1</size></box></geometry></collision>
    </link>
    <link name="upper"><pose>0 0 0.2 0 0 0</pose><inertial><mass>0.5</mass></inertial>
      <collision name="c"><pose>0.2 0 0 0 0 0</pose>
        <geometry><box><size>0.4 0.05 0.05</size></box></geometry></collision>
    </link>
    <joint name="shoulder" type="revolute"><parent>base</parent><child>upper</child>
      <axis><xyz>0 0 1</xyz><limit><lower>-3</lower><upper>3</upper></limit></axis></joint>
    <plugin filename="gz-sim-joint-state-publisher-system"
            name="gz::sim::systems::JointStatePublisher"/>
  </model>
</sdf>
"""


def test_spawn_model_minus_j_starts_a_joint_at_its_position(gz_ws):
    """gazebo_ros's spawn_model -J JOINT POSITION: the model's joint starts there (ROS 1's
    spawn_model sets it through /gazebo/set_model_configuration once the model is in); a
    joint the model lacks fails the spawn, saying which joints it has."""
    gz_ws.write("arm.sdf", ARM_SDF)
    proc = start_world(gz_ws, "empty.sdf")
    try:
        done = gz_ws.run("run", "gazebo_ros", "spawn_model", "-sdf", "-file",
                         str(gz_ws.root / "arm.sdf"), "-model", "arm", "-J", "shoulder", "0.7",
                         timeout=60)
        assert done.returncode == 0, done.stdout + done.stderr
        state = gz(gz_ws, "topic", "-e", "-t", "/world/empty/model/arm/joint_state", "-n", "1")
        position = re.search(r'name: "shoulder".*?position: (-?[\d.e-]+)', state.stdout,
                             re.DOTALL)
        assert position and float(position.group(1)) == pytest.approx(0.7, abs=0.01), \
            state.stdout
        wrong = gz_ws.run("run", "gazebo_ros", "spawn_model", "-sdf", "-file",
                          str(gz_ws.root / "arm.sdf"), "-model", "arm2", "-J", "elbow", "1",
                          timeout=60)
        assert wrong.returncode == 1
        assert "no joint named 'elbow'; its joints: shoulder" in wrong.stderr, wrong.stderr
        assert "Traceback" not in wrong.stderr
    finally:
        assert stop(proc) == 130

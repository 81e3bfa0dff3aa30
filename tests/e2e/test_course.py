"""The course's ROS 1 workflow on the demo stack: its publisher.py (rospy), copied verbatim
from the course text, runs as a package executable and drives the robot; its `/gazebo/*`
commands work with the course's own message text through gazebo_ros's interface node.
Real sim, bridge, robot_state_publisher, create and nodes on a real Zenoh router."""

from __future__ import annotations

import re
import signal
import subprocess
import time

import pytest

from tests.support.course import course_publisher, course_text
from tests.support.environment import REPO

LAUNCH = REPO / "launch_files" / "robot.launch.yaml"






def course_set_model_state() -> str:
    """The message text of the course's `rostopic pub /gazebo/set_model_state …`."""
    found = re.search(r'rostopic pub /gazebo/set_model_state gazebo_msgs/ModelState "(.*?)"',
                      course_text(), re.S)
    assert found is not None
    return found.group(1)


@pytest.fixture
def course(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = f"{REPO / 'packages'}:{ws.root / 'ws'}"
    script = ws.write("ws/course_nodes/scripts/publisher.py", course_publisher())
    script.chmod(0o755)
    ws.write("ws/course_nodes/package.xml", """
    <?xml version="1.0"?>
    <package format="2"><name>course_nodes</name><version>0.0.1</version>
    <description>The course's nodes</description><maintainer email="a@b.c">a</maintainer>
    <license>MIT</license></package>
    """)
    ws.write("course.launch.yaml", f"""
    launch:
      - include: {{file: "{LAUNCH}", arg: [{{name: drive, value: "false"}}]}}
      - node: {{pkg: gazebo_ros, exec: gazebo_ros_api, output: screen}}
    """)
    proc = ws.start("launch", "course.launch.yaml", output="launch.out")
    ws.wait_for_output("spawned 'my_robot' into world 'robot'", 90, "launch.out")
    ws.wait_for_output("serving /gazebo/* for world 'robot'", 60, "launch.out")
    yield ws
    proc.send_signal(signal.SIGINT)
    assert proc.wait(60) == 130


def test_the_course_publisher_drives_the_robot_and_prints_x_and_y(course):
    node = course.start("run", "course_nodes", "publisher.py", output="publisher.out")
    try:
        deadline = time.monotonic() + 90
        points: list[tuple[float, float]] = []
        while not points or points[-1][0] < 1.0:  # driven past a metre (the course prints
            assert time.monotonic() < deadline, course.output("publisher.out")  # raw floats:
            time.sleep(0.2)  # "X: 1.5e-05" is not past it)
            points = [(float(x), float(y)) for x, y in re.findall(
                r"X: (-?[\d.e+-]+), Y: (-?[\d.e+-]+)", course.output("publisher.out"))]
        assert len(points) > 10 and points[-1][0] > points[0][0] + 0.5
        assert points[-1][1] > points[0][1]  # angular.z 0.2: it turns left
    finally:
        node.send_signal(signal.SIGINT)
        assert node.wait(20) == 0, course.output("publisher.out")  # ROSInterruptException


def call(ws, service: str, type_name: str, request: str = "{}") -> str:
    done = ws.run("service", "call", service, type_name, request)
    assert done.returncode == 0, done.stderr
    return done.stdout


def field(text: str, name: str) -> float:
    return float(re.search(rf"{name}: (-?[\d.e+-]+)", text).group(1))


def test_the_course_gazebo_commands_with_the_course_text(course):
    box = ("<sdf version='1.6'><model name='unit_box'><link name='link'><inertial><mass>1"
           "</mass></inertial><collision name='c'><geometry><box><size>1 1 1</size></box>"
           "</geometry></collision><visual name='v'><geometry><box><size>1 1 1</size></box>"
           "</geometry></visual></link></model></sdf>")
    spawned = call(course, "/gazebo/spawn_sdf_model", "gazebo_msgs/srv/SpawnModel",
                   f'{{model_name: unit_box, model_xml: "{box}", initial_pose: {{position: '
                   f'{{x: 2.0, y: -2.0, z: 0.5}}}}}}')
    assert "success: true" in spawned, spawned
    call(course, "/gazebo/pause_physics", "std_srvs/srv/Empty")
    # the course's own command line, in a bash that sourced launcher's setup file: rostopic
    # pub latches the message and stays until Ctrl-C, as ROS 1's does
    sent = subprocess.Popen(["bash", "-c", f". {REPO / 'hooks' / 'setup.bash'} && exec rostopic "
                             "pub /gazebo/set_model_state gazebo_msgs/ModelState "
                             f'"{course_set_model_state()}"'], cwd=course.root, env=course.env,
                            stdout=subprocess.PIPE, text=True)
    try:
        assert "publishing and latching message" in sent.stdout.readline()
        deadline = time.monotonic() + 10
        while True:
            state = call(course, "/gazebo/get_model_state", "gazebo_msgs/srv/GetModelState",
                         "{model_name: unit_box}")
            if field(state, "x") == pytest.approx(10.0) or time.monotonic() > deadline:
                break
            time.sleep(0.2)
    finally:
        sent.send_signal(signal.SIGINT)
        assert sent.wait(20) == 0
    assert (field(state, "x"), field(state, "y"), field(state, "z")) == \
        pytest.approx((10.0, 20.0, 1.0))  # paused: it stays where the course put it
    physics = call(course, "/gazebo/get_physics_properties",
                   "gazebo_msgs/srv/GetPhysicsProperties")
    assert "pause: true" in physics and field(physics, "time_step") == 0.001
    reset = subprocess.run(["bash", "-c", f". {REPO / 'hooks' / 'setup.bash'} && rosservice "
                            "call /gazebo/reset_world"], cwd=course.root, env=course.env,
                           capture_output=True, text=True, timeout=60)  # the course's words
    assert (reset.returncode, reset.stdout) == (0, ""), reset.stderr
    state = call(course, "/gazebo/get_model_state", "gazebo_msgs/srv/GetModelState",
                 "{model_name: unit_box}")
    assert (field(state, "x"), field(state, "y")) == pytest.approx((2.0, -2.0))
    physics = call(course, "/gazebo/get_physics_properties",
                   "gazebo_msgs/srv/GetPhysicsProperties")
    assert "pause: true" in physics  # a reset keeps a paused world paused, as Gazebo does
    call(course, "/gazebo/unpause_physics", "std_srvs/srv/Empty")
    states = course.run("topic", "echo", "/gazebo/model_states", "--once", "--field", "name",
                        timeout=30)
    assert "- unit_box" in states.stdout and "- my_robot" in states.stdout, states.stderr
    deleted = call(course, "/gazebo/delete_model", "gazebo_msgs/srv/DeleteModel",
                   "{model_name: unit_box}")
    assert "success: true" in deleted
    world = call(course, "/gazebo/get_world_properties", "gazebo_msgs/srv/GetWorldProperties")
    assert "my_robot" in world and "unit_box" not in world
    missing = call(course, "/gazebo/get_model_state", "gazebo_msgs/srv/GetModelState",
                   "{model_name: unit_box}")
    assert "success: false" in missing and "model [unit_box] does not exist" in missing

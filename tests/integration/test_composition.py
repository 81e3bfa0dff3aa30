"""Composable nodes: `node_container`, `load_composable_node` and launch_ros's Python actions
load components into launcher's component container, a real process on a real Zenoh router;
what the nodes publish is read by `launcher topic echo`, another process. Each bad input of
issue 17 is a test, and each test checks that nothing it started is left."""

from __future__ import annotations

import signal
import time

import pytest

from tests.support.environment import REPO

COMPONENTS = '''
import time
from launcher.bus.node import Node


def Talker():
    node = Node("talker")
    word = node.declare_parameter("word", "hello").value
    publisher = node.create_publisher("std_msgs/msg/String", "chatter")
    message = node.message("std_msgs/msg/String", data=f"{node.fully_qualified_name} {word}")
    node.create_timer(0.05, lambda: publisher.publish(message))
    return node


def Raiser():
    raise RuntimeError("no robot here")


def Blocker():
    node = Node("blocker")
    node.create_timer(0.05, lambda: time.sleep(3600))
    return node


def Crasher():
    node = Node("crasher")
    node.create_timer(0.3, lambda: 1 / 0)
    return node
'''

RCLPY_COMPONENT = '''
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__("rclpy_talker")
        self.publisher = self.create_publisher(String, "chatter", 10)
        self.declare_parameter("word", "rclpy")
        self.create_timer(0.05, self.tick)

    def tick(self):
        word = self.get_parameter("word").value
        self.publisher.publish(String(data=f"{self.get_fully_qualified_name()} {word}"))
'''


@pytest.fixture
def comp(ws):
    """A workspace on its own bus with the package `testcomp`: components declared in
    package.xml (launcher nodes) and in setup.cfg's rclpy_components (an rclpy node)."""
    ws.own_bus()
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "ws")
    ws.write("ws/testcomp/package.xml", """
    <?xml version="1.0"?>
    <package format="3"><name>testcomp</name><version>0.1.0</version>
      <description>components</description><maintainer email="a@b.c">a</maintainer>
      <license>MIT</license>
      <export>
        <component plugin="testcomp::Talker" module="testcomp.parts:Talker"/>
        <component plugin="testcomp::Raiser" module="testcomp.parts:Raiser"/>
        <component plugin="testcomp::Blocker" module="testcomp.parts:Blocker"/>
        <component plugin="testcomp::Crasher" module="testcomp.parts:Crasher"/>
      </export>
    </package>
    """)
    ws.write("ws/testcomp/setup.cfg", """
    [options.entry_points]
    rclpy_components =
        testcomp::RclpyTalker = testcomp.rclpy_parts:Talker
    """)
    ws.write("ws/testcomp/testcomp/__init__.py", "")
    ws.write("ws/testcomp/testcomp/parts.py", COMPONENTS)
    ws.write("ws/testcomp/testcomp/rclpy_parts.py", RCLPY_COMPONENT)
    return ws


def echo(ws, topic: str) -> str:
    done = ws.run("topic", "echo", topic, "--once", "-f", "--field", "data", timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout.removesuffix("---\n").strip()


def stop(proc, sig: int = signal.SIGINT) -> int:
    proc.send_signal(sig)
    return proc.wait(30)


def container(nodes: str, name: str = "box", namespace: str = "/") -> str:
    return f"""
    launch:
    - node_container:
        pkg: rclcpp_components
        exec: component_container
        name: {name}
        namespace: {namespace}
        output: screen
        composable_node:
{nodes}
    """


def test_composable_nodes_take_names_namespaces_remaps_and_parameters(comp):
    comp.write("c.launch.yaml", container("""
          - pkg: testcomp
            plugin: testcomp::Talker
            name: first
            namespace: a
            param: [{name: word, value: bonjour}]
            remap: [{from: chatter, to: talk}]
          - {pkg: testcomp, plugin: testcomp::Talker, namespace: b}
          - pkg: testcomp
            plugin: testcomp::RclpyTalker
            namespace: c
            param: [{name: word, value: hej}]
            extra_arg: [{name: use_intra_process_comms, value: "true"}]
    """))
    launch = comp.start("launch", "c.launch.yaml")
    try:
        comp.wait_for_output("Loaded node '/c/rclpy_talker' in container '/box'", 60)
        assert "Loaded node '/a/first' in container '/box'" in comp.output()
        assert echo(comp, "/a/talk") == "/a/first bonjour"
        assert echo(comp, "/b/chatter") == "/b/talker hello"
        assert echo(comp, "/c/chatter") == "/c/rclpy_talker hej"
        nodes = comp.run("node", "list")
        for name in ("/box", "/a/first", "/b/talker", "/c/rclpy_talker"):
            assert name in nodes.stdout.split(), nodes.stdout
        # one process for the three: the container
        assert len([p for p in launch_children(launch) if "component_container" in p]) == 1
    finally:
        assert stop(launch) == 130


def launch_children(proc) -> list[str]:
    import psutil

    return [" ".join(p.cmdline()) for p in psutil.Process(proc.pid).children(recursive=True)]


def test_an_unknown_plugin_is_a_located_error_with_what_the_package_offers(comp):
    comp.write("c.launch.yaml", container("""
          - {pkg: testcomp, plugin: testcomp::Talkr, name: wrong}
          - {pkg: testcomp, plugin: testcomp::Talker, name: right}
    """))
    done = comp.run("launch", "c.launch.yaml", "--duration", "4", timeout=60)
    assert done.returncode == 1
    assert "c.launch.yaml:10:9: package 'testcomp' has no component 'testcomp::Talkr' " \
           "(did you mean 'testcomp::Talker' or 'testcomp::RclpyTalker' or " \
           "'testcomp::Blocker'?); it offers: testcomp::Blocker, testcomp::Crasher, " \
           "testcomp::Raiser, testcomp::RclpyTalker, testcomp::Talker" \
           in done.stdout + done.stderr, done.stdout + done.stderr
    assert "Loaded node '/right' in container '/box'" in done.stdout  # the rest loaded
    assert "Traceback" not in done.stdout + done.stderr


def test_two_nodes_with_one_name_in_a_container_are_refused(comp):
    comp.write("c.launch.yaml", container("""
          - {pkg: testcomp, plugin: testcomp::Talker, name: same, namespace: n}
          - {pkg: testcomp, plugin: testcomp::RclpyTalker, name: same, namespace: /n}
    """))
    done = comp.run("launch", "c.launch.yaml", "--duration", "4", timeout=60)
    out = done.stdout + done.stderr
    assert done.returncode == 1, out
    assert "Loaded node '/n/same' in container '/box'" in out
    assert "c.launch.yaml:11:9: composable node '/n/same' (testcomp::RclpyTalker) was not " \
           "loaded into '/box': a node named '/n/same' is loaded in this container already " \
           "(unique id 1)" in out, out


def test_a_constructor_that_raises_is_reported_and_the_others_run(comp):
    comp.write("c.launch.yaml", container("""
          - {pkg: testcomp, plugin: testcomp::Raiser, name: doomed}
          - {pkg: testcomp, plugin: testcomp::Talker, name: fine}
    """))
    launch = comp.start("launch", "c.launch.yaml")
    try:
        comp.wait_for_output("Loaded node '/fine' in container '/box'", 60)
        assert "c.launch.yaml:10:9: composable node '/doomed' (testcomp::Raiser) was not " \
               "loaded into '/box': testcomp::Raiser: its constructor raised RuntimeError: " \
               "no robot here" in comp.output() + comp.output("stderr.txt")
        assert echo(comp, "/chatter") == "/fine hello"
    finally:
        assert stop(launch) == 130
    assert "Traceback" not in comp.output() + comp.output("stderr.txt")


def test_a_blocked_callback_stops_only_its_own_component(comp):
    """Each component is spun by its own thread: the blocker's timer never returns, the
    talker beside it keeps publishing; the container still stops on Ctrl-C (the blocked
    thread is abandoned, its entities undeclared) and nothing is left."""
    comp.write("c.launch.yaml", container("""
          - {pkg: testcomp, plugin: testcomp::Blocker}
          - {pkg: testcomp, plugin: testcomp::Talker}
    """))
    launch = comp.start("launch", "c.launch.yaml")
    try:
        comp.wait_for_output("Loaded node '/talker' in container '/box'", 60)
        time.sleep(0.5)  # the blocker is inside its callback by now
        for _ in range(3):
            assert echo(comp, "/chatter") == "/talker hello"
    finally:
        assert stop(launch) == 130
    assert "/blocker (testcomp::Blocker) did not stop within 2 s (a callback blocks)" in \
        comp.output()


def test_a_callback_that_raises_unloads_that_node_only(comp):
    comp.write("c.launch.yaml", container("""
          - {pkg: testcomp, plugin: testcomp::Crasher}
          - {pkg: testcomp, plugin: testcomp::Talker}
    """))
    launch = comp.start("launch", "c.launch.yaml")
    try:
        comp.wait_for_output("/crasher (testcomp::Crasher) raised in a callback: "
                             "ZeroDivisionError: division by zero; unloaded it", 60)
        assert echo(comp, "/chatter") == "/talker hello"
        nodes = comp.run("node", "list").stdout.split()
        assert "/talker" in nodes and "/crasher" not in nodes, nodes
    finally:
        assert stop(launch) == 130


def test_load_into_a_running_container_and_into_one_that_does_not_exist(comp):
    comp.env["LAUNCHER_LOAD_TIMEOUT"] = "2"
    comp.write("c.launch.yaml", """
    launch:
    - node_container: {pkg: rclcpp_components, exec: component_container, name: box,
                       namespace: r}
    - load_composable_node:
        target: /r/box
        composable_node: [{pkg: testcomp, plugin: testcomp::Talker, name: later}]
    - load_composable_node:
        target: /r/bxo
        composable_node: [{pkg: testcomp, plugin: testcomp::Talker, name: lost}]
    """)
    launch = comp.start("launch", "c.launch.yaml")
    try:
        comp.wait_for_output("Loaded node '/later' in container '/r/box'", 60)
        text = comp.wait_for_output("no container named '/r/bxo' answered within 2 s "
                                    "(did you mean '/r/box'?); containers running: /r/box",
                                    30)
        assert "composable node '/lost' (testcomp::Talker) was not loaded into '/r/bxo'" \
            in text
        assert echo(comp, "/chatter") == "/later hello"
    finally:
        assert stop(launch) == 130


def test_load_into_a_container_that_has_exited_fails_at_once(comp):
    """The container here is a program that exits at once: the load is not waited for."""
    script = comp.write("ws/testcomp/lib/testcomp/quitter", "#!/bin/sh\nexit 3\n")
    script.chmod(0o755)
    comp.write("c.launch.yaml", """
    launch:
    - node_container:
        pkg: testcomp
        exec: quitter
        name: box
        composable_node: [{pkg: testcomp, plugin: testcomp::Talker}]
    """)
    started = time.monotonic()
    done = comp.run("launch", "c.launch.yaml", timeout=60)
    out = done.stdout + done.stderr
    assert done.returncode == 1
    assert "composable node 'testcomp::Talker' (testcomp::Talker) was not loaded into " \
           "'/box': the container '/box' exited before it loaded it" in out, out
    assert time.monotonic() - started < 25  # not the 30 s wait for a container elsewhere


def test_python_launch_files_use_launch_ros_composition(comp):
    comp.write("c.launch.py", """
    from launch import LaunchDescription
    from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
    from launch_ros.descriptions import ComposableNode


    def generate_launch_description():
        box = ComposableNodeContainer(
            name='box', namespace='', package='rclcpp_components',
            executable='component_container_mt', output='screen',
            composable_node_descriptions=[
                ComposableNode(package='testcomp', plugin='testcomp::Talker', name='one',
                               parameters=[{'word': 'python'}],
                               remappings=[('chatter', 'said')],
                               extra_arguments=[{'use_intra_process_comms': True}]),
            ])
        more = LoadComposableNodes(target_container=box, composable_node_descriptions=[
            ComposableNode(package='testcomp', plugin='testcomp::RclpyTalker', name='two')])
        return LaunchDescription([box, more])
    """)
    launch = comp.start("launch", "c.launch.py")
    try:
        comp.wait_for_output("Loaded node '/two' in container '/box'", 60)
        assert echo(comp, "/said") == "/one python"
        assert echo(comp, "/chatter") == "/two rclpy"
    finally:
        assert stop(launch) == 130


def test_the_builtin_nodes_load_as_components(comp):
    """robot_state_publisher, the bridge and the demo's driver, from their packages' plugin
    names, in one container; the robot description comes from real xacro."""
    comp.env["LAUNCHER_PACKAGE_PATH"] += ":" + str(REPO / "packages")
    comp.write("c.launch.yaml", container("""
          - pkg: robot_state_publisher
            plugin: robot_state_publisher::RobotStatePublisher
            param:
              - name: robot_description
                value: "$(command 'xacro $(find-pkg-share robot_description)/urdf/robot.xacro')"
          - pkg: robot_application
            plugin: robot_application::Driver
            param: [{name: speed, value: 0.25}]
    """))
    launch = comp.start("launch", "c.launch.yaml")
    try:
        comp.wait_for_output("Loaded node '/driver' in container '/box'", 60)
        assert "<robot" in echo(comp, "/robot_description")
        twist = comp.run("topic", "echo", "/cmd_vel", "--once", "--field", "linear.x",
                         timeout=60)
        assert twist.stdout.removesuffix("---\n").strip() == "0.25", twist.stdout
    finally:
        assert stop(launch) == 130


def test_a_container_without_a_name_is_refused_before_it_starts(comp):
    comp.write("c.launch.yaml", """
    launch:
    - node_container:
        pkg: rclcpp_components
        exec: component_container
        composable_node: [{pkg: testcomp, plugin: testcomp::Talker}]
    """)
    done = comp.run("launch", "c.launch.yaml", timeout=60)
    out = done.stdout + done.stderr
    assert done.returncode == 1, out
    assert "c.launch.yaml:2:3: node_container needs a 'name': composable nodes are loaded " \
           "into it by name" in out, out
    assert "process started" not in out and "Traceback" not in out

"""A robot on several computers, for real: three OpenSSH hosts (robot1, robot2, robot3), each
in a network namespace of its own with its own host key, hostname and run folder
(tests/support/sshd.py), reached from a launching host through the user's own ssh and its
config. Launch files in every syntax put a talker on robot1, a relay on robot2 and a listener
on robot3, talking across the hosts on the launch's graph; after every end, the launcher's
SIGKILL and a cut link included, nothing is left on any host. Each bad connection is said at
its place, with nothing left behind."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import psutil
import pytest

from tests.support.packages import make_tree, manifest
from tests.support.processes import launcher_argv
from tests.support.sshd import SshHosts, require

HOSTS = ("robot1", "robot2", "robot3")
LEFT_WAIT = 3.0  # s: 2 s for the launch's processes, and the hosts' routers' 0.5 s linger

TALKER1 = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import String
rospy.init_node("talker")
pub = rospy.Publisher("/a", String, queue_size=10)
rate = rospy.Rate(5)
while not rospy.is_shutdown():
    pub.publish(String(data="hello across"))
    rate.sleep()
"""
LISTENER1 = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import String
rospy.init_node("listener")
rospy.Subscriber("/b", String, lambda m: print("heard", m.data, flush=True))
rospy.spin()
"""
PARAMS1 = """#!/usr/bin/env python3
import rospy
rospy.init_node("reader")
print("greeting:", rospy.get_param("/greeting"), "rate:", rospy.get_param("~rate"), flush=True)
"""
TALKER2 = """#!/usr/bin/env python3
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node("talker")
pub = node.create_publisher(String, "/a", 10)
node.create_timer(0.2, lambda: pub.publish(String(data="hello across")))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""
LISTENER2 = """#!/usr/bin/env python3
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node("listener")
node.create_subscription(String, "/b", lambda m: print("heard", m.data, flush=True), 10)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""

ROS1 = """<launch>
  <machine name="robot1" address="robot1"/>
  <machine name="robot2" address="robot2"/>
  <machine name="robot3" address="robot3"/>
  <node pkg="chat" type="talker1.py" name="talker" machine="robot1"/>
  <node pkg="topic_tools" type="relay" name="relay" args="/a /b" machine="robot2"/>
  <node pkg="chat" type="listener1.py" name="listener" machine="robot3" output="screen"/>
</launch>
"""
ROS2_XML = """<launch extensions="launcher">
  <machine name="robot1" address="robot1"/>
  <machine name="robot2" address="robot2"/>
  <machine name="robot3" address="robot3"/>
  <node pkg="chat" exec="talker2.py" name="talker" machine="robot1"/>
  <node pkg="topic_tools" exec="relay" name="relay" args="/a /b" machine="robot2"/>
  <group machine="robot3">
    <node pkg="chat" exec="listener2.py" name="listener" output="screen"/>
  </group>
</launch>
"""
ROS2_YAML = """extensions: [launcher]
launch:
  - machine: {name: robot1, address: robot1}
  - machine: {name: robot2, address: robot2}
  - machine: {name: robot3, address: robot3}
  - node: {pkg: chat, exec: talker2.py, name: talker, machine: robot1}
  - node: {pkg: topic_tools, exec: relay, name: relay, args: "/a /b", machine: robot2}
  - group:
      machine: robot3
      children:
        - node: {pkg: chat, exec: listener2.py, name: listener, output: screen}
"""
ROS2_PY = """from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node
from launcher.api.extensions import Machine, PushMachine


def generate_launch_description():
    return LaunchDescription([
        *(Machine(name=name, address=name) for name in ("robot1", "robot2", "robot3")),
        GroupAction([PushMachine("robot1"),
                     Node(package="chat", executable="talker2.py", name="talker")]),
        GroupAction([PushMachine("robot2"),
                     Node(package="topic_tools", executable="relay", name="relay",
                          arguments=["/a", "/b"])]),
        GroupAction([PushMachine("robot3"),
                     Node(package="chat", executable="listener2.py", name="listener",
                          output="screen")]),
    ])
"""
FILES = {"ros1.launch": ROS1, "ros2.launch.xml": ROS2_XML, "ros2.launch.yaml": ROS2_YAML,
         "ros2.launch.py": ROS2_PY}


@pytest.fixture(scope="module")
def hosts(tmp_path_factory):
    """The three hosts, each with launcher on its PATH and the `chat` package on its package
    path (their own set-up, given by sshd as a login's environment)."""
    require()
    root = tmp_path_factory.mktemp("hosts")
    make_tree(root / "src", {
        "chat/package.xml": manifest("chat"),
        "chat/scripts/talker1.py": TALKER1, "chat/scripts/listener1.py": LISTENER1,
        "chat/scripts/talker2.py": TALKER2, "chat/scripts/listener2.py": LISTENER2,
        "chat/scripts/params1.py": PARAMS1,
    }, executable=tuple(f"chat/scripts/{n}" for n in ("talker1.py", "listener1.py",
                                                        "talker2.py", "listener2.py",
                                                        "params1.py")))
    with SshHosts(root / "ssh", HOSTS) as made:
        for name in HOSTS:
            made.set_environment(name, own_setup(root))
        made.package_root = root / "src"
        yield made


def own_setup(root) -> dict[str, str]:
    return {"PATH": f"{os.path.dirname(sys.executable)}:/usr/bin:/bin",
            "LAUNCHER_PACKAGE_PATH": str(root / "src"), "LAUNCHER_ROUTER_LINGER": "0.5"}


@pytest.fixture
def launching(ws, hosts):
    """The workspace, run on the launching host with the user's ssh config."""
    ws.own_bus()
    ws.env.update({"LAUNCHER_SSH_COMMAND": hosts.ssh_command,
                   "LAUNCHER_PACKAGE_PATH": str(hosts.package_root)})
    yield ws
    for name in HOSTS:  # (a test that failed midway leaves no host busy for the next)
        hosts.end_sessions(name)


def start(ws, hosts, *args: str, output: str = "out.txt") -> subprocess.Popen:
    out = open(ws.root / output, "w")  # noqa: SIM115 - closed with the workspace
    return subprocess.Popen(hosts.in_launching([*launcher_argv(), *args]), cwd=ws.root,
                            env=ws.env, stdout=out, stderr=subprocess.STDOUT, text=True)


def run(ws, hosts, *args: str, timeout: float = 90) -> subprocess.CompletedProcess:
    return subprocess.run(hosts.in_launching([*launcher_argv(), *args]), cwd=ws.root,
                          env=ws.env, capture_output=True, text=True, timeout=timeout)


def running(hosts, name: str) -> list[tuple[str, str]]:
    """(name, command line) of what runs on the host; one that ends while it is looked at (a
    zombie, or gone) is not running."""
    found = []
    for proc in hosts.processes_in(name):
        try:
            found.append((proc.name(), " ".join(proc.cmdline())))
        except psutil.Error:
            continue
    return found


def launched_on(hosts, name: str) -> list[str]:
    """What runs on the host but its sshd's own processes (a cut connection's sshd waits for
    TCP to give up, as sshd's ClientAliveInterval says: the server's, not the launch's)."""
    return [line for process, line in running(hosts, name) if not process.startswith("sshd")]


def nothing_left(hosts, within: float = LEFT_WAIT) -> dict[str, list[str]]:
    """What is still running on each host after `within` seconds (empty lists: nothing)."""
    deadline = time.monotonic() + within
    while True:
        left = {name: [line for _, line in running(hosts, name)] for name in HOSTS}
        if not any(left.values()) or time.monotonic() > deadline:
            return left
        time.sleep(0.05)


@pytest.mark.parametrize("name", list(FILES))
def test_a_launch_file_spreads_its_nodes_over_three_hosts_that_talk(launching, hosts, name):
    launching.write(name, FILES[name])
    proc = start(launching, hosts, "launch", name)
    try:
        text = launching.wait_for_output("heard hello across", 120, "out.txt")
        assert "@robot3] heard hello across" in text
        heard = run(launching, hosts, "topic", "echo", "/b", "std_msgs/msg/String", "--once")
        assert "hello across" in heard.stdout, heard.stderr
    finally:
        proc.send_signal(signal.SIGINT)
        code = proc.wait(60)
    assert code == 130, launching.output("out.txt")
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


def test_a_ros1_node_on_another_host_reads_the_launchs_parameters(launching, hosts):
    launching.write("params.launch", '<launch><machine name="robot2" address="robot2"/>'
                                     '<param name="greeting" value="hi from the launch"/>'
                                     '<node pkg="chat" type="params1.py" name="reader" '
                                     'machine="robot2" output="screen">'
                                     '<param name="rate" value="7"/></node></launch>\n')
    done = run(launching, hosts, "launch", "params.launch")
    assert "@robot2] greeting: hi from the launch rate: 7" in done.stdout, done.stdout
    assert done.returncode == 0
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


def test_a_process_on_another_host_respawns_there(launching, hosts):
    launching.write("count.yaml", "extensions: [launcher]\nlaunch:\n"
                                  "  - machine: {name: robot2, address: robot2}\n"
                                  "  - executable: {cmd: \"sh -c 'echo up; exit 4'\","
                                  " name: short, machine: robot2, output: screen,"
                                  " respawn: 'true', respawn_delay: 0.2,"
                                  " respawn_max_retries: 2}\n")
    done = run(launching, hosts, "launch", "count.yaml")
    assert done.stdout.count("[short-1@robot2] up") == 3, done.stdout
    assert done.returncode == 1
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


def test_a_required_node_on_another_host_ends_the_launch(launching, hosts):
    launching.write("required.launch", '<launch><machine name="robot2" address="robot2"/>'
                                       '<machine name="robot3" address="robot3"/>'
                                       '<node pkg="chat" type="listener1.py" name="l" '
                                       'machine="robot3"/>'
                                       '<node pkg="topic_tools" type="relay" name="r" '
                                       'args="/nowhere" machine="robot2" required="true"/>'
                                       '</launch>\n')
    done = run(launching, hosts, "launch", "required.launch", timeout=120)
    assert "@robot2]" in done.stdout
    assert done.returncode != 0
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


def test_killing_the_launcher_leaves_nothing_on_any_host(launching, hosts):
    launching.write("ros1.launch", ROS1)
    proc = start(launching, hosts, "launch", "ros1.launch")
    launching.wait_for_output("heard hello across", 120, "out.txt")
    proc.kill()
    proc.wait(10)
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


def test_a_cut_link_ends_that_hosts_processes_and_the_launch_says_so(launching, hosts):
    launching.write("ros1.launch", ROS1)
    proc = start(launching, hosts, "launch", "ros1.launch")
    try:
        launching.wait_for_output("heard hello across", 120, "out.txt")
        hosts.cut("robot2")
        try:
            deadline = time.monotonic() + 2.0
            while launched_on(hosts, "robot2") and time.monotonic() < deadline:
                time.sleep(0.05)
            assert launched_on(hosts, "robot2") == []
            launching.wait_for_output("lost machine 'robot2'", 10, "out.txt")
        finally:
            hosts.restore("robot2")
    finally:
        proc.send_signal(signal.SIGINT)
        proc.wait(60)
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


def test_a_second_shell_on_another_host_sees_every_node(launching, hosts):
    launching.write("ros2.launch.yaml", ROS2_YAML)
    proc = start(launching, hosts, "launch", "ros2.launch.yaml")
    try:
        launching.wait_for_output("heard hello across", 120, "out.txt")
        seen = hosts.ssh("robot2", "launcher node list")
        assert {"/talker", "/relay", "/listener"} <= set(seen.stdout.split()), seen.stderr
        every = hosts.ssh("robot2", "launcher node list -a").stdout.split()
        assert every.count("/_parameter_server") == 1  # the graph's one master, as ROS 1's
    finally:
        proc.send_signal(signal.SIGINT)
        proc.wait(60)
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


# --- bad connections: each said at its place, nothing left on any host ------------------------
def one_node(ws, machine: str) -> None:
    ws.write("one.launch", f'<launch>\n{machine}\n'
                           '<node pkg="chat" type="talker1.py" name="t" machine="far"/>\n'
                           '</launch>\n')


def failed(ws, hosts, said: str) -> None:
    done = run(ws, hosts, "launch", "one.launch", timeout=120)
    text = done.stdout + done.stderr
    assert done.returncode == 1, text
    assert "one.launch:3:" in text, text
    assert said in text, text
    assert nothing_left(hosts) == {name: [] for name in HOSTS}


def test_an_unknown_host_is_said(launching, hosts):
    one_node(launching, '<machine name="far" address="robot9"/>')
    failed(launching, hosts, "cannot resolve 'robot9'")


def test_a_refused_connection_is_said(launching, hosts):
    one_node(launching, '<machine name="far" address="robot2"/>')
    hosts.stop_sshd("robot2")
    try:
        failed(launching, hosts, "robot2 refused the connection on port 22")
    finally:
        hosts.start_sshd("robot2")
        hosts.set_environment("robot2", own_setup(hosts.package_root.parent))


def test_a_failed_login_is_said(launching, hosts):
    one_node(launching, '<machine name="far" address="robot2"/>')
    hosts.refuse_login("robot2")
    try:
        failed(launching, hosts, "logging in as robot2 failed (publickey")
    finally:
        hosts.allow_login("robot2")


def test_a_host_key_that_does_not_match_known_hosts_is_said_and_never_overridden(launching,
                                                                                 hosts):
    one_node(launching, '<machine name="far" address="robot2"/>')
    launching.env["LAUNCHER_SSH_COMMAND"] = hosts.wrong_known_hosts("robot2")
    failed(launching, hosts, "the host key of robot2 does not match known_hosts")


def test_a_host_without_launcher_is_said(launching, hosts):
    one_node(launching, '<machine name="far" address="robot2"/>')
    hosts.set_environment("robot2", {**own_setup(hosts.package_root.parent),
                                     "PATH": "/usr/bin:/bin"})
    try:
        failed(launching, hosts, "launcher is not installed there")
    finally:
        hosts.set_environment("robot2", own_setup(hosts.package_root.parent))


def test_a_missing_env_loader_is_said(launching, hosts):
    one_node(launching, '<machine name="far" address="robot2" env-loader="/nowhere/env.sh"/>')
    failed(launching, hosts, "env-loader '/nowhere/env.sh' does not exist there")


def test_a_failing_env_loader_is_said(launching, hosts):
    loader = hosts.root / "failing-loader"
    loader.write_text("#!/bin/sh\necho 'the workspace is not built' >&2\nexit 3\n")
    loader.chmod(0o755)
    one_node(launching, f'<machine name="far" address="robot2" env-loader="{loader}"/>')
    failed(launching, hosts, f"env-loader '{loader}' failed there (exit 3): the workspace is "
                             "not built")


def test_a_host_that_does_not_answer_within_its_timeout_is_said(launching, hosts):
    one_node(launching, '<machine name="far" address="robot2" timeout="2"/>')
    hosts.freeze("robot2")
    try:
        failed(launching, hosts, "did not answer within 2 s")
    finally:
        hosts.thaw("robot2")


def test_the_ssh_client_the_user_set_is_used(launching, hosts):
    """LAUNCHER_SSH_COMMAND (what every test here relies on): without it, the user's plain
    `ssh` does not know robot2 (no config names it), which is said as such."""
    one_node(launching, '<machine name="far" address="robot2"/>')
    launching.env.pop("LAUNCHER_SSH_COMMAND")
    failed(launching, hosts, "cannot resolve 'robot2'")


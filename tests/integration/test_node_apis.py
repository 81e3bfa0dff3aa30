"""ROS node code runs unchanged on launcher's graph: ros2/examples' rclpy packages used in place
(../shared/external/ros2_examples), rclpy and rospy programs, `launcher run`. Real processes
on a real Zenoh router; each test checks that nothing it started is left."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import time

import pytest

from launcher.compat import SITE
from tests.support.environment import shared
from tests.support.nodes import node_package

PUBLISHERS = ["publisher_old_school", "publisher_local_function", "publisher_member_function"]
SUBSCRIBERS = ["subscriber_old_school", "subscriber_lambda", "subscriber_member_function"]
CLIENTS = ["client", "client_async", "client_async_member_function", "client_async_callback"]
SERVICES = ["service", "service_member_function"]


@pytest.fixture
def examples(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared("external", "ros2_examples", "rclpy"))
    return ws


def stop(proc, sig: int = signal.SIGINT) -> int:
    proc.send_signal(sig)
    return proc.wait(20)




@pytest.mark.parametrize("publisher, subscriber", list(zip(PUBLISHERS, SUBSCRIBERS,
                                                           strict=True)))
def test_each_example_publisher_reaches_each_example_subscriber(examples, publisher,
                                                                subscriber):
    """Every variant of both, under `launcher run` (as `ros2 run`), unchanged."""
    listener = examples.start("run", "examples_rclpy_minimal_subscriber", subscriber,
                              output="sub.txt")
    talker = examples.start("run", "examples_rclpy_minimal_publisher", publisher,
                            output="pub.txt")
    try:
        heard = examples.wait_for_output('I heard: "Hello World: 2"', 30, "sub.txt")
        assert "[INFO] [" in heard and "] [minimal_subscriber]: I heard" in heard
        assert '[minimal_publisher]: Publishing: "Hello World: 0"' in examples.output("pub.txt")
    finally:
        # Ctrl-C: the examples catch KeyboardInterrupt and end with status 0, as with rclpy
        assert stop(talker) == 0, examples.output("pub.txt")
        assert stop(listener) == 0, examples.output("sub.txt")


@pytest.mark.parametrize("client", CLIENTS)
def test_each_example_client_gets_the_sum_from_a_service(examples, client):
    server = examples.start("run", "examples_rclpy_minimal_service",
                            SERVICES[CLIENTS.index(client) % 2], output="service.txt")
    try:
        done = examples.run("run", "examples_rclpy_minimal_client", client, timeout=60)
        assert done.returncode == 0, done.stderr
        # (its logger writes on stderr, as rcutils does)
        assert "Result of add_two_ints: for 41 + 1 = 42" in done.stderr, done.stderr
        assert "Incoming request\na: 41 b: 1" in examples.wait_for_output(
            "Incoming request", 10, "service.txt")
    finally:
        # SIGTERM: rclpy's handler ends spinning with ExternalShutdownException (caught)
        assert stop(server, signal.SIGTERM) == 0, examples.output("service.txt")


def test_every_example_executable_in_one_launch_file(examples):
    """All twelve executables of the four packages as `node` actions (renamed, so that no two
    share a name): every subscriber hears, every client gets its sum."""
    nodes = []
    for exe in PUBLISHERS:
        nodes.append(f"- node: {{pkg: examples_rclpy_minimal_publisher, exec: {exe}, "
                     f"name: {exe}, output: log}}")
    for exe in SUBSCRIBERS:
        nodes.append(f"- node: {{pkg: examples_rclpy_minimal_subscriber, exec: {exe}, "
                     f"name: {exe}, output: screen}}")
    for exe in SERVICES:
        nodes.append(f"- node: {{pkg: examples_rclpy_minimal_service, exec: {exe}, "
                     f"name: {exe}, output: log}}")
    clients = "\n".join(
        f"        - node: {{pkg: examples_rclpy_minimal_client, exec: {exe}, name: {exe}, "
        f"output: screen}}" for exe in CLIENTS)
    body = "\n".join("  " + line for line in nodes)
    examples.write("all.launch.yaml", f"""
launch:
{body}
  - timer:
      period: 1.0
      children:
{clients}
""")
    done = examples.run("launch", "all.launch.yaml", "--duration", "8", timeout=120)
    assert done.returncode == 0, done.stderr
    for exe in SUBSCRIBERS:
        assert re.search(rf"\[{exe}-\d+\] .*\[{exe}\]: I heard: \"Hello World: \d+\"",
                         done.stdout), (exe, done.stdout)
    for exe in CLIENTS:
        assert re.search(rf"\[{exe}-\d+\] .*Result of add_two_ints: for 41 \+ 1 = 42",
                         done.stdout), (exe, done.stdout)
    for exe in CLIENTS:  # each ends by itself once it has its answer
        assert re.search(rf"\[INFO\] \[{exe}-\d+\]: process has finished cleanly",
                         done.stderr + done.stdout), exe


def test_a_python3_command_and_the_users_shell_get_the_modules_too(examples):
    """`executable: {cmd: python3 node.py}` imports rclpy and messages as a package node
    does; `launcher env` gives a shell the same (the site hook on PYTHONPATH)."""
    examples.write("node.py", """
    import rclpy
    from std_msgs.msg import String
    with rclpy.init():
        node = rclpy.create_node('plain')
        print('plain node:', node.get_fully_qualified_name(), String(data='x'), flush=True)
    """)
    examples.write("plain.launch.yaml", """
    launch:
      - executable: {cmd: python3 node.py, output: screen}
    """)
    done = examples.run("launch", "plain.launch.yaml", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "plain node: /plain std_msgs.msg.String(data='x')" in done.stdout
    shell = examples.run("env", "--shell", "json")
    assert SITE in json.loads(shell.stdout)["PYTHONPATH"].split(os.pathsep)


def test_rclpy_api_parameters_executors_and_errors(examples):
    node_package(examples, "rclpy_checks", {"checks.py": '''
import threading, sys
import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rcl_interfaces.msg import SetParametersResult
from std_msgs.msg import String

rclpy.init()
try:
    rclpy.init()
except RuntimeError as exc:
    print("twice:", exc)
node = Node("checks")
print("speed:", node.declare_parameter("speed", 1.0).value)
print("name:", node.declare_parameter("label", "none").value)
try:
    node.get_parameter("nope")
except Exception as exc:
    print("undeclared:", type(exc).__name__)
node.add_on_set_parameters_callback(
    lambda params: SetParametersResult(successful=params[0].value < 10))
print("set 5:", node.set_parameters([Parameter("speed", value=5.0)])[0].successful)
print("set 50:", node.set_parameters([Parameter("speed", value=50.0)])[0].successful,
      node.get_parameter("speed").value)
print("fqn:", node.get_fully_qualified_name(), node.get_namespace())
group = ReentrantCallbackGroup()
both = threading.Barrier(2, timeout=5)
ran = []
def slow():
    both.wait()  # two timers inside at once: only with a pool and a reentrant group
    ran.append(1)
timers = [node.create_timer(0.05, slow, callback_group=group) for _ in range(2)]
executor = MultiThreadedExecutor(num_threads=2)
executor.add_node(node)
while len(ran) < 2:
    executor.spin_once(timeout_sec=1.0)
print("parallel:", len(ran) >= 2)
for timer in timers:
    timer.cancel()
executor.shutdown()
guard_ran = []
guard = node.create_guard_condition(lambda: guard_ran.append(1))
guard.trigger()
rclpy.spin_once(node, timeout_sec=1.0)
print("guard:", guard_ran)
shared = rclpy.get_global_executor()  # rclpy.spin_once leaves the node out of it after
print("lent:", node not in shared.get_nodes())
shared.add_node(node)
rclpy.spin_once(node, timeout_sec=0)
print("taken back:", node not in shared.get_nodes())
node.destroy_node()
try:
    rclpy.spin(node)
except Exception as exc:
    print("destroyed:", type(exc).__name__, exc)
rclpy.shutdown()
print("ok:", rclpy.ok())
'''})
    done = examples.run("run", "rclpy_checks", "checks.py", "--ros-args", "-p", "speed:=2.5",
                        "-r", "__ns:=/robot", timeout=60)
    assert done.returncode == 0, done.stderr
    out = done.stdout
    assert "twice: Context.init() must only be called once" in out
    assert "speed: 2.5" in out and "name: none" in out  # the override wins over the default
    assert "undeclared: ParameterNotDeclaredException" in out
    assert "set 5: True" in out and "set 50: False 5.0" in out
    assert "fqn: /robot/checks /robot" in out
    assert "parallel: True" in out and "guard: [1]" in out
    assert "lent: True" in out and "taken back: True" in out
    assert "destroyed: InvalidHandle cannot use Destroyable because destruction was requested" \
        in out
    assert "ok: False" in out



def test_param_describe_delete_and_refusals_on_an_rclpy_node(examples):
    """`param describe`, `param delete` and `param set` ask an rclpy node that keeps its
    declared types, read-only flags and set callbacks: refusals come back with the reason."""
    node_package(examples, "rclpy_params", {"tuned.py": '''
import rclpy
from rclpy.node import Node
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor, SetParametersResult
rclpy.init()
node = Node("tuned")
node.declare_parameter("gain", 1.0, ParameterDescriptor(
    description="how hard it pushes",
    floating_point_range=[FloatingPointRange(from_value=0.0, to_value=10.0, step=0.5)]))
node.declare_parameter("frame", "base", ParameterDescriptor(read_only=True))
node.declare_parameter("spare", 1, ParameterDescriptor(dynamic_typing=True))
node.add_on_set_parameters_callback(lambda ps: SetParametersResult(
    successful=all(p.value != 9.5 for p in ps), reason="9.5 is too hard"))
print("ready", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
'''})
    proc = examples.start("run", "rclpy_params", "tuned.py", output="tuned.txt")
    try:
        examples.wait_for_output("ready", 30, "tuned.txt")
        described = examples.run("param", "describe", "/tuned", "gain", "frame").stdout
        assert described == (
            "Parameter name: gain\n  Type: double\n  Description: how hard it pushes\n"
            "  Constraints:\n    Min value: 0.0\n    Max value: 10.0\n    Step: 0.5\n"
            "Parameter name: frame\n  Type: string\n  Constraints:\n    Read only: true\n")
        refused = examples.run("param", "set", "/tuned", "gain", "9.5")
        assert refused.returncode == 1
        assert refused.stdout == "Setting parameter failed: 9.5 is too hard\n"
        wrong = examples.run("param", "set", "/tuned", "gain", "fast").stdout
        assert "Wrong parameter type, parameter {gain} is of type {double}" in wrong
        fixed = examples.run("param", "set", "/tuned", "frame", "odom").stdout
        assert "cannot be set because it is read-only" in fixed
        assert examples.run("param", "set", "/tuned", "gain", "2.5").returncode == 0
        assert examples.run("param", "get", "/tuned", "gain").stdout.strip() == \
            "Double value is: 2.5"
        static = examples.run("param", "delete", "/tuned", "gain")
        assert static.returncode == 1 and static.stdout == \
            "Deleting parameter failed: cannot undeclare a statically typed parameter\n"
        deleted = examples.run("param", "delete", "/tuned", "spare")
        assert deleted.returncode == 0 and deleted.stdout == "Deleted parameter successfully\n"
        names = examples.run("param", "list", "/tuned").stdout.split()
        assert "spare" not in names and "gain" in names
    finally:
        assert stop(proc) in (0, 130)


ROSPY_NODES = {
    "talker.py": '''#!/usr/bin/env python
import rospy
from std_msgs.msg import String
pub = rospy.Publisher('chatter', String, queue_size=10, latch=True)
rospy.init_node('talker', anonymous=True)
print("rate param:", rospy.get_param('~rate'), rospy.get_param('~missing', 'dflt'))
print("name:", rospy.get_name().startswith('/talker_'))
rate = rospy.Rate(rospy.get_param('~rate'))
n = 0
try:
    while not rospy.is_shutdown():
        pub.publish(String(data='hello %d' % n))
        n += 1
        rate.sleep()
except rospy.ROSInterruptException:  # a sleep under way when Ctrl-C came, as with rospy
    pass
''',
    "listener.py": '''#!/usr/bin/env python
import rospy
from std_msgs.msg import String
from std_srvs.srv import Trigger, TriggerResponse
def heard(message, extra):
    rospy.loginfo('%s heard %s', extra, message.data)
rospy.init_node('listener')
rospy.Subscriber('words', String, heard, callback_args='I')
rospy.Service('ready', Trigger, lambda request: TriggerResponse(success=True, message='yes'))
rospy.on_shutdown(lambda: print('bye', flush=True))
rospy.spin()
''',
    "caller.py": '''#!/usr/bin/env python
import rospy
from std_msgs.msg import String
from std_srvs.srv import Trigger
try:
    rospy.get_param('x')
except rospy.ROSInitException as exc:
    print('before init:', exc)
try:
    rospy.Time.now()
except rospy.ROSInitException as exc:
    print('time before init:', exc)
rospy.init_node('caller')
rospy.wait_for_service('ready', timeout=20)
answer = rospy.ServiceProxy('ready', Trigger)()
print('answer:', answer.success, answer.message)
print('message:', rospy.wait_for_message('words', String, timeout=20).data.startswith('hello'))
try:
    rospy.wait_for_message('nothing_here', String, timeout=0.5)
except rospy.ROSException as exc:
    print('timeout:', exc)
stamp = rospy.Time.now()
print('time:', stamp.secs > 0, round((stamp + rospy.Duration(1.5)).to_sec() - stamp.to_sec(), 6))
''',
}


def test_rospy_nodes_publish_subscribe_serve_and_remap(examples):
    node_package(examples, "course_nodes", ROSPY_NODES)
    listener = examples.start("run", "course_nodes", "listener.py", output="listener.txt")
    # ROS 1 argv: `from:=to` remaps, `_name:=value` sets a private parameter
    talker = examples.start("run", "course_nodes", "talker.py", "chatter:=words", "_rate:=20",
                            output="talker.txt")
    try:
        examples.wait_for_output("I heard hello", 30, "listener.txt")
        done = examples.run("run", "course_nodes", "caller.py", "chatter:=words", timeout=60)
        assert done.returncode == 0, done.stderr
        out = done.stdout
        assert "before init: get_param: the node is not initialized. Have you called " \
               "init_node()?" in out
        assert "time before init: time is not initialized" in out
        assert "answer: True yes" in out and "message: True" in out
        assert "timeout: timeout exceeded while waiting for message on topic /nothing_here" \
            in out
        assert "time: True 1.5" in out
        talked = examples.output("talker.txt")
        assert "rate param: 20 dflt" in talked and "name: True" in talked
    finally:
        # Ctrl-C: is_shutdown() turns true, the loop ends, status 0 (rospy's handler)
        assert stop(talker) == 0, examples.output("talker.txt")
        assert stop(listener) == 0
    assert "bye" in examples.output("listener.txt")


def test_a_real_rclpy_wins_and_launcher_says_how_to_choose(examples, tmp_path):
    real = tmp_path / "real"
    (real / "rclpy").mkdir(parents=True)
    (real / "rclpy" / "__init__.py").write_text("WHO = 'the real one'\n")
    node_package(examples, "which", {"which.py": "import rclpy\nprint(getattr(rclpy, 'WHO', "
                                                 "'launcher'))\n"})
    examples.env["PYTHONPATH"] = str(real)
    done = examples.run("run", "which", "which.py")
    assert done.stdout.strip() == "the real one", done.stderr
    assert f"a real ROS client library is installed (rclpy in {real})" in done.stderr
    assert "set LAUNCHER_ROS_MODULES=launcher" in done.stderr
    examples.env["LAUNCHER_ROS_MODULES"] = "launcher"
    done = examples.run("run", "which", "which.py")
    assert done.stdout.strip() == "launcher" and "real ROS" not in done.stderr


def test_run_of_an_unknown_package_or_executable(examples):
    done = examples.run("run", "examples_rclpy_minimal_publishr", "x")
    assert done.returncode == 1 and done.stdout == ""
    assert ("[run] error: package 'examples_rclpy_minimal_publishr' not found (did you mean "
            "'examples_rclpy_minimal_publisher'") in done.stderr
    done = examples.run("run", "examples_rclpy_minimal_publisher", "publisher")
    assert done.returncode == 1
    assert ("has no executable 'publisher' (did you mean 'publisher_old_school'") in done.stderr
    assert "it has: publisher_local_function, publisher_member_function, publisher_old_school" \
        in done.stderr
    assert "Traceback" not in done.stderr
    done = examples.run("run", "examples_rclpy_minimal_publisher")
    assert done.returncode == 2 and "expected a package and an executable" in done.stderr


def test_run_of_a_package_whose_setup_py_cannot_be_read(examples):
    setup = examples.write("ws/dyn/setup.py", """
    import os
    from setuptools import setup
    setup(name='dyn', entry_points={'console_scripts': [os.environ['TOOL']]})
    """)
    node_package(examples, "dyn", {})
    done = examples.run("run", "dyn", "tool")
    assert done.returncode == 1
    assert f"{setup}:3:" in done.stderr and "cannot read setup.py's entry_points without " \
        "running it" in done.stderr


def test_a_node_started_by_launcher_run_leaves_nothing_after_sigkill_of_its_parent(examples):
    """`launcher run` becomes the node (exec): killing it leaves no launcher process."""
    proc = examples.start("run", "examples_rclpy_minimal_publisher", "publisher_member_function")
    examples.wait_for_output("Publishing", 30, "stderr.txt")  # (rclpy logs on stderr)
    assert "launcher.packages.entry" in " ".join(__import__("psutil").Process(proc.pid)
                                                 .cmdline())
    proc.kill()
    proc.wait(10)
    time.sleep(0.2)


LEAN = """
import sys, time
import rclpy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('lean')
heard = []
node.create_subscription(String, 'lean_topic', heard.append, 10)
pub = node.create_publisher(String, 'lean_topic', 10)
twist = node.create_publisher(Twist, 'lean_twist', 10)
end = time.monotonic() + 30
while not heard and time.monotonic() < end:
    pub.publish(String(data='hi'))
    twist.publish(Twist())
    rclpy.spin_once(node, timeout_sec=0.05)
from launcher.bus.node import Node
from launcher.nodes.robot_state_publisher import RobotStatePublisher
urdf = ('<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute">'
        '<parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint></robot>')
rsp = Node('rsp', argv=['--ros-args', '-p', 'robot_description:=' + urdf])
RobotStatePublisher(rsp)
rsp.destroy_node()
heavy = sorted(m for m in sys.modules if m.split('.')[0] in ('numpy', 'mujoco', 'rosbags'))
print('heard', heard[0].data if heard else None, 'heavy', heavy)
node.destroy_node()
rclpy.shutdown()
"""


def test_an_rclpy_node_imports_no_numpy_mujoco_or_rosbags(examples):
    """A node that publishes, subscribes and offers its parameter services reads its types'
    definitions from launcher's cache: none of the heavy modules at start or on the first
    message; nor does a robot_state_publisher set up beside it."""
    script = examples.write("lean.py", LEAN)
    done = subprocess.run([sys.executable, str(script)], cwd=examples.root,
                          env={**examples.env, "PYTHONPATH": SITE}, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "heard hi heavy []" in done.stdout, done.stdout + done.stderr

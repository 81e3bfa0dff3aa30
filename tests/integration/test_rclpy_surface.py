"""The rest of rclpy that real nodes use (found failing on ros2/demos' demo_nodes_py):
pre- and post-set parameter callbacks, parameter_dict_from_yaml_file, the logger service
with two executors on two threads, and an entry point that reads sys.argv as it is imported."""

from __future__ import annotations

import signal

from tests.support.nodes import node_package

PARAMS = """
import threading, time
import rclpy
from rcl_interfaces.msg import LoggerLevel, SetParametersResult
from rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_dict_from_yaml_file

rclpy.init()
node = Node("tuned", enable_logger_service=True)
node.declare_parameter("param1", 0.0)
node.declare_parameter("param2", 0.0)
seen = []
node.add_pre_set_parameters_callback(
    lambda ps: ps + [Parameter("param2", Parameter.Type.DOUBLE, 4.0)]
    if any(p.name == "param1" for p in ps) else ps)
node.add_on_set_parameters_callback(lambda ps: SetParametersResult(successful=True))
node.add_post_set_parameters_callback(lambda ps: seen.append(sorted(p.name for p in ps)))
node.set_parameters([Parameter("param1", Parameter.Type.DOUBLE, 1.0)])
print("internal", node.get_parameter("param2").value, seen[-1], flush=True)
values = parameter_dict_from_yaml_file(PARAMS_FILE, target_nodes=["tuned"])
print("yaml", sorted(values), values["arm.gain"].value.double_value, flush=True)

executor = SingleThreadedExecutor()
executor.add_node(node)
threading.Thread(target=executor.spin, daemon=True).start()
asker = Node("asker")
setter = asker.create_client(SetLoggerLevels, "/tuned/set_logger_levels")
getter = asker.create_client(GetLoggerLevels, "/tuned/get_logger_levels")
setter.wait_for_service(10)
future = setter.call_async(SetLoggerLevels.Request(levels=[LoggerLevel(name="tuned", level=10)]))
rclpy.spin_until_future_complete(asker, future, timeout_sec=10)  # (a second executor)
future = getter.call_async(GetLoggerLevels.Request(names=["tuned"]))
rclpy.spin_until_future_complete(asker, future, timeout_sec=10)
print("logger", future.result().levels[0].level, flush=True)
print("ready", flush=True)
while rclpy.ok():
    time.sleep(0.1)
    if seen and seen[-1] == ["param1", "param2"] and node.get_parameter("param1").value == 5.0:
        print("external", node.get_parameter("param2").value, flush=True)
        break
"""


def test_parameter_callbacks_yaml_files_and_the_logger_service(ws):
    params_file = ws.write("params.yaml", """
    tuned:
      ros__parameters:
        arm:
          gain: 2.5
          joints: [a, b]
    other:
      ros__parameters:
        x: 1
    """)
    node_package(ws, "surface", {"params.py": PARAMS.replace(
        "PARAMS_FILE", repr(str(params_file)))})
    ws.own_bus()
    proc = ws.start("run", "surface", "params.py", output="params.txt")
    try:
        said = ws.wait_for_output("ready", 60, "params.txt")
        assert "internal 4.0 ['param1', 'param2']" in said, said  # the pre-set callback added
        assert "yaml ['arm.gain', 'arm.joints'] 2.5" in said, said
        assert "logger 10" in said, said
        done = ws.run("param", "set", "/tuned", "param1", "5.0")
        assert done.returncode == 0, done.stderr
        assert "external 4.0" in ws.wait_for_output("external", 30, "params.txt")
    finally:
        proc.send_signal(signal.SIGINT)
        proc.wait(20)


def test_an_entry_point_reading_sys_argv_as_it_is_imported_gets_its_own(ws):
    ws.own_bus()
    ws.write("ws/argv_pkg/package.xml", """
    <?xml version="1.0"?>
    <package format="3"><name>argv_pkg</name><version>0.1.0</version><description>a
    </description><maintainer email="a@b.c">a</maintainer><license>MIT</license></package>
    """)
    ws.write("ws/argv_pkg/setup.cfg", """
    [options.entry_points]
    console_scripts =
        show = argv_pkg.show:main
    """)
    ws.write("ws/argv_pkg/argv_pkg/__init__.py", "")
    ws.write("ws/argv_pkg/argv_pkg/show.py", """
    import argparse, sys
    ARGS = argparse.ArgumentParser().parse_args()  # at import, as some nodes do
    def main():
        print("argv", sys.argv[1:])
    """)
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "ws")
    done = ws.run("run", "argv_pkg", "show")
    assert done.returncode == 0, done.stderr
    assert "argv []" in done.stdout, done.stdout


BLACKBOARD = """
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
rclpy.init()
node = Node("parameter_blackboard", allow_undeclared_parameters=True,
            automatically_declare_parameters_from_overrides=True)
publisher = node.create_publisher(String, "board", 10)
node.create_timer(0.1, lambda: publisher.publish(String(data="chalk")))
print("up", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""

CLIENT = """
import rclpy
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.wait_for_message import wait_for_message
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node("async_param_client")
client = AsyncParameterClient(node, "parameter_blackboard")
assert client.wait_for_services(10.0)
future = client.set_parameters([Parameter("int_parameter", Parameter.Type.INTEGER, 10),
                                 Parameter("string_parameter", Parameter.Type.STRING, "Fee")])
rclpy.spin_until_future_complete(node, future)
print("set", [r.successful for r in future.result().results])
future = client.get_parameters(["int_parameter", "string_parameter"])
rclpy.spin_until_future_complete(node, future)
print("get", [parameter_value_to_python(v) for v in future.result().values])
future = client.load_parameter_file(PARAMS_FILE)
rclpy.spin_until_future_complete(node, future)
print("load", [r.successful for r in future.result().results])
future = client.get_parameters(["int_parameter"])
rclpy.spin_until_future_complete(node, future)
print("loaded", parameter_value_to_python(future.result().values[0]))
ok, message = wait_for_message(String, node, "board", time_to_wait=10.0)
print("message", ok, message.data)
print("none", wait_for_message(String, node, "silent", time_to_wait=0.3))
"""


def test_async_parameter_client_and_wait_for_message(ws):
    params_file = ws.write("board.yaml", """
    /parameter_blackboard:
      ros__parameters:
        int_parameter: 12
    """)
    node_package(ws, "board", {"blackboard.py": BLACKBOARD, "client.py": CLIENT.replace(
        "PARAMS_FILE", repr(str(params_file)))})
    ws.own_bus()
    board = ws.start("run", "board", "blackboard.py", output="board.txt")
    try:
        ws.wait_for_output("up", 30, "board.txt")
        done = ws.run("run", "board", "client.py", timeout=60)
        assert done.returncode == 0, done.stderr
        out = done.stdout
        assert "set [True, True]" in out and "get [10, 'Fee']" in out, out
        assert "load [True]" in out and "loaded 12" in out, out
        assert "message True chalk" in out and "none (False, None)" in out, out
    finally:
        board.send_signal(signal.SIGINT)
        board.wait(20)


MATCHED = """
import time
import rclpy
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.node import Node
from std_msgs.msg import String
rclpy.init()
node = Node("watcher")
seen = []
node.create_publisher(String, "out", 10, event_callbacks=PublisherEventCallbacks(
    matched=lambda info: seen.append(("pub", info.current_count, info.current_count_change,
                                      info.total_count))))
node.create_subscription(String, "in", lambda m: None, 10,
                         event_callbacks=SubscriptionEventCallbacks(
                             matched=lambda info: seen.append(("sub", info.current_count))))
other = Node("other")


def settle(expected):
    end = time.monotonic() + 10
    while len(seen) < expected and time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.1)


a = other.create_subscription(String, "out", lambda m: None, 10)
settle(1)
b = other.create_subscription(String, "out", lambda m: None, 10)
settle(2)
other.destroy_subscription(a)
settle(3)
p = other.create_publisher(String, "in", 10)
settle(4)
other.destroy_publisher(p)
settle(5)
print(seen)
"""


def test_matched_events_count_the_other_side_as_it_comes_and_goes(ws):
    node_package(ws, "matched", {"watch.py": MATCHED})
    ws.own_bus()
    done = ws.run("run", "matched", "watch.py", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "[('pub', 1, 1, 1), ('pub', 2, 1, 2), ('pub', 1, -1, 2), ('sub', 1), ('sub', 0)]" \
        in done.stdout, done.stdout


INTROSPECTED = """
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node
from rclpy.qos import qos_profile_system_default
from rclpy.service_introspection import ServiceIntrospectionState
rclpy.init()
node = Node("adder")
service = node.create_service(AddTwoInts, "add_two_ints",
                              lambda req, resp: setattr(resp, "sum", req.a + req.b) or resp)
service.configure_introspection(node.get_clock(), qos_profile_system_default,
                                ServiceIntrospectionState.CONTENTS)
print("up", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""


def test_service_introspection_and_service_echo(ws):
    node_package(ws, "intro", {"adder.py": INTROSPECTED})
    ws.own_bus()
    adder = ws.start("run", "intro", "adder.py", output="adder.txt")
    echo = ws.start("service", "echo", "/add_two_ints", "example_interfaces/srv/AddTwoInts",
                    output="echo.txt")
    try:
        ws.wait_for_output("up", 30, "adder.txt")
        import time

        time.sleep(1.5)
        called = ws.run("service", "call", "/add_two_ints", "example_interfaces/srv/AddTwoInts",
                        "{a: 2, b: 3}")
        assert "sum: 5" in called.stdout, called
        said = ws.wait_for_output("event_type: 2", 20, "echo.txt")
        assert "event_type: 1" in said and "request:\n- a: 2\n  b: 3" in said, said
        assert "response:\n- sum: 5" in said, said
        # the events are a topic of their own (hidden, as ROS 2 lists it)
        listed = ws.run("topic", "list", "-t", "--include-hidden-topics")
        topics = listed.stdout + listed.stderr
        assert "/add_two_ints/_service_event [example_interfaces/srv/AddTwoInts_Event]" \
            in topics, topics
    finally:
        for proc in (echo, adder):
            proc.send_signal(signal.SIGINT)
            proc.wait(20)


def test_topic_echo_of_a_services_event_topic_named_in_full(ws):
    """`ros2 topic echo /add_two_ints/_service_event` works: a hidden topic named in full,
    whose type (AddTwoInts_Event) comes with its service."""
    node_package(ws, "intro", {"adder.py": INTROSPECTED})
    ws.own_bus()
    adder = ws.start("run", "intro", "adder.py", output="adder.txt")
    echo = None
    try:
        ws.wait_for_output("up", 30, "adder.txt")
        echo = ws.start("topic", "echo", "/add_two_ints/_service_event", output="events.txt")
        import time

        time.sleep(1.5)
        called = ws.run("service", "call", "/add_two_ints", "example_interfaces/srv/AddTwoInts",
                        "{a: 4, b: 5}")
        assert "sum: 9" in called.stdout, called
        said = ws.wait_for_output("event_type: 2", 20, "events.txt")
        assert "request:\n- a: 4\n  b: 5" in said and "nobody publishes" not in said, said
    finally:
        for proc in (echo, adder):
            if proc is not None:
                proc.send_signal(signal.SIGINT)
                proc.wait(20)


CUSTOM_EXECUTOR = """
from concurrent.futures import ThreadPoolExecutor
import rclpy
from rclpy.executors import Executor, ShutdownException, TimeoutException
from rclpy.node import Node
from std_msgs.msg import String


class PoolExecutor(Executor):
    def __init__(self):
        super().__init__()
        self.pool = ThreadPoolExecutor(max_workers=2)
        self.handled = 0

    def spin_once(self, timeout_sec=None):
        try:
            handler, group, node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)
        except (ShutdownException, TimeoutException):
            return
        self.handled += 1
        self.pool.submit(handler)


rclpy.init()
node = Node("custom")
heard = []
node.create_subscription(String, "words", lambda m: heard.append(m.data), 10)
publisher = node.create_publisher(String, "words", 10)
node.create_timer(0.05, lambda: publisher.publish(String(data="hi")))
executor = PoolExecutor()
executor.add_node(node)
while len(heard) < 5:
    executor.spin_once(timeout_sec=1.0)
print("heard", heard[:5], executor.handled >= 10)
executor.pool.shutdown()
"""


def test_an_executor_of_the_users_spins_with_wait_for_ready_callbacks(ws):
    node_package(ws, "custom_exec", {"custom.py": CUSTOM_EXECUTOR})
    ws.own_bus()
    done = ws.run("run", "custom_exec", "custom.py", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "heard ['hi', 'hi', 'hi', 'hi', 'hi'] True" in done.stdout, done.stdout


def test_launcher_logger_gets_and_sets_a_nodes_level(ws):
    node_package(ws, "loud", {"loud.py": """
import rclpy
from rclpy.node import Node
rclpy.init()
node = Node("loud", enable_logger_service=True)
node.create_timer(0.1, lambda: node.get_logger().debug("whisper"))
print("up", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""})
    ws.own_bus()
    loud = ws.start("run", "loud", "loud.py", output="loud.txt")
    try:
        ws.wait_for_output("up", 30, "loud.txt")
        # its own level, unset (0) until set, as rclpy answers (it then follows the default)
        assert ws.run("logger", "get", "/loud").stdout == "loud: UNSET\n"
        assert ws.run("logger", "set", "/loud", "debug").stdout == "loud: DEBUG\n"
        ws.wait_for_output("whisper", 10, "loud.txt")  # debug messages now come out
        bad = ws.run("logger", "set", "/loud", "chatty")
        assert bad.returncode == 2 and "unknown level 'chatty'" in bad.stderr
        absent = ws.run("logger", "get", "/quiet")
        assert absent.returncode == 1 and "offers no get_logger_levels service" in \
            absent.stderr, absent.stderr
    finally:
        loud.send_signal(signal.SIGINT)
        loud.wait(20)


THROTTLED = """
import time
import rclpy
from rclpy.callback_groups import CallbackGroup
from rclpy.node import Node


class Tokens(CallbackGroup):
    # a bucket of three tokens, never refilled: three callbacks, then none
    def __init__(self):
        super().__init__()
        self.tokens, self.calls = 3, []

    def can_execute(self, entity):
        return self.tokens > 0

    def beginning_execution(self, entity):
        self.calls.append(("begin", type(entity).__name__))
        if self.tokens > 0:
            self.tokens -= 1
            return True
        return False

    def ending_execution(self, entity):
        self.calls.append(("end", type(entity).__name__))


rclpy.init()
node = Node("throttled")
fired = []
group = Tokens()
node.create_timer(0.02, lambda: fired.append(time.monotonic()), callback_group=group)
end = time.monotonic() + 1.5
while time.monotonic() < end:
    rclpy.spin_once(node, timeout_sec=0.1)
print("fired", len(fired), group.calls[:2], flush=True)
"""


def test_a_callback_group_of_the_programs_own_decides_when_its_callbacks_run(ws):
    """rclpy asks a custom CallbackGroup (ros2/examples' ThrottledCallbackGroup) whether a
    callback may run (can_execute, beginning_execution) and tells it when it ended: a group
    with three tokens lets its 50 Hz timer run three times, not 75."""
    node_package(ws, "throttle", {"throttled.py": THROTTLED})
    ws.own_bus()
    done = ws.run("run", "throttle", "throttled.py", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "fired 3 [('begin', 'Timer'), ('end', 'Timer')]" in done.stdout, done.stdout


LOGGER_SERVICE = """
import threading, time
import rclpy
from example_interfaces.msg import String
from rcl_interfaces.msg import LoggerLevel
from rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels
from rclpy.executors import SingleThreadedExecutor
from rclpy.impl.logging_severity import LoggingSeverity
from rclpy.node import Node

with rclpy.init():
    served = Node("served", enable_logger_service=True)
    child = served.get_logger().get_child("child")
    def said(msg):
        for logger, tag in ((served.get_logger(), "parent"), (child, "child")):
            logger.debug(f"{tag} {msg.data} debug")
            logger.info(f"{tag} {msg.data} info")
            logger.error(f"{tag} {msg.data} error")
    served.create_subscription(String, "output", said, 10)
    asker = Node("asker")
    pub = asker.create_publisher(String, "output", 10)
    setter = asker.create_client(SetLoggerLevels, "served/set_logger_levels")
    getter = asker.create_client(GetLoggerLevels, "served/get_logger_levels")
    executor = SingleThreadedExecutor()
    executor.add_node(served)
    thread = threading.Thread(target=executor.spin)
    thread.start()
    setter.wait_for_service(10)
    def levels():
        f = getter.call_async(GetLoggerLevels.Request(names=["served", "served.child"]))
        rclpy.spin_until_future_complete(asker, f)
        return [l.level for l in f.result().levels]
    def set_(parent, kid):
        f = setter.call_async(SetLoggerLevels.Request(levels=[LoggerLevel(name="served", level=parent), LoggerLevel(name="served.child", level=kid)]))
        rclpy.spin_until_future_complete(asker, f)
        return [r.successful for r in f.result().results]
    time.sleep(0.5)
    print("levels", levels(), flush=True)
    pub.publish(String(data="one")); time.sleep(0.5)
    print("set", set_(int(LoggingSeverity.DEBUG), int(LoggingSeverity.ERROR)), levels(), flush=True)
    pub.publish(String(data="two")); time.sleep(0.5)
    print("set", set_(int(LoggingSeverity.WARN), int(LoggingSeverity.DEBUG)), levels(), flush=True)
    pub.publish(String(data="three")); time.sleep(0.5)
    executor.shutdown()
    thread.join()
print("done", flush=True)
"""


def test_the_logger_service_sets_a_child_logger_apart_from_its_parent(ws):
    """demo_nodes_py's use_logger_service, as rclpy has it: a child logger's level is its own
    once set (unset: 0, and it follows its parent), both got and set through the node's
    logger services, and each logger shows what its own effective level lets through."""
    node_package(ws, "logsvc", {"logsvc.py": LOGGER_SERVICE})
    ws.own_bus()
    done = ws.run("run", "logsvc", "logsvc.py", timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    # as real rclpy (Kilted) prints it, every level on stderr (rcutils' stream)
    printed = done.stdout.splitlines()
    assert printed == ["levels [0, 0]", "set [True, True] [10, 40]",
                       "set [True, True] [30, 10]", "done"], done.stdout
    shown = [line.split("]: ", 1)[1] for line in done.stderr.splitlines() if "]: " in line]
    assert shown == [
        "parent one info", "parent one error", "child one info", "child one error",
        "parent two debug", "parent two info", "parent two error", "child two error",
        "parent three error", "child three debug", "child three info", "child three error"]

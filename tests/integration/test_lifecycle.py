"""Lifecycle nodes (rclpy.lifecycle) on the bus, driven with `launcher lifecycle` as with
`ros2 lifecycle`: states, transitions, a lifecycle publisher that speaks only when active,
transition events, and a transition that is not allowed refused with the ones that are."""

from __future__ import annotations

import signal

from tests.support.nodes import node_package

TALKER = """
import rclpy
from rclpy.lifecycle import Node, State, TransitionCallbackReturn
from std_msgs.msg import String


class LifecycleTalker(Node):
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self._pub = self.create_lifecycle_publisher(String, "lifecycle_chatter", 10)
        self._timer = self.create_timer(0.1, self.publish)
        self.get_logger().info(f"on_configure() is called from {state.label}.")
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info("on_activate() is called.")
        return super().on_activate(state)

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info("on_deactivate() is called.")
        return super().on_deactivate(state)

    def publish(self):
        self._pub.publish(String(data="Lifecycle HelloWorld!"))


rclpy.init()
node = LifecycleTalker("lc_talker")
print("up", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""


def test_a_lifecycle_node_is_driven_through_its_states_from_the_cli(ws):
    ws.own_bus()
    node_package(ws, "lc", {"talker.py": TALKER})
    talker = ws.start("run", "lc", "talker.py", output="talker.txt")
    try:
        ws.wait_for_output("up", 30, "talker.txt")
        assert ws.run("lifecycle", "nodes").stdout == "/lc_talker\n"
        assert ws.run("lifecycle", "get", "/lc_talker").stdout == "unconfigured [1]\n"
        offered = ws.run("lifecycle", "list", "/lc_talker").stdout
        assert offered == ("- configure [1]\n\tStart: unconfigured\n\tGoal: configuring\n"
                           "- shutdown [5]\n\tStart: unconfigured\n\tGoal: shuttingdown\n")
        refused = ws.run("lifecycle", "set", "/lc_talker", "activate")
        assert refused.returncode == 1 and "Traceback" not in refused.stderr
        assert "Unknown transition requested 'activate': /lc_talker is unconfigured, where " \
               "it offers configure, shutdown" in refused.stderr, refused.stderr
        direct = ws.run("service", "call", "/lc_talker/change_state",
                        "lifecycle_msgs/srv/ChangeState", "{transition: {id: 3}}")
        assert "success: false" in direct.stdout, direct  # as lifecycle_msgs reports it
        assert ws.run("lifecycle", "set", "/lc_talker", "configure").stdout == \
            "Transitioning successful\n"
        assert ws.run("lifecycle", "get", "/lc_talker").stdout == "inactive [2]\n"
        quiet = ws.run("topic", "echo", "/lifecycle_chatter", "std_msgs/msg/String", "--once",
                       "--timeout", "1")
        assert quiet.returncode != 0  # inactive: the lifecycle publisher says nothing
        events = ws.start("topic", "echo", "/lc_talker/transition_event",
                          "lifecycle_msgs/msg/TransitionEvent", output="events.txt")
        try:
            ws.wait_for_output("", 2, "events.txt")
            import time

            time.sleep(1.0)
            assert ws.run("lifecycle", "set", "/lc_talker", "3").returncode == 0
            heard = ws.run("topic", "echo", "/lifecycle_chatter", "std_msgs/msg/String",
                           "--once", "--timeout", "10")
            assert "data: Lifecycle HelloWorld!" in heard.stdout, heard
            said = ws.wait_for_output("label: active", 10, "events.txt")
            # (as rcl_lifecycle publishes them: the states, the transition field left empty)
            assert "goal_state:\n  id: 13\n  label: activating" in said, said
            assert "transition:\n  id: 0\n  label: ''" in said, said
        finally:
            events.send_signal(signal.SIGINT)
            events.wait(10)
        assert ws.run("lifecycle", "get", "/lc_talker").stdout == "active [3]\n"
        log = ws.output("talker.txt")
        assert "[lc_talker]: on_configure() is called from unconfigured." in log
        assert "Unable to start transition activate [3] from current state unconfigured: it " \
               "is not allowed there (allowed: configure [1], shutdown [5])" in log, log
        missing = ws.run("lifecycle", "get", "/lc_talkr")
        assert "Node not found: '/lc_talkr' is not a lifecycle node on the graph (did you " \
               "mean '/lc_talker'?)" in missing.stderr, missing.stderr
    finally:
        talker.send_signal(signal.SIGINT)
        assert talker.wait(20) == 0, ws.output("talker.txt")


FAILING = """
import rclpy
from rclpy.lifecycle import Node, State, TransitionCallbackReturn


class Fragile(Node):
    attempts = 0

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.attempts += 1
        if self.attempts == 1:
            return TransitionCallbackReturn.FAILURE  # back to unconfigured
        if self.attempts == 2:
            raise RuntimeError("sensor not found")  # an error: error processing
        return TransitionCallbackReturn.SUCCESS

    def on_error(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info(f"on_error from {state.label}")
        return TransitionCallbackReturn.SUCCESS  # recovered: unconfigured


rclpy.init()
node = Fragile("fragile")
for _ in range(3):
    outcome = node.trigger_configure()
    print("configure", outcome.name, node._current_state.label, flush=True)
print("shutdown", node.trigger_shutdown().name, node._current_state.label, flush=True)
"""


def test_a_failing_or_raising_transition_goes_where_rcl_lifecycle_sends_it(ws):
    ws.own_bus()
    node_package(ws, "fragile", {"fragile.py": FAILING})
    done = ws.run("run", "fragile", "fragile.py", timeout=60)
    assert done.returncode == 0, done.stderr
    out = done.stdout + done.stderr
    assert "configure FAILURE unconfigured" in out, out
    assert "configure ERROR unconfigured" in out and "on_error from configuring" in out, out
    assert "Caught exception in callback for transition 10: sensor not found" in out, out
    assert "configure SUCCESS inactive" in out and "shutdown SUCCESS finalized" in out, out


def wait_state(ws, node: str, state: str, timeout: float = 60) -> None:
    import time

    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if ws.run("lifecycle", "get", node).stdout.startswith(state):
            return
        time.sleep(0.3)
    raise AssertionError(f"{node} never {state}: {ws.run('lifecycle', 'get', node).stdout}")


def test_a_launch_files_lifecycle_node_with_autostart_is_configured_and_activated(ws):
    """launch_ros's `lifecycle_node` (YAML here; XML and Python alike) with `autostart`
    (Jazzy): the launch configures and activates it once it runs, and logs its
    transitions."""
    ws.own_bus()
    node_package(ws, "lc", {"talker.py": TALKER})
    ws.write("managed.launch.yaml", """
    launch:
      - lifecycle_node: {pkg: lc, exec: talker.py, name: managed, namespace: fleet,
                         autostart: true, output: screen}
    """)
    launch = ws.start("launch", "managed.launch.yaml", output="launch.txt")
    try:
        wait_state(ws, "/fleet/managed", "active [3]")
        heard = ws.run("topic", "echo", "/fleet/lifecycle_chatter", "std_msgs/msg/String",
                       "--once", "--timeout", "10")
        assert "Lifecycle HelloWorld!" in heard.stdout, heard
        ws.wait_for_output("/fleet/managed: inactive -> activating", 10, "launch.txt")
    finally:
        launch.send_signal(signal.SIGINT)
        assert launch.wait(30) == 130


EVENTS = """
from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch.events import matches_action
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    node = LifecycleNode(package="lc", executable="talker.py", name="driven", namespace="",
                         output="screen")
    configure = EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                            transition_id=Transition.TRANSITION_CONFIGURE))
    activate = EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                           transition_id=Transition.TRANSITION_ACTIVATE))
    return LaunchDescription([
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=node, goal_state="inactive",
            entities=[LogInfo(msg="CONFIGURED, now activating"), activate])),
        RegisterEventHandler(OnProcessStart(target_action=node, on_start=[configure])),
        node,
    ])
"""


def test_change_state_events_and_on_state_transition_drive_a_node(ws):
    """launch_ros's own pattern: configure when the process starts (EmitEvent of a
    ChangeState matching the node), and on reaching `inactive`, log and activate."""
    ws.own_bus()
    node_package(ws, "lc", {"talker.py": TALKER})
    ws.write("driven.launch.py", EVENTS)
    launch = ws.start("launch", "driven.launch.py", output="launch.txt")
    try:
        wait_state(ws, "/driven", "active [3]")
        ws.wait_for_output("CONFIGURED, now activating", 10, "launch.txt")
    finally:
        launch.send_signal(signal.SIGINT)
        assert launch.wait(30) == 130


def test_a_transition_the_node_refuses_is_reported(ws):
    ws.own_bus()
    node_package(ws, "lc", {"talker.py": TALKER})
    ws.write("refused.launch.py", EVENTS.replace("on_start=[configure]",
                                                 "on_start=[activate]"))
    done = ws.run("launch", "refused.launch.py", "--duration", "6", timeout=90)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "lifecycle node /driven: transition 'activate' failed: the node refused it" in \
        done.stdout + done.stderr
    assert "Traceback" not in done.stdout + done.stderr

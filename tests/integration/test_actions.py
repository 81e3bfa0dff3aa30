"""Actions (rclpy.action) on the bus, in rmw_zenoh's layout: ros2/examples' action servers and
clients, every entry point, unchanged under `launcher run` (as `ros2 run`), printing what they
print on ROS 2; and an independent client, raw Zenoh with rosbags' CDR, sending a goal on the
keys rmw_zenoh uses."""

from __future__ import annotations

import re
import signal
import time

import pytest

from tests.support.environment import shared
from tests.support.nodes import node_package

SERVER, CLIENT = "examples_rclpy_minimal_action_server", "examples_rclpy_minimal_action_client"
SEQUENCE = "array('i', [0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55])"


@pytest.fixture
def examples(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(shared("external", "ros2_examples", "rclpy"))
    return ws


def stop(proc) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(20)


def pair(ws, server: str, client: str, tag: str) -> tuple:
    """A server and a client of their own graph (a run folder each), started."""
    env = {"LAUNCHER_RUN_DIR": str(ws.root / f"run-{tag}")}
    started = ws.start("run", SERVER, server, output=f"{tag}-server.txt", env=env)
    time.sleep(0.5)
    return started, ws.start("run", CLIENT, client, output=f"{tag}-client.txt", env=env)


def lines(text: str) -> list[str]:
    """The messages of a node's log lines, without their stamps."""
    return [re.sub(r"^\[INFO\] \[[\d.]+\] ", "", line) for line in text.splitlines() if line]


def test_every_action_example_runs_unchanged_and_prints_what_ros_2_prints(examples):
    """Five pairs at once, each on its own graph: every server and every client entry point."""
    pairs = {"basic": ("server", "client"), "defer": ("server_defer", "client_not_composable"),
             "cancel": ("server_not_composable", "client_cancel"),
             "single": ("server_single_goal", "client"),
             "queue": ("server_queue_goals", "client_asyncio")}
    started = {tag: pair(examples, *names, tag) for tag, names in pairs.items()}
    try:
        for tag, (_server, client) in started.items():
            assert client.wait(120) == 0, examples.output(f"{tag}-client.txt")
    finally:
        for server, client in started.values():
            if client.poll() is None:
                client.kill()
            assert stop(server) == 0
    said = {tag: (lines(examples.output(f"{tag}-server.txt")),
                  lines(examples.output(f"{tag}-client.txt"))) for tag in pairs}
    server, client = said["basic"]
    assert client[:3] == ["[minimal_action_client]: Waiting for action server...",
                          "[minimal_action_client]: Sending goal request...",
                          "[minimal_action_client]: Goal accepted :)"], client
    assert "[minimal_action_client]: Received feedback: array('i', [0, 1, 1, 2])" in client
    assert client[-1] == f"[minimal_action_client]: Goal succeeded! Result: {SEQUENCE}"
    assert server[:3] == ["[minimal_action_server]: Received goal request",
                          "[minimal_action_server]: Executing goal...",
                          "[minimal_action_server]: Publishing feedback: array('i', [0, 1, 1])"]
    assert server[-1] == f"[minimal_action_server]: Returning result: {SEQUENCE}"
    server, client = said["defer"]
    assert "[minimal_action_server]: Deferring execution..." in server
    assert client[-1] == f"[minimal_action_client]: Goal succeeded! Result: {SEQUENCE}"
    server, client = said["cancel"]
    assert "[minimal_action_server]: Received cancel request" in server
    assert server[-1] == "[minimal_action_server]: Goal canceled"
    assert client[-1] == "[minimal_action_client]: Goal successfully canceled", client
    server, client = said["single"]
    assert client[-1] == f"[minimal_action_client]: Goal succeeded! Result: {SEQUENCE}"
    server, client = said["queue"]
    # two goals at once (queued one after the other by this server), then two in sequence
    assert server.count("[minimal_action_server]: Goal put in the queue") == 1, server
    assert client.count("[minimal_action_client]: result example_interfaces.action."
                        f"Fibonacci_Result(sequence={SEQUENCE}) and status flag 4") == 2, client
    assert client[-1] == ("[minimal_action_client]: B) result example_interfaces.action."
                          f"Fibonacci_Result(sequence={SEQUENCE}) and status flag 4"), client


QUICK_SERVER = """
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer
from rclpy.node import Node


def execute(goal_handle):
    sequence = [0, 1]
    for _ in range(1, goal_handle.request.order):
        sequence.append(sequence[-1] + sequence[-2])
        goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
    goal_handle.succeed()
    return Fibonacci.Result(sequence=sequence)


rclpy.init()
node = Node("quick_server")
server = ActionServer(node, Fibonacci, "fibonacci", execute)
print("ready", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""


def test_an_independent_client_finds_and_uses_the_action_on_rmw_zenohs_keys(examples):
    """Raw Zenoh with rosbags' CDR (tests/integration/clients/raw_action_client.py): the
    endpoints' liveliness tokens as rmw_zenoh writes them (three services, two publishers),
    a goal accepted on send_goal's key, feedback and status on their topics, the result."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    node_package(examples, "quick", {"quick_server.py": QUICK_SERVER})
    server = examples.start("run", "quick", "quick_server.py", output="server.txt")
    try:
        examples.wait_for_output("ready", 30, "server.txt")
        settings = examples.run("env", "--zenoh").stdout
        uri = settings.strip().split("=", 1)[1]
        client = Path(__file__).parent / "clients" / "raw_action_client.py"
        done = subprocess.run([sys.executable, str(client)], capture_output=True, text=True,
                              timeout=60, env={**examples.env, "ZENOH_SESSION_CONFIG_URI": uri,
                                               "PYTHONPATH": os.pathsep.join(sys.path)})
        assert done.returncode == 0, done.stdout + done.stderr + examples.output("server.txt")
        out = done.stdout
        kinds = dict(re.findall(r"^endpoint (\w+) (SS|MP) ", out, re.M))
        assert kinds == {"cancel_goal": "SS", "feedback": "MP", "get_result": "SS",
                         "send_goal": "SS", "status": "MP"}, out
        assert "example_interfaces::action::dds_::Fibonacci_SendGoal_ RIHS01_" in out, out
        assert "action_msgs::srv::dds_::CancelGoal_ RIHS01_" in out, out
        assert "accepted True" in out and "result 4 [0, 1, 1, 2, 3, 5]" in out, out
        assert "feedback [0, 1, 1, 2, 3, 5]" in out and "statuses [4]" in out, out
    finally:
        assert stop(server) == 0, examples.output("server.txt")


def test_the_action_cli_lists_describes_and_sends_goals_as_ros2_action_does(examples):
    server = examples.start("run", SERVER, "server", output="server.txt")
    try:
        examples.wait_for_output("", 5, "server.txt")
        listed = examples.run("action", "list", "-t")
        for _ in range(50):  # (the server's tokens take a moment to spread)
            if "/fibonacci" in listed.stdout:
                break
            time.sleep(0.1)
            listed = examples.run("action", "list", "-t")
        assert listed.stdout == "/fibonacci [example_interfaces/action/Fibonacci]\n", listed
        info = examples.run("action", "info", "/fibonacci").stdout
        assert info == ("Action: /fibonacci\nAction clients: 0\nAction servers: 1\n"
                        "    /minimal_action_server\n"), info
        assert examples.run("action", "type", "/fibonacci").stdout == \
            "example_interfaces/action/Fibonacci\n"
        # its topics and services are hidden names: left out of the lists, as ros2 does
        topics = examples.run("topic", "list").stdout.split()
        assert "/fibonacci/_action/status" not in topics
        assert "/fibonacci/_action/status" in \
            examples.run("topic", "list", "--include-hidden-topics").stdout.split()
        assert "/fibonacci/_action/send_goal" not in \
            examples.run("service", "list").stdout.split()
        assert "/fibonacci/_action/send_goal" in \
            examples.run("service", "list", "--include-hidden-services").stdout.split()
        sent = examples.run("action", "send_goal", "/fibonacci",
                            "example_interfaces/action/Fibonacci", "{order: 2}", "--feedback",
                            timeout=60)
        assert sent.returncode == 0, sent.stderr
        out = sent.stdout
        assert out.startswith("Waiting for an action server to become available...\n"
                              "Sending goal:\n     order: 2\n\nGoal accepted with ID: "), out
        assert re.search(r"Goal accepted with ID: [0-9a-f]{32}\n\nFeedback:\n    sequence:\n"
                         r"- 0\n- 1\n- 1\n", out), out
        assert out.endswith("Result:\n    sequence:\n- 0\n- 1\n- 1\n\n"
                            "Goal finished with status: SUCCEEDED\n"), out
        # bad input: a server that is not there, a malformed goal, an unknown type
        missing = examples.run("action", "send_goal", "/fibonaci",
                               "example_interfaces/action/Fibonacci", "{order: 2}",
                               "--timeout", "1")
        assert missing.returncode == 1 and "Traceback" not in missing.stderr
        assert ("no action server for /fibonaci (example_interfaces/action/Fibonacci) after "
                "1 s (did you mean '/fibonacci'?); the graph's actions: /fibonacci") \
            in missing.stderr, missing.stderr
        malformed = examples.run("action", "send_goal", "/fibonacci",
                                 "example_interfaces/action/Fibonacci", "{order: many}")
        assert malformed.returncode == 2
        assert "the goal for example_interfaces/action/Fibonacci: order: expected int32, got " \
               "'many'" in malformed.stderr, malformed.stderr
        unknown = examples.run("action", "send_goal", "/fibonacci",
                               "example_interfaces/action/Fibonaci", "{order: 2}")
        assert unknown.returncode == 2 and "did you mean 'example_interfaces/action/" \
            "Fibonacci'" in unknown.stderr, unknown.stderr
    finally:
        assert stop(server) == 0


def test_an_action_file_with_a_mistake_is_an_error_at_its_line_and_column(examples):
    """A package's own `.action` file, found with no build step; one that is wrong is an
    error at its file:line:column."""
    examples.write("ws/my_actions/package.xml", """
    <?xml version="1.0"?>
    <package format="3"><name>my_actions</name><version>0.1.0</version><description>a
    </description><maintainer email="a@b.c">a</maintainer><license>MIT</license></package>
    """)
    examples.write("ws/my_actions/action/Dock.action",
                   "string station\n---\nbool docked\n---\nfloat32 distance\n")
    examples.write("ws/my_actions/action/Broken.action",
                   "string station\n---\nbool docked\nfloat32[ distance\n---\nint8 x\n")
    examples.write("ws/my_actions/action/Short.action", "string station\n---\nbool docked\n")
    import os

    examples.env["LAUNCHER_PACKAGE_PATH"] += os.pathsep + str(examples.root / "ws")
    shown = examples.run("interface", "show", "my_actions/action/Dock")
    assert shown.returncode == 0, shown.stderr
    assert "string station\n---\nbool docked\n---\nfloat32 distance" in shown.stdout, shown
    broken = examples.run("action", "send_goal", "/dock", "my_actions/action/Broken", "{}")
    assert broken.returncode != 0 and "Traceback" not in broken.stderr
    assert f"{examples.root}/ws/my_actions/action/Broken.action:4:1: invalid message " \
           "definition: cannot read 'float32[ distance'" in broken.stderr, broken.stderr
    short = examples.run("action", "send_goal", "/dock", "my_actions/action/Short", "{}")
    assert "Short.action: an .action file needs exactly two '---' lines (goal, result, " \
           "feedback), found 1" in short.stderr, short.stderr


NO_SERVER = """
import time
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient
from rclpy.node import Node
rclpy.init()
node = Node("lonely_client")
client = ActionClient(node, Fibonacci, "nobody_serves_this")
start = time.monotonic()
print("ready", client.wait_for_server(timeout_sec=0.5), client.server_is_ready(),
      round(time.monotonic() - start, 1) < 3)
"""


def test_waiting_for_a_server_that_is_not_there_ends_with_false(examples):
    node_package(examples, "lonely", {"client.py": NO_SERVER})
    done = examples.run("run", "lonely", "client.py", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "ready False False True" in done.stdout, done.stdout

"""Actions (rclpy.action) on the bus, in rmw_zenoh's layout: ros2/examples' action servers and
clients, every entry point, unchanged under `launcher run` (as `ros2 run`), printing what they
print on ROS 2; and an independent client, raw Zenoh with rosbags' CDR, sending a goal on the
keys rmw_zenoh uses."""

from __future__ import annotations

import re
import signal
import time

import pytest

from tests.conftest import shared
from tests.integration.test_node_apis import node_package

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

"""`launcher topic` with the flags ros2 users type, against a live node over real sessions."""

from __future__ import annotations

import signal
import sys

import pytest
import yaml

from tests.support.nodes import script_launched

PY = sys.executable
# Joint states stamped with the wall clock, 20 a second, and a latched string.
STATES = """
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
node = Node("states")
pub = node.create_publisher("sensor_msgs/msg/JointState", "joint_states")
node.create_publisher("std_msgs/msg/String", "banner", LATCHED).publish(
    node.message("std_msgs/msg/String", data="hello"))
count = [0]

def tick():
    count[0] += 1
    pub.publish(node.message("sensor_msgs/msg/JointState",
        header={"stamp": node.get_clock().now().to_msg(), "frame_id": "base_link"},
        name=["left", "right"], position=[float(count[0]), -1.0]))

node.create_timer(0.05, tick)
node.get_logger().info("publishing")
node.spin()
node.destroy_node()
"""


@pytest.fixture
def states(ws):
    with script_launched(ws.own_bus(), "states.py", STATES, "publishing") as running:
        yield running


def echo(ws, *flags: str) -> str:
    result = ws.run("topic", "echo", "/joint_states", "--once", *flags, timeout=60)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_echo_flags(states):
    short = yaml.safe_load(echo(states, "--no-arr").split("---")[0])
    assert short["name"] == "<sequence type: string, length: 2>"
    assert short["position"] == "<sequence type: double, length: 2>"
    assert short["header"]["frame_id"] == "base_link"
    no_str = yaml.safe_load(echo(states, "--no-str").split("---")[0])
    assert no_str["header"]["frame_id"] == "<string length: <9>>"
    assert no_str["name"] == ["<string length: <4>>", "<string length: <5>>"]
    cut = yaml.safe_load(echo(states, "-l", "1").split("---")[0])
    assert cut["name"] == ["l...", "..."] and cut["header"]["frame_id"] == "b..."
    whole = yaml.safe_load(echo(states, "-f").split("---")[0])
    assert whole["name"] == ["left", "right"]
    flow = echo(states, "--flow-style").split("---")[0].strip()
    assert flow.startswith("{header: {stamp: {sec: ") and "\n" not in flow
    later = yaml.safe_load(echo(states, "--filter", "m.position[0] > 40 and "
                                                   "m.header.frame_id == 'base_link'")
                           .split("---")[0])
    assert later["position"][0] > 40  # messages before it were not printed
    raw = echo(states, "--raw").split("---")[0].strip()
    assert raw[2:18] == r'\x00\x01\x00\x00' and "base_link" in raw  # CDR, little endian


def test_echo_qos_flags(states):
    latched = states.run("topic", "echo", "/banner", "--once", "--timeout", "3",
                         "--qos-durability", "transient_local")
    assert latched.returncode == 0 and "data: hello" in latched.stdout
    missed = states.run("topic", "echo", "/banner", "std_msgs/msg/String", "--once",
                        "--timeout", "1.5", "--qos-durability", "volatile")
    assert missed.returncode == 1 and "no message on /banner within 1.5 s" in missed.stderr
    sensor = states.run("topic", "echo", "/joint_states", "--once", "--qos-profile",
                        "sensor_data", "--qos-depth", "1", "--field", "name")
    assert sensor.returncode == 0 and "left" in sensor.stdout


@pytest.mark.parametrize("flags, message", [
    (("--filter", "m.nosuch > 1"), "--filter: no field 'nosuch'"),
    (("--filter", "x.data"), "unknown name 'x'"),
    (("--filter", "m.data ==",), "invalid expression"),
    (("--filter", "__import__('os')"), "unknown name '__import__'"),
    (("--qos-profile", "fast"), "invalid choice: 'fast'"),
    (("--qos-depth", "0"), "expected a whole number > 0"),
    (("-l", "2", "-f"), "not allowed with argument"),
], ids=["unknown-field", "unknown-name", "syntax", "no-python", "profile", "depth",
        "length-and-full"])
def test_echo_bad_flags(states, flags, message):
    result = states.run("topic", "echo", "/joint_states", "--once", "--timeout", "3", *flags)
    assert result.returncode != 0 and message in result.stderr, result.stderr
    assert "Traceback" not in result.stderr


def watch(ws, name: str, *args: str, needle: str) -> str:
    """Run `launcher topic ARGS…` until `needle` shows, then Ctrl-C it."""
    proc = ws.start("topic", *args, output=name)
    try:
        text = ws.wait_for_output(needle, 30, name)
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) in (0, 130)
    return text


def test_bw_delay_and_verbose_info(states):
    bw = watch(states, "bw.txt", "bw", "/joint_states", needle="Message size mean")
    assert "Subscribed to [/joint_states]" in bw
    line = next(li for li in bw.splitlines() if "/s from " in li)
    rate, unit = line.split()[:2]
    assert unit in ("B/s", "KB/s") and float(rate) > 0
    delay = watch(states, "delay.txt", "delay", "/joint_states", needle="average delay")
    mean = float(next(li for li in delay.splitlines() if "average delay" in li).split()[-1])
    assert 0 <= mean < 1.0  # stamped with the wall clock just before it was sent
    no_header = states.run("topic", "delay", "/banner")
    assert no_header.returncode == 2 and "has no header.stamp" in no_header.stderr
    info = states.run("topic", "info", "-v", "/joint_states").stdout
    assert "Publisher count: 1" in info and "Node name: states\nNode namespace: /\n" in info
    assert "Endpoint type: PUBLISHER" in info and "Topic type: sensor_msgs/msg/JointState" in info
    assert "  Reliability: RELIABLE\n  History (Depth): KEEP_LAST (10)\n" \
           "  Durability: VOLATILE" in info

"""foxglove_bridge, served to Foxglove's own client: @foxglove/ws-protocol (npm) driven by
Node.js, decoding with @foxglove/rosmsg2-serialization (tests/js/foxglove_client.js), against
the demo's real sim, bridge and robot_state_publisher on a real router; the token asked of
every connection, as the user nobody too."""

from __future__ import annotations

import json
import os
import re
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from launcher.bus.types import registry
from tests.support.environment import REPO
from tests.support.processes import tagged_processes
from tests.support.waiting import free_port, wait_for

LAUNCH = str(REPO / "launch_files" / "robot.launch.yaml")
CLIENT = REPO / "tests" / "js" / "foxglove_client.js"
TWIST = "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n" + "=" * 80 + \
    "\nMSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n"


def client(url: str, *steps: dict, timeout: float = 120,
           protocols: tuple[str, ...] = ()) -> list[dict]:
    """Foxglove's client, run by node, through `steps` (offering `protocols`, when given, as
    its WebSocket subprotocols): its JSON lines."""
    node = shutil.which("node")
    assert node, "the set-up installs Node.js (nodejs) for these tests"
    done = subprocess.run([node, str(CLIENT), url, json.dumps(list(steps)),
                           *([",".join(protocols)] if protocols else [])],
                          capture_output=True, text=True, timeout=timeout,
                          cwd=CLIENT.parent)
    lines = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    assert lines, done.stdout + done.stderr
    return lines


def found(lines: list[dict], key: str) -> dict:
    return next(line for line in lines if key in line)


@pytest.fixture
def served(ws):
    """The demo (not driving) and a foxglove_bridge on a port of the test's; its URL."""
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")
    port = free_port()
    demo = ws.start("launch", LAUNCH, "drive:=false", output="demo.out")
    bridge = ws.start("run", "foxglove_bridge", "foxglove_bridge", "--ros-args", "-p",
                      f"port:={port}", output="bridge.out")
    try:
        url = wait_for(lambda: re.search(r"Foxglove connects to (ws://\S+)",
                                         ws.output("bridge.out")), 60).group(1)
        wait_for(lambda: "/odom" in ws.run("topic", "list").stdout.split(), 90)
        yield ws, url, port
    finally:
        for proc in (bridge, demo):
            proc.send_signal(2)
        for proc in (bridge, demo):
            proc.wait(60)


def odom_x(ws) -> float:
    out = ws.run("topic", "echo", "/odom", "--once", "--field", "pose.pose.position.x").stdout
    return float(re.findall(r"-?\d+\.\d+(?:e-?\d+)?", out)[0])


def test_foxglove_client_sees_decodes_drives_and_calls_through_the_token(served):
    ws, url, port = served
    assert re.fullmatch(rf"ws://127\.0\.0\.1:{port}/\?token=\S+", url)
    token = url.split("token=")[1]
    assert (ws.root / "run" / "domain-0.token").read_text().strip() == token
    start = odom_x(ws)
    lines = client(
        url,
        {"do": "channels", "topic": "/odom"},
        {"do": "echo", "topic": "/odom", "count": 2},
        {"do": "publish", "topic": "/cmd_vel", "type": "geometry_msgs/msg/Twist",
         "schema": TWIST, "message": {"linear": {"x": 1.0, "y": 0, "z": 0},
                                      "angular": {"x": 0, "y": 0, "z": 0}},
         "hz": 10, "seconds": 4},
        {"do": "call", "service": "/robot_state_publisher/list_parameters",
         "request": {"prefixes": [], "depth": 0}},
        {"do": "asset", "uri": "package://robot_description/urdf/robot.xacro"},
        {"do": "asset", "uri": "package://robot_description/../../../../etc/passwd"},
        {"do": "asset", "uri": "file:///etc/passwd"},
        {"do": "parameters", "names": ["/robot_state_publisher.robot_description"]},
        {"do": "graph"})
    connected = found(lines, "connected")
    assert connected["connected"] == "foxglove_bridge"
    assert {"clientPublish", "services", "connectionGraph", "parameters"} <= \
        set(connected["capabilities"])
    odom = next(c for c in found(lines, "channels")["channels"] if c["topic"] == "/odom")
    assert (odom["encoding"], odom["schemaName"], odom["schemaEncoding"]) == \
        ("cdr", "nav_msgs/msg/Odometry", "ros2msg")
    assert odom["schema"] == registry().definition("nav_msgs/msg/Odometry")
    assert "MSG: geometry_msgs/PoseWithCovariance" in odom["schema"]
    message = found(lines, "echo")["messages"][0]
    assert message["child_frame_id"] and message["header"]["frame_id"]
    assert abs(message["pose"]["pose"]["position"]["x"] - start) < 0.2  # the sim's, at rest
    assert found(lines, "published")["sent"] >= 30
    moved = odom_x(ws) - start
    assert abs(moved) > 0.3, moved  # the client's Twist drove the robot
    called = found(lines, "called")
    assert "robot_description" in called["response"]["result"]["names"], called
    assets = [line for line in lines if "asset" in line]
    assert assets[0]["status"] == 0 and assets[0]["size"] > 100, assets[0]
    assert [a["status"] for a in assets[1:]] == [1, 1]  # refused: outside, and not allowed
    parameters = found(lines, "parameters")["parameters"]
    assert [p["name"] for p in parameters] == ["/robot_state_publisher.robot_description"]
    assert "<robot" in parameters[0]["value"]
    graph = found(lines, "graph")["graph"]
    published = {t["name"]: t["publisherIds"] for t in graph["publishedTopics"]}
    assert "/odom" in published and published["/odom"]


def test_a_client_offering_only_the_protocols_old_name_is_served(served):
    """@foxglove/ws-protocol's own client offers only `foxglove.websocket.v1` (as older
    Foxglove and Lichtblick apps do); the SDK takes only `foxglove.sdk.v1`. Through the
    front, it connects, is answered with the name it offered, and receives /odom."""
    _, url, _ = served
    lines = client(url, {"do": "echo", "topic": "/odom", "count": 2},
                   protocols=("foxglove.websocket.v1",))
    assert found(lines, "connected")["protocol"] == "foxglove.websocket.v1", lines
    assert len(found(lines, "echo")["messages"]) == 2, lines


def test_without_the_token_every_connection_is_refused(served):
    ws, url, port = served
    base = url.split("?")[0]
    for wrong in (base, f"{base}?token=not-it", f"{base}?token="):
        assert found(client(wrong), "refused")["refused"] == 403


HANDSHAKE = """
import socket, sys
port, token = int(sys.argv[1]), sys.argv[2]
for query in ("", "?token=" + token):
    with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
        sock.sendall(("GET /" + query + " HTTP/1.1\\r\\nHost: 127.0.0.1\\r\\n"
                      "Upgrade: websocket\\r\\nConnection: Upgrade\\r\\n"
                      "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\\r\\n"
                      "Sec-WebSocket-Version: 13\\r\\nSec-WebSocket-Protocol: foxglove.sdk.v1"
                      "\\r\\n\\r\\n").encode())
        print(sock.recv(200).split(b"\\r\\n")[0].decode())
"""


@pytest.mark.skipif(os.geteuid() != 0, reason="needs root to act as another user")
def test_another_user_is_refused_without_the_token_and_served_with_it(served):
    """As the user nobody: the front refuses the handshake without the token, and the SDK's
    own server, in the bridge's private network, is nowhere on this host's ports."""
    ws, url, port = served
    token = url.split("token=")[1]
    done = subprocess.run(["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups",
                           "/usr/bin/python3", "-c", HANDSHAKE, str(port), token],
                          capture_output=True, text=True, timeout=60, cwd="/")
    assert done.returncode == 0, done.stderr
    refused, served_line = done.stdout.splitlines()
    assert refused.startswith("HTTP/1.1 403") and served_line.startswith("HTTP/1.1 101")
    import psutil

    bridge = next(p for p in tagged_processes(ws.tag)
                  if "launcher.nodes.foxglove:main" in " ".join(p.cmdline()))
    ports = {c.laddr.port for c in bridge.net_connections("inet")
             if c.status == psutil.CONN_LISTEN}
    assert ports == {port}  # the front alone: the SDK's listener is in its own network


def test_bad_clients_leave_the_bridge_serving_the_others(served):
    """A client subscribing to 10,000 channel ids, publishing on a channel it never
    advertised, sending a frame far over the size cap or text that is not JSON, publishing
    bytes that are not its schema's, and calling a service that is gone: each is refused or
    dropped, said in the bridge's log, and another client is served as before."""
    ws, url, port = served
    start = odom_x(ws)
    for what in ("subscribe10000", "unadvertised"):
        lines = client(url, {"do": "abuse", "what": what}, {"do": "wait", "seconds": 0.5})
        assert found(lines, "abused")["abused"] == what
    garbage = client(url, {"do": "abuse", "what": "garbage"}, {"do": "wait", "seconds": 1})
    assert found(garbage, "status")["level"] == 2  # an error status: "Invalid message"
    oversized = client(url, {"do": "abuse", "what": "oversized", "bytes": 80 * 1024 * 1024},
                       {"do": "wait_closed", "seconds": 5})
    assert found(oversized, "abused")["abused"] == "oversized"
    # over the SDK's 16 MiB cap: refused from the frame's header, the client dropped (its
    # close reaches it at once, or once its own sending gives up: the SDK's timing)
    wait_for(lambda: "Message too long: 83886080 > 16777216" in ws.output("bridge.out"), 20)
    mismatched = client(url, {"do": "publish", "topic": "/cmd_vel",
                              "type": "geometry_msgs/msg/Twist", "raw": [1, 2, 3],
                              "hz": 20, "seconds": 2})
    assert found(mismatched, "published")["sent"] >= 10
    wait_for(lambda: "is not a geometry_msgs/msg/Twist in CDR: dropped" in
             ws.output("bridge.out"), 20)
    assert abs(odom_x(ws) - start) < 0.05  # nothing reached the robot
    # a service that goes: the call fails, and says so, instead of hanging
    source = ws.start("rostopic", "pub", "-r", "5", "/mux_in", "std_msgs/String", "x",
                      output="source.out")
    mux = ws.start("run", "topic_tools", "mux", "/mux_out", "/mux_in", output="mux.out")
    try:
        listed = client(url, {"do": "call", "service": "/mux/list", "request": {}})
        assert found(listed, "called")["response"]["topics"] == ["/mux_in"]
        mux.send_signal(2)
        mux.wait(30)
        gone = client(url, {"do": "call", "service": "/mux/list", "request": {},
                            "seconds": 20})
        assert "failed" in found(gone, "called"), gone
    finally:
        for proc in (mux, source):
            if proc.poll() is None:
                proc.send_signal(2)
                proc.wait(30)
    # and the bridge serves a well-behaved client as before
    lines = client(url, {"do": "echo", "topic": "/odom", "count": 3})
    assert len(found(lines, "echo")["messages"]) == 3
    assert "Traceback" not in ws.output("bridge.out")


def test_rviz2_points_to_the_running_bridge_and_a_real_rviz2_wins(served):
    ws, url, port = served
    config = REPO / "tests" / "unit" / "missing.rviz"
    assert not config.exists()
    ws.env["HOME"] = str(ws.root)
    ws.write("view.rviz", "Visualization Manager:\n  Global Options: {Fixed Frame: odom}\n"
                          "  Displays:\n    - {Class: rviz_default_plugins/Odometry, "
                          "Topic: /odom}\n")
    rviz = ws.start("run", "rviz2", "rviz2", "-d", str(ws.root / "view.rviz"),
                    output="rviz.out")
    try:
        wait_for(lambda: "import the layout" in ws.output("rviz.out"), 60)
        assert f"connect Foxglove (the app, or app.foxglove.dev) to {url}" in \
            ws.output("rviz.out")  # the running bridge's address: no second bridge
    finally:
        rviz.send_signal(2)
        assert rviz.wait(30) == 0
    # a real rviz2 earlier on PATH is the one that runs, with the same arguments
    real = ws.root / "real-ros"
    real.mkdir()
    (real / "rviz2").write_text('#!/bin/sh\necho "REAL-rviz2 $*"\n')
    (real / "rviz2").chmod(0o755)
    ws.env["PATH"] = f"{real}:{ws.env['PATH']}"
    done = ws.run("run", "rviz2", "rviz2", "-d", "x.rviz")
    assert done.stdout.strip() == "REAL-rviz2 -d x.rviz", done.stdout + done.stderr
    wrong = ws.run("rviz2-layout", str(config))
    assert wrong.returncode == 1 and "cannot read the rviz config" in wrong.stderr


def test_the_packages_launch_file_serves_sim_time_and_the_latched_robot(served):
    """`ros2 launch foxglove_bridge foxglove_bridge_launch.xml`, as the ROS package ships it,
    with use_sim_time: the server's time is the sim's /clock; the latched /robot_description
    and /tf_static reach a client that comes after them (the 3D panel draws the robot)."""
    ws, url, _ = served
    port = free_port()
    launched = ws.start("launch", "foxglove_bridge", "foxglove_bridge_launch.xml",
                        f"port:={port}", "use_sim_time:=true", output="launched.out")
    try:
        other = wait_for(lambda: re.search(r"Foxglove connects to (ws://\S+)",
                                           ws.output("launched.out")), 60).group(1)
        assert f":{port}/?token=" in other and other.split("?")[1] == url.split("?")[1]
        lines = client(other, {"do": "time", "seconds": 2},
                       {"do": "echo", "topic": "/robot_description", "count": 1},
                       {"do": "echo", "topic": "/tf_static", "count": 1})
        assert "time" in found(lines, "connected")["capabilities"]
        times = found(lines, "times")["times"]
        assert len(times) > 10 and times == sorted(times)
        assert times[-1] < 3600 * 1e9  # sim time: seconds since the sim began, not the epoch
        description = [line for line in lines if line.get("echo") == "/robot_description"]
        assert "<robot" in description[0]["messages"][0]["data"]
        static = [line for line in lines if line.get("echo") == "/tf_static"]
        assert static[0]["messages"][0]["transforms"]
    finally:
        launched.send_signal(2)
        assert launched.wait(30) == 130


ISOLATED = """
import socket
from launcher.nodes.foxglove import isolation
isolation.enter_user_namespace()
network = isolation.PrivateNetwork()

def serve():
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen()
    return listener

inner = network.call(serve)
port = inner.getsockname()[1]
try:
    socket.create_connection(("127.0.0.1", port), timeout=2).close()
    print("REACHABLE FROM THE HOST")
except OSError:
    print("PRIVATE")
network.call(lambda: socket.create_connection(("127.0.0.1", port), timeout=2)).close()
print("INSIDE OK")
outside = socket.socket()
outside.bind(("127.0.0.1", 0))
outside.listen()
socket.create_connection(outside.getsockname(), timeout=2).close()
print("HOST OK")
"""


@pytest.mark.skipif(os.geteuid() != 0, reason="needs root to act as another user")
def test_the_private_network_works_for_a_user_other_than_root():
    """The bridge's isolation as most users run it, not root: a user namespace of its own,
    then one thread's network namespace; the rest of the process stays on the host's
    network. (launcher's Python files are copied where the user nobody can read them.)"""
    import tempfile

    copy = Path(tempfile.mkdtemp(prefix="launcher-nobody-"))
    try:
        shutil.copytree(REPO / "launcher", copy / "launcher",
                        ignore=shutil.ignore_patterns("__pycache__", "builtin", "*.so"))
        for path in [copy, *copy.rglob("*")]:
            path.chmod(0o755 if path.is_dir() else 0o644)
        done = subprocess.run(["setpriv", "--reuid=nobody", "--regid=nogroup",
                               "--clear-groups", "/usr/bin/python3", "-c", ISOLATED], cwd="/",
                              capture_output=True, text=True, timeout=60,
                              env={"PYTHONPATH": str(copy), "PATH": "/usr/bin:/bin"})
    finally:
        shutil.rmtree(copy, ignore_errors=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["PRIVATE", "INSIDE", "OK", "HOST", "OK"], done.stdout


@pytest.mark.skipif(os.geteuid() != 0, reason="needs root to act as another user")
def test_where_user_namespaces_are_restricted_the_bridge_says_what_to_do():
    """As the user nobody, where user namespaces cannot be made (as Ubuntu 24.04 restricts
    them; here: a namespace whose limit is 0): no way keeps the SDK's server from the other
    users, so the bridge does not start, says why and what to do, leaves nothing listening,
    and shows no traceback. (launcher's Python files are copied where nobody can read them.)"""
    import tempfile

    copy = Path(tempfile.mkdtemp(prefix="launcher-nobody-"))
    port = free_port()
    try:
        shutil.copytree(REPO / "launcher", copy / "launcher",
                        ignore=shutil.ignore_patterns("__pycache__", "builtin", "*.so"))
        for path in [copy, *copy.rglob("*")]:
            path.chmod(0o755 if path.is_dir() else 0o644)
        done = subprocess.run(
            [sys.executable, str(REPO / "tests/integration/clients/without_user_namespaces.py"),
             "/usr/bin/python3", "-c", "import sys; from launcher.nodes.foxglove import main; "
             "sys.exit(main())", "--ros-args", "-p", f"port:={port}"],
            cwd=copy, env={"PATH": "/usr/bin:/bin", "PYTHONPATH": str(copy), "HOME": "/"},
            capture_output=True, text=True, timeout=60)
    finally:
        shutil.rmtree(copy, ignore_errors=True)
    said = done.stdout + done.stderr
    assert done.returncode == 1, said
    assert "cannot start behind the graph's token" in said, said
    assert "user.max_user_namespaces=0" in said and "sudo sysctl -w" in said, said
    assert "token:=false" in said and "every local user can watch and command" in said, said
    assert "Traceback" not in said, said
    with pytest.raises(OSError):  # nothing listens on the port
        socket.create_connection(("127.0.0.1", port), timeout=1).close()


def test_ubuntus_apparmor_restriction_gets_the_profile_that_lifts_it(tmp_path):
    """Where AppArmor restricts user namespaces (Ubuntu 24.04's default), the advice is the
    AppArmor profile for launcher's Python, which keeps the token."""
    from launcher.nodes.foxglove.isolation import advice

    (tmp_path / "kernel").mkdir()
    (tmp_path / "kernel" / "apparmor_restrict_unprivileged_userns").write_text("1\n")
    said = advice("a network namespace", "Operation not permitted", str(tmp_path))
    assert "kernel.apparmor_restrict_unprivileged_userns=1" in said
    assert f"profile launcher-foxglove {os.path.realpath(sys.executable)} " \
           "flags=(unconfined) {\\n  userns,\\n}" in said, said
    assert "sudo apparmor_parser -r /etc/apparmor.d/launcher-foxglove" in said


def test_a_subscribed_parameter_sends_its_changes(served):
    ws, url, _ = served
    name = "/foxglove_bridge.max_qos_depth"
    watcher = subprocess.Popen([shutil.which("node"), str(CLIENT), url, json.dumps(
        [{"do": "paramwatch", "names": [name], "seconds": 8}])], stdout=subprocess.PIPE,
        text=True, cwd=CLIENT.parent)
    time.sleep(3)
    changed = ws.run("param", "set", "/foxglove_bridge", "max_qos_depth", "30")
    assert changed.returncode == 0, changed.stderr
    out, _ = watcher.communicate(timeout=60)
    updates = next(json.loads(line) for line in out.splitlines() if "parameterUpdates" in line)
    values = [p["value"] for p in updates["parameterUpdates"] if p["name"] == name]
    assert values[0] == 25 and values[-1] == 30, values  # the value, then its change


def test_the_bridges_parameters_are_described_from_their_declarations(served):
    ws, _, _ = served
    described = ws.run("param", "describe", "/foxglove_bridge", "port")
    assert described.returncode == 0, described.stderr
    text = described.stdout
    assert "Type: integer" in text and "Description: the WebSocket port" in text, text
    assert "Min value: 1" in text and "Max value: 65535" in text, text


def test_token_false_serves_without_the_token_and_warns(ws):
    ws.own_bus()
    port = free_port()
    bridge = ws.start("run", "foxglove_bridge", "foxglove_bridge", "--ros-args", "-p",
                      f"port:={port}", "-p", "token:=false", output="bridge.out")
    try:
        url = wait_for(lambda: re.search(r"Foxglove connects to (ws://\S+)",
                                         ws.output("bridge.out")), 60).group(1)
        assert url == f"ws://127.0.0.1:{port}/"
        assert "the token check is off" in ws.output("bridge.out")
        assert found(client(url), "connected")["connected"] == "foxglove_bridge"
    finally:
        bridge.send_signal(2)
        bridge.wait(30)


IMAGES = """
import sys, time
from launcher.bus.node import Node
from launcher.bus.types import registry
node = Node("camera_like")
message = node.message("sensor_msgs/msg/Image", height=480, width=640, encoding="rgb8",
                       step=1920, data=[0] * (640 * 480 * 3))
payload = registry().serialize(message, "sensor_msgs/msg/Image")
publisher = node.create_publisher("sensor_msgs/msg/Image", "/camera_like")
begin = time.monotonic()
while time.monotonic() - begin < float(sys.argv[1]):
    publisher.publish_raw(payload)
    time.sleep(1 / 30)
node.destroy_node()
"""


def test_a_slow_client_loses_frames_and_the_others_do_not_wait(served):
    """A client that stops reading for 10 s while 30 images a second come: the bridge keeps
    a bounded queue for it (frames are dropped, not piled up), and another client receives
    throughout."""
    ws, url, _ = served
    images = subprocess.Popen([sys.executable, "-c", IMAGES, "25"], env=ws.env, cwd=ws.root)
    try:
        wait_for(lambda: "/camera_like" in ws.run("topic", "list").stdout.split(), 30)
        slow = subprocess.Popen([shutil.which("node"), str(CLIENT), url, json.dumps(
            [{"do": "stall", "topic": "/camera_like", "seconds": 10}])],
            stdout=subprocess.PIPE, text=True, cwd=CLIENT.parent)
        time.sleep(3)
        fast = client(url, {"do": "rate", "topic": "/camera_like", "seconds": 5})
        out, _ = slow.communicate(timeout=60)
    finally:
        images.wait(60)
    stalled = next(json.loads(line) for line in out.splitlines() if "stalled" in line)
    sent_meanwhile = 30 * (stalled["seconds"] + 3)  # (about: at 30 Hz, the stall and after)
    assert stalled["after"] < sent_meanwhile - 100, stalled  # dropped, not all kept for it
    assert stalled["after"] > 0  # and it reads on afterwards
    assert found(fast, "rate")["count"] > 30  # the other client was served meanwhile

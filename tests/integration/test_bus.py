"""The bus with real processes and real Zenoh sessions."""

from __future__ import annotations

import signal
import subprocess
import sys
import time

import pytest

from launcher.bus.discovery import answers
from tests.support.nodes import TALKER, launch, stop, wait_text
from tests.support.processes import launcher_argv

PY = sys.executable
LISTENER = """
from launcher.bus.node import Node
node = Node("listener")
gain = node.declare_parameter("gain", 1.0).value
sub = node.create_subscription("geometry_msgs/msg/Twist", "cmd_vel",
                               lambda m: print("heard", m.linear.x * gain, flush=True))
print("listening on", sub.topic, "as", node.fully_qualified_name, "gain", gain, flush=True)
node.spin()
node.destroy_node()
"""


@pytest.fixture
def bus(ws):
    ws.own_bus()
    ws.write("talker.py", TALKER)
    ws.write("listener.py", LISTENER)
    return ws


def graph_socket(ws, domain: int = 0):
    return ws.root / "run" / f"domain-{domain}.sock"




# A launch that hosts the graph: a Python program may be a node, so the launch starts the
# graph's router with it (a launch of system programs alone starts none).
IDLE = "launch:\n  - executable: {{cmd: {py} -c 'import time; time.sleep({seconds})'}}\n"




def wait_for_router(ws, timeout: float = 20, domain: int = 0) -> str:
    """The endpoint of the graph's router of this workspace, once it answers."""
    deadline = time.monotonic() + timeout
    while not answers(graph_socket(ws, domain)):
        assert time.monotonic() < deadline, "no router started"
        time.sleep(0.05)
    return f"unixsock-stream/{graph_socket(ws, domain)}"


def wait_router_gone(ws, timeout: float = 20) -> None:
    deadline = time.monotonic() + timeout
    while answers(graph_socket(ws)):
        assert time.monotonic() < deadline, "the router did not stop"
        time.sleep(0.1)






def test_topic_cli_against_a_live_node_and_latched_delivery(bus):
    proc, out = launch(bus, "talk.launch.yaml",
                       f"launch:\n  - executable: {{cmd: {PY} talker.py 1.5, output: screen}}\n")
    wait_text(out, "talking on /cmd_vel")
    listing = bus.run("topic", "list", "-t")
    assert "/cmd_vel [geometry_msgs/msg/Twist]" in listing.stdout, listing.stderr
    echo = bus.run("topic", "echo", "/cmd_vel", "--once")
    assert "linear:\n  x: 1.5" in echo.stdout, echo.stderr
    field = bus.run("topic", "echo", "cmd_vel", "--field", "linear.x", "--once")
    assert field.stdout.startswith("1.5"), field.stderr
    latched = bus.run("topic", "echo", "/robot_description", "--once")
    assert "data: <robot name='r'/>" in latched.stdout  # a late subscriber gets it
    info = bus.run("topic", "info", "/cmd_vel")
    assert "Publisher count: 1" in info.stdout
    verbose = bus.run("topic", "list", "-v").stdout
    published = verbose.split("Subscribed topics:")[0]
    assert published.startswith("Published topics:\n")
    assert " * /cmd_vel [geometry_msgs/msg/Twist] 1 publisher\n" in published
    count = bus.run("topic", "list", "-c").stdout
    assert int(count) == len(bus.run("topic", "list").stdout.split())
    assert bus.run("topic", "type", "/cmd_vel").stdout == "geometry_msgs/msg/Twist\n"
    unknown = bus.run("topic", "type", "/cmd_vle")
    assert unknown.returncode == 1 and "did you mean '/cmd_vel'" in unknown.stderr
    found = bus.run("topic", "find", "geometry_msgs/msg/Twist").stdout.split()
    assert found == ["/cmd_vel"]
    assert stop(proc) == 130
    assert "process stopped" in out.read_text()


def test_launches_of_one_domain_share_its_graph_and_other_domains_stay_apart(bus):
    body = "launch:\n  - executable: {{cmd: {py} {script} {v}, output: screen}}\n"
    first, out1 = launch(bus, "one.launch.yaml", body.format(py=PY, script="talker.py", v="1.0"))
    other, out2 = launch(bus, "two.launch.yaml", body.format(py=PY, script="talker.py", v="2.0"),
                         env={"ROS_DOMAIN_ID": "7"})
    wait_text(out1, "talking")
    wait_text(out2, "talking")
    listener, out3 = launch(bus, "three.launch.yaml",
                            body.format(py=PY, script="listener.py", v=""))
    wait_text(out3, "heard 1.0")  # a second launch of domain 0 joins the first one's graph
    seen = {bus.run("topic", "echo", "/cmd_vel", "--field", "linear.x", "--once").stdout.split()[0]
            for _ in range(3)}
    assert seen == {"1.0"}
    bus.env["ROS_DOMAIN_ID"] = "7"
    seen = {bus.run("topic", "echo", "/cmd_vel", "--field", "linear.x", "--once").stdout.split()[0]
            for _ in range(3)}
    assert seen == {"2.0"}
    assert answers(graph_socket(bus, 0)) and answers(graph_socket(bus, 7))
    assert stop(first) == 130  # the launch that started the router ends: the others go on
    bus.env.pop("ROS_DOMAIN_ID")
    bus.run("topic", "pub", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {x: 4.5}}",
            "--times", "3", "--rate", "10")
    wait_text(out3, "heard 4.5")
    assert "heard 2.0" not in out3.read_text()
    assert stop(listener) == 130 and stop(other) == 130
    wait_router_gone(bus)  # nothing uses domain 0 any more: its router stops


def test_a_standing_router_stands_for_another_host(bus):
    host_a, out_a = launch(bus, "a.launch.yaml",
                           f"launch:\n  - executable: {{cmd: {PY} talker.py 7.0}}\n")
    port = free_port()
    standing = bus.start("router", "--listen", f"tcp/127.0.0.1:{port}", output="router.out")
    wait_text(bus.root / "router.out", f"tcp/127.0.0.1:{port}")
    other_host = {"LAUNCHER_ROUTER": f"tcp/127.0.0.1:{port}",
                  "LAUNCHER_RUN_DIR": str(bus.root / "elsewhere")}
    host_b, out_b = launch(bus, "b.launch.yaml",
                           f"launch:\n  - executable: {{cmd: {PY} listener.py, output: screen}}\n",
                           env=other_host)
    wait_text(out_b, "heard 7.0")
    assert not (bus.root / "elsewhere" / "domain-0.sock").exists()  # it started no router
    assert stop(host_b) == 130 and stop(host_a) == 130
    assert stop(standing) == 0


def free_port() -> int:
    import socket

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def test_names_params_and_topic_pub_into_a_node(bus):
    proc, out = launch(bus, "l.launch.yaml", (
        f"launch:\n  - executable:\n      cmd: {PY} listener.py --ros-args -r __ns:=/r1 "
        "-r cmd_vel:=/fleet/cmd -p gain:=2.0\n      output: screen\n"))
    wait_text(out, "listening on /fleet/cmd as /r1/listener gain 2.0")
    published = bus.run("topic", "pub", "/fleet/cmd", "geometry_msgs/msg/Twist",
                        "{linear: {x: 1.25}}", "--times", "3", "--rate", "10")
    assert published.returncode == 0, published.stderr
    assert "publisher: beginning loop\npublishing #1: geometry_msgs.msg.Twist(linear=" \
           "geometry_msgs.msg.Vector3(x=1.25, y=0.0, z=0.0), angular=" in published.stdout
    every_other = bus.run("topic", "pub", "/fleet/cmd", "std_msgs/msg/Empty", "-t", "4",
                          "-r", "20", "-p", "2", "-w", "0")
    assert every_other.stdout.count("publishing #") == 2 and "#2: std_msgs.msg.Empty()\n" \
        in every_other.stdout
    nobody = bus.run("topic", "pub", "/nobody", "std_msgs/msg/Empty", "--once",
                     "--max-wait-time-secs", "0.5")
    assert nobody.returncode == 1
    assert "Waiting for at least 1 matching subscription(s)..." in nobody.stdout
    assert "timed out waiting for 1 subscription(s) on /nobody" in nobody.stderr
    wait_text(out, "heard 2.5")
    assert stop(proc) == 130


def test_a_malformed_payload_is_dropped_and_the_node_goes_on(bus):
    proc, out = launch(bus, "l.launch.yaml",
                       f"launch:\n  - executable: {{cmd: {PY} listener.py, output: screen}}\n")
    wait_text(out, "listening on /cmd_vel")
    endpoint = wait_for_router(bus)
    injector = bus.write("inject.py", f"""
import time, zenoh
from launcher.bus import keys
from launcher.bus.session import config
from launcher.bus.types import registry
s = zenoh.open(config("client", [], ["{endpoint}"]))
key = keys.topic_key(0, "/cmd_vel", "geometry_msgs/msg/Twist",
                     registry().type_hash("geometry_msgs/msg/Twist"))
time.sleep(0.3)
for _ in range(3):
    s.put(key, b"garbage")
time.sleep(0.2)
s.close()
""")
    subprocess.run([PY, str(injector)], env=bus.env, check=True, timeout=30)
    text = wait_text(out, "dropped a malformed geometry_msgs/msg/Twist message on /cmd_vel")
    assert text.count("dropped a malformed") == 1  # said once per topic
    bus.run("topic", "pub", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {x: 3.0}}",
            "--times", "2", "--rate", "10")
    wait_text(out, "heard 3.0")  # still running
    assert stop(proc) == 130


@pytest.mark.parametrize("args, expected, code", [
    (["topic", "pub", "/x", "geometry_msgs/msg/Twits", "{}"],
     "unknown message type 'geometry_msgs/msg/Twits' (did you mean 'geometry_msgs/msg/Twist'",
     1),
    (["topic", "pub", "/x", "geometry_msgs/msg/Twist", "{linear: {x: fast}}"],
     "linear.x: expected float64, got 'fast'", 1),
    (["topic", "pub", "/x", "geometry_msgs/msg/Twist", "{linear: [1,"],
     "the message is not valid YAML", 2),
    (["topic", "echo", "/bad-name", "std_msgs/msg/String", "--once"],
     "invalid topic name '/bad-name': the part 'bad-name' holds a character other than", 1),
    (["topic", "echo", "/quiet", "std_msgs/msg/String", "--timeout", "1"],
     "no message on /quiet within 1 s", 1),  # (without --once too)
], ids=["unknown-type", "yaml-does-not-fit", "yaml-invalid", "invalid-topic",
        "echo-timeout-nothing"])
def test_cli_bad_input(bus, args, expected, code):
    proc, out = launch(bus, "idle.launch.yaml", IDLE.format(py=PY, seconds=30))
    wait_for_router(bus)
    result = bus.run(*args, timeout=30)
    assert result.returncode == code and expected in result.stderr, result.stderr
    assert "Traceback" not in result.stderr
    assert stop(proc) == 130


def test_no_router_reachable_is_a_clear_error(bus):
    bus.env["LAUNCHER_ROUTER"] = "tcp/127.0.0.1:9"
    bus.env["LAUNCHER_BUS_TIMEOUT"] = "1"
    start = time.monotonic()
    result = bus.run("topic", "list", timeout=30)
    assert result.returncode == 1 and time.monotonic() - start < 15
    assert "no router answered at tcp/127.0.0.1:9 within 1 s" in result.stderr
    assert "Traceback" not in result.stderr
    assert not (bus.root / "run" / "domain-0.sock").exists()  # it started none
    bus.env.pop("LAUNCHER_ROUTER")
    nothing = bus.run("topic", "list", timeout=30)  # nothing running: an empty graph
    assert nothing.returncode == 0 and nothing.stdout == "", nothing.stderr
    wait_router_gone(bus)


def test_bag_record_info_play_round_trip(bus):
    talker, out = launch(bus, "talk.launch.yaml",
                         f"launch:\n  - executable: {{cmd: {PY} talker.py 4.0, output: screen}}\n")
    wait_text(out, "talking")
    recorded = bus.run("bag", "record", "/cmd_vel", "-o", "run1", "--duration", "2", timeout=60)
    assert recorded.returncode == 0, recorded.stderr
    count = int(recorded.stdout.split("recorded ")[1].split()[0])
    assert 5 <= count <= 50  # 20 Hz for 2 s, less the time to find the topic
    assert stop(talker) == 130

    info = bus.run("bag", "info", "run1")
    assert "Topic: /cmd_vel | Type: geometry_msgs/msg/Twist | Count: " in info.stdout
    from mcap.reader import make_reader  # the file opens with the mcap library
    (mcap_file,) = (bus.root / "run1").glob("*.mcap")
    with open(mcap_file, "rb") as handle:
        messages = list(make_reader(handle).iter_messages())
    assert len(messages) == count and messages[0][1].topic == "/cmd_vel"
    from rosbags.rosbag2 import Reader

    from launcher.bus.types import registry
    with Reader(bus.root / "run1") as reader:
        (connection, _, data), *_ = reader.messages()
        assert registry().deserialize(data, connection.msgtype).linear.x == 4.0

    listener, heard = launch(bus, "l.launch.yaml",
                             f"launch:\n  - executable: {{cmd: {PY} listener.py, output: screen}}\n")
    wait_text(heard, "listening")
    played = bus.run("bag", "play", "run1", "--rate", "4", timeout=60)
    assert played.returncode == 0 and f"played {count} messages" in played.stdout
    wait_text(heard, "heard 4.0")
    assert stop(listener) == 130
    again = bus.run("bag", "record", "/cmd_vel", "-o", "run1", "--duration", "1")
    assert again.returncode == 2 and "already exists" in again.stderr


SERVER = """
from launcher.bus.node import Node
node = Node("switch")
state = {"on": False}
def set_bool(request, response):
    if request.data and state["on"]:
        raise RuntimeError("already on")
    state["on"] = request.data
    response.success, response.message = True, f"now {'on' if request.data else 'off'}"
    return response
node.create_service("std_srvs/srv/SetBool", "~/enable", set_bool)
print("serving", flush=True)
node.spin()
node.destroy_node()
"""


def test_services_round_trip_and_the_cli(bus):
    bus.write("server.py", SERVER)
    proc, out = launch(bus, "s.launch.yaml",
                       f"launch:\n  - executable: {{cmd: {PY} server.py, output: screen}}\n")
    wait_text(out, "serving")
    listing = bus.run("service", "list", "-t")
    assert "/switch/enable [std_srvs/srv/SetBool]" in listing.stdout, listing.stderr
    called = bus.run("service", "call", "/switch/enable", "std_srvs/srv/SetBool", "{data: true}")
    assert called.returncode == 0, called.stderr
    assert "success: true" in called.stdout and "message: now on" in called.stdout
    failed = bus.run("service", "call", "/switch/enable", "std_srvs/srv/SetBool", "{data: true}")
    assert failed.returncode == 1 and "RuntimeError: already on" in failed.stderr
    nodes = bus.run("node", "list")
    assert nodes.stdout.split() == ["/switch"]
    info = bus.run("node", "info", "/switch")
    servers = info.stdout.split("Service Servers:\n")[1].split("  Service Clients:")[0]
    assert "    /switch/enable: std_srvs/srv/SetBool\n" in servers, info.stdout
    assert "    /switch/describe_parameters: rcl_interfaces/srv/DescribeParameters" in servers
    silent = bus.run("service", "call", "/nobody", "std_srvs/srv/Trigger", "--timeout", "0.5")
    assert silent.returncode == 1 and "did not answer within 0.5 s" in silent.stderr
    unknown = bus.run("service", "call", "/x", "std_srvs/srv/Trigr")
    assert unknown.returncode == 1 and "did you mean 'std_srvs/srv/Trigger" in unknown.stderr
    assert bus.run("service", "type", "/switch/enable").stdout == "std_srvs/srv/SetBool\n"
    assert bus.run("service", "find", "std_srvs/srv/SetBool").stdout.split() == \
        ["/switch/enable"]
    info = bus.run("service", "info", "/switch/enable").stdout
    assert info.startswith("Type: std_srvs/srv/SetBool\nClients count: ") and \
        info.endswith("Services count: 1\n")
    misspelt = bus.run("service", "type", "/switch/enabel")
    assert misspelt.returncode == 1 and "did you mean '/switch/enable'" in misspelt.stderr
    repeated = subprocess.Popen(launcher_argv() + ["service", "call", "/switch/enable",
                                "std_srvs/srv/SetBool", "{data: false}", "-r", "5"],
                                cwd=bus.root, env=bus.env, stdout=subprocess.PIPE, text=True)
    answers = 0
    while answers < 3:  # one call after another, at 5 Hz, until Ctrl-C
        answers += "response:" in repeated.stdout.readline()
    hidden = bus.run("node", "list", "-a").stdout.split()  # (its node begins with '_')
    assert "/switch" in hidden and "/_launcher_service_call" in hidden
    assert bus.run("node", "list").stdout.split() == ["/switch"]
    repeated.send_signal(signal.SIGINT)
    assert repeated.wait(10) in (0, 130)
    assert stop(proc) == 130


def test_param_list_get_set_on_a_live_node(bus):
    proc, out = launch(bus, "l.launch.yaml", (
        f"launch:\n  - executable:\n      cmd: {PY} listener.py --ros-args -p gain:=2.0 "
        "-p label:=left\n      output: screen\n"))
    wait_text(out, "listening")
    listing = bus.run("param", "list", "/listener")
    assert listing.stdout.split() == ["/listener:", "gain", "label"], listing.stderr
    assert bus.run("param", "get", "/listener", "gain").stdout.strip() == "Double value is: 2.0"
    assert bus.run("param", "get", "/listener", "label").stdout.strip() == \
        "String value is: left"
    assert "Set parameter successful" in bus.run("param", "set", "/listener", "gain", "3").stdout
    assert bus.run("param", "get", "/listener", "gain").stdout.strip() == "Integer value is: 3"
    dumped = bus.run("param", "dump", "/listener")
    assert dumped.stdout == "/listener:\n  ros__parameters:\n    gain: 3\n    label: left\n"
    bus.write("tuned.yaml", "/**:\n  ros__parameters:\n    gain: 4.5\n    pid:\n      p: 1.0\n")
    loaded = bus.run("param", "load", "/listener", "tuned.yaml")
    assert loaded.stdout == "Set parameter gain successful\nSet parameter pid.p successful\n"
    assert bus.run("param", "get", "/listener", "pid.p").stdout.strip() == "Double value is: 1.0"
    assert "    pid:\n      p: 1.0\n" in bus.run("param", "dump", "/listener").stdout
    bus.write("other.yaml", "/talker:\n  ros__parameters:\n    gain: 1.0\n")
    wrong = bus.run("param", "load", "/listener", "other.yaml")
    assert wrong.returncode == 1 and "other.yaml has no parameters for /listener" in wrong.stderr
    missing = bus.run("param", "get", "/nobody", "x", "--timeout", "0.5")
    assert missing.returncode == 1 and "did not answer" in missing.stderr
    assert stop(proc) == 130


def test_a_node_never_destroyed_still_lets_its_program_exit(bus):
    proc, out = launch(bus, "idle.launch.yaml", IDLE.format(py=PY, seconds=30))
    wait_for_router(bus)
    script = bus.write("forgetful.py", """
from launcher.bus.node import Node
node = Node("forgetful")
node.create_service("std_srvs/srv/Trigger", "~/poke", lambda req, res: res)
print("done", flush=True)
""")
    result = subprocess.run([PY, str(script)], env=bus.env, capture_output=True, text=True,
                            timeout=30)
    assert result.returncode == 0 and "done" in result.stdout
    assert stop(proc) == 130


def test_a_session_never_closed_still_lets_its_program_exit(bus):
    """A program of launcher's bus API that subscribes on a session and never closes it:
    Zenoh's callback thread once held it at its exit for good."""
    script = bus.write("unclosed.py", """
from launcher.bus.session import open_session
session = open_session()
subscriber = session.declare_subscriber("any/key", lambda sample: None)
print("subscribed", flush=True)
""")
    result = subprocess.run([PY, str(script)], env=bus.env, capture_output=True, text=True,
                            timeout=30)
    assert result.returncode == 0 and "subscribed" in result.stdout, result.stderr


def test_use_sim_time_follows_clock(bus):
    bus.write("timed.py", """
from launcher.bus.node import Node
node = Node("timed")
def report():
    now = node.get_clock().now()
    if now.nanoseconds:
        print("sim time", now.seconds, flush=True)
node.create_timer(0.05, report)
print("sim", node.get_clock().use_sim_time, flush=True)
node.spin()
node.destroy_node()
""")
    proc, out = launch(bus, "t.launch.yaml", (
        f"launch:\n  - executable:\n      cmd: {PY} timed.py --ros-args -p use_sim_time:=true\n"
        "      output: screen\n"))
    wait_text(out, "sim True")
    bus.run("topic", "pub", "/clock", "rosgraph_msgs/msg/Clock",
            "{clock: {sec: 42, nanosec: 500000000}}", "--times", "3", "--rate", "10")
    wait_text(out, "sim time 42.5")
    assert stop(proc) == 130


def test_a_node_alone_starts_the_graph_which_stops_after_it(bus):

    node = subprocess.Popen([PY, "talker.py", "9.0"], cwd=bus.root, env=bus.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        assert "talking" in node.stdout.readline()
        echo = bus.run("topic", "echo", "/cmd_vel", "--field", "linear.x", "--once")
        assert echo.stdout.startswith("9.0"), echo.stderr
        hz = subprocess.Popen(launcher_argv() + ["topic", "hz", "/cmd_vel", "-w", "5"],
                              cwd=bus.root, env=bus.env, stdout=subprocess.PIPE, text=True)
        line, figures = hz.stdout.readline(), hz.stdout.readline()
        hz.send_signal(signal.SIGINT)
        hz.wait(10)
        rate = float(line.split()[2])
        assert 5 < rate < 40  # published at 20 Hz
        assert figures.startswith("\tmin: ") and figures.rstrip().endswith("window: 6")
        csv = bus.run("topic", "echo", "/cmd_vel", "--csv", "--once")
        assert csv.stdout.strip() == "9.0,0.0,0.0,0.0,0.0,0.0"
    finally:
        node.send_signal(signal.SIGINT)
        node.wait(10)
    wait_router_gone(bus)


LINKS = """
import sys, time
from launcher.bus.node import Node
node = Node(sys.argv[1])
print("up", flush=True)
time.sleep(1.5)
info = node.session.info
print(len(list(info.peers_zid())), len(list(info.routers_zid())), flush=True)
node.destroy_node()
"""


def test_nodes_link_to_the_router_alone_not_to_one_another(bus):
    """A star, not a mesh: n nodes make n links (a mesh made n(n-1)/2, 4,950 for 100)."""
    bus.write("links.py", LINKS)
    nodes = [subprocess.Popen([PY, "links.py", f"n{i}"], cwd=bus.root, env=bus.env,
                              stdout=subprocess.PIPE, text=True) for i in range(3)]
    try:
        assert [node.stdout.readline().strip() for node in nodes] == ["up"] * 3
        assert [node.stdout.readline().split() for node in nodes] == [["0", "1"]] * 3
    finally:
        for node in nodes:
            try:
                node.wait(20)
            except subprocess.TimeoutExpired:
                node.kill()
                node.wait()


def test_a_node_started_with_sigint_ignored_still_stops_on_it(bus):
    """`python node.py &` in a script starts it with SIGINT ignored; a node still stops on
    Ctrl-C and on a launch's SIGINT (rclpy's init does the same)."""
    node = subprocess.Popen([PY, "talker.py", "2.0"], cwd=bus.root, env=bus.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_IGN))
    assert "talking" in node.stdout.readline()
    heard = bus.run("topic", "echo", "/cmd_vel", "--once", "--field", "linear.x")
    assert heard.stdout.startswith("2.0"), heard.stderr  # its timer runs: it is in spin()
    node.send_signal(signal.SIGINT)
    assert node.wait(10) == 0  # spin() ends quietly on Ctrl-C
    wait_router_gone(bus)


# A signal that lands while destroy_node() undeclares: sent from inside the subscription's own
# destroy, so it lands there every time (`timeout -s INT` sends its second one about then).
SIGNAL_IN_TEARDOWN = """
import os, signal, sys, threading
from launcher.bus.node import Node
node = Node("teardown")
sub = node.create_subscription("geometry_msgs/msg/Twist", "cmd_vel", print)
destroy = sub.destroy
def destroy_under_a_signal():
    os.kill(os.getpid(), signal.SIGINT)
    sum(range(100000))  # Python runs the handler here
    destroy()
sub.destroy = destroy_under_a_signal
if sys.argv[1] == "second":
    threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT)).start()
    node.spin()  # the first Ctrl-C ends it
try:
    node.destroy_node()
    print("destroyed, entities left:", len(node.host.entities), flush=True)
except KeyboardInterrupt:
    print("interrupted after, entities left:", len(node.host.entities), flush=True)
"""


def test_a_second_ctrl_c_during_destroy_node_lets_it_finish(bus):
    bus.write("teardown.py", SIGNAL_IN_TEARDOWN)
    proc = subprocess.run([PY, "teardown.py", "second"], cwd=bus.root, env=bus.env,
                          capture_output=True, text=True, timeout=30)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout == "destroyed, entities left: 0\n"  # the stop under way is the answer


def test_a_ctrl_c_during_destroy_node_is_raised_once_it_is_done(bus):
    bus.write("teardown.py", SIGNAL_IN_TEARDOWN)
    proc = subprocess.run([PY, "teardown.py", "first"], cwd=bus.root, env=bus.env,
                          capture_output=True, text=True, timeout=30)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout == "interrupted after, entities left: 0\n"


# Subscribers on the topics come and go all the time, so the latched publishers' matching
# callbacks keep asking for the GIL on Zenoh's threads while the node is destroyed.
CHURN = """
import sys, time
from launcher.bus.node import Node
node = Node("churner")
print("churning", flush=True)
while True:
    subs = [node.create_subscription("std_msgs/msg/String", f"t{i}", print) for i in range(20)]
    time.sleep(0.005)
    for sub in subs:
        sub.destroy()
"""
LATCHED_ROUNDS = """
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
for round in range(10):
    node = Node(f"latched{round}")
    for i in range(20):
        node.create_publisher("std_msgs/msg/String", f"t{i}", LATCHED)
    node.spin(0.2)
    node.destroy_node()
    print("destroyed", round, flush=True)
"""


def test_latched_entities_are_destroyed_while_their_matching_callbacks_fire(bus):
    """zenoh-python undeclares an advanced publisher holding the GIL while it waits for a
    task on Zenoh's thread, which may itself wait for the GIL to run a matching callback:
    destroy_node() hung (a container of robots outlived SIGINT and SIGTERM). Ten nodes of
    latched entities, each destroyed under a churn of subscribers, all finish."""
    bus.write("churn.py", CHURN)
    bus.write("rounds.py", LATCHED_ROUNDS)
    churn = subprocess.Popen([PY, "churn.py"], cwd=bus.root, env=bus.env,
                             stdout=subprocess.PIPE, text=True)
    try:
        assert churn.stdout.readline() == "churning\n"
        rounds = subprocess.run([PY, "rounds.py"], cwd=bus.root, env=bus.env,
                                capture_output=True, text=True, timeout=30)
    finally:
        churn.kill()
        churn.wait()
    assert rounds.returncode == 0, rounds.stderr
    assert rounds.stdout.splitlines()[-1] == "destroyed 9"


def test_bag_record_all_includes_latched_topics(bus):
    talker, out = launch(bus, "talk.launch.yaml",
                         f"launch:\n  - executable: {{cmd: {PY} talker.py 2.0, output: screen}}\n")
    wait_text(out, "talking")
    recorded = bus.run("bag", "record", "-a", "-o", "everything", "--duration", "1.5",
                       timeout=60)
    assert recorded.returncode == 0, recorded.stderr
    assert "messages on /cmd_vel" in recorded.stdout
    assert "recorded 1 messages on /robot_description" in recorded.stdout
    assert stop(talker) == 130
    nothing = bus.run("bag", "record", "-o", "x")
    assert nothing.returncode == 2 and "name the topics to record, or -a" in nothing.stderr


LATE_LISTENER = """
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
node = Node("waiter")
node.create_subscription("std_msgs/msg/String", "/late", lambda m: print("got", m.data,
                         flush=True), LATCHED)
print("waiting", flush=True)
node.spin(20)
node.destroy_node()
"""
# An rmw_zenoh-style latched publisher that appears after the subscriber and whose one message
# is put before anyone listens: only zenoh-ext's advanced publisher cache holds it.
CACHE_ONLY = """
import sys, time
import zenoh, zenoh.ext
from launcher.bus import keys
from launcher.bus.messages import build
from launcher.bus.session import open_session
from launcher.bus.types import registry
types = registry()
name = "std_msgs/msg/String"
key = keys.topic_key(keys.domain(), "/late", name, types.type_hash(name))
payload = bytes(types.serialize(build(name, {"data": "latched"}), name))
session = open_session("peer")
publisher = zenoh.ext.declare_advanced_publisher(
    session, key, cache=zenoh.ext.CacheConfig(1), publisher_detection=True)
publisher.put(payload)
entity = keys.Entity(str(session.zid()), 1, 1, keys.PUBLISHER, "", "cache", "/late", name,
                     types.type_hash(name), ":1:,1:,:,:,,")
token = session.liveliness().declare_token(keys.liveliness_key(keys.domain(), entity))
print("serving", flush=True)
time.sleep(float(sys.argv[1]))
token.undeclare(); publisher.undeclare(); session.close()
"""


def test_a_latched_subscriber_gets_what_a_later_publisher_holds(bus):
    proc, _ = launch(bus, "idle.launch.yaml", IDLE.format(py=PY, seconds=60))
    bus.env["LAUNCHER_ROUTER"] = wait_for_router(bus)
    bus.write("waiter.py", LATE_LISTENER)
    bus.write("cache.py", CACHE_ONLY)
    waiter = subprocess.Popen([PY, "waiter.py"], cwd=bus.root, env=bus.env,
                              stdout=subprocess.PIPE, text=True)
    try:
        assert waiter.stdout.readline().strip() == "waiting"  # its first fetch found nothing
        cache = subprocess.Popen([PY, "cache.py", "5"], cwd=bus.root, env=bus.env,
                                 stdout=subprocess.DEVNULL)
        line = waiter.stdout.readline().strip()  # the new publisher's token: fetched again
        assert line == "got latched", line
        cache.wait(30)
    finally:
        waiter.send_signal(signal.SIGINT)
        waiter.wait(30)
        assert stop(proc) == 130


CLOCK = """
import time
from launcher.bus.node import Node
node = Node("clock")
pub = node.create_publisher("rosgraph_msgs/msg/Clock", "/clock")
while pub.get_subscription_count() == 0:
    time.sleep(0.01)
for tenth in range(1, 101):  # 10 s of sim time in about half a second
    sec, rest = divmod(tenth, 10)
    pub.publish(node.message("rosgraph_msgs/msg/Clock",
                             clock={"sec": sec, "nanosec": rest * 100_000_000}))
    time.sleep(0.005)
time.sleep(0.5)
node.destroy_node()
"""

SIM_TIMED = """
import time
{imports}
start = time.monotonic()
def fired():
    print("fired", round({now}, 3), round(time.monotonic() - start, 2), flush=True)
{make_timer}
print("ready", flush=True)
{spin}
"""


def sim_timer_fires(bus, script: str) -> list[tuple[float, float]]:
    """(sim time, wall time) of each call of a 1 s timer on sim time, while /clock runs 10 s
    of sim time in half a second of wall time, after 1.5 s of wall time with no /clock."""
    bus.write("timed.py", script)
    proc, out = launch(bus, "t.launch.yaml", (
        f"launch:\n  - executable:\n      cmd: {PY} timed.py --ros-args -p use_sim_time:=true\n"
        "      output: screen\n"))
    wait_text(out, "ready")
    time.sleep(1.5)
    bus.write("clock.py", CLOCK)
    subprocess.run([PY, "clock.py"], cwd=bus.root, env=bus.env, timeout=60, check=True)
    assert stop(proc) == 130
    return [(float(line.split()[2]), float(line.split()[3]))
            for line in out.read_text().splitlines() if "fired" in line]


def assert_kept_sim_time(fires: list[tuple[float, float]]) -> None:
    """A 1 s timer called at each second of sim time, none before the /clock came (after
    1.5 s of wall time), and ten sim seconds in well under ten of wall time."""
    assert [round(sim) for sim, _ in fires] == list(range(1, 11))
    assert fires[0][1] > 1.4
    assert fires[-1][1] - fires[0][1] < 1.5


def test_a_bus_timer_on_a_sim_time_clock_keeps_sim_time(bus):
    fires = sim_timer_fires(bus, SIM_TIMED.format(
        imports="from launcher.bus.node import Node\nnode = Node('timed')",
        now="node.get_clock().now().seconds",
        make_timer="node.create_timer(1.0, fired, node.get_clock())",
        spin="node.spin()"))
    assert_kept_sim_time(fires)


def test_an_rclpy_timer_on_a_sim_time_node_keeps_sim_time(bus):
    fires = sim_timer_fires(bus, SIM_TIMED.format(
        imports="import rclpy\nrclpy.init()\nnode = rclpy.create_node('timed')",
        now="node.get_clock().now().nanoseconds / 1e9",
        make_timer="node.create_timer(1.0, fired)",
        spin="rclpy.spin(node)"))
    assert_kept_sim_time(fires)

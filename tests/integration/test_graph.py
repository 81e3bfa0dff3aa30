"""One graph per user and domain, as in ROS 2: the running demo seen and driven from other
shells and by an independent rmw_zenoh client, the router's life, other users kept out, and
the bad inputs of connecting. Real processes, real routers, a real third-party client."""

from __future__ import annotations

import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from launcher.bus.discovery import answers
from tests.support.environment import REPO
from tests.support.processes import launcher_argv

CLIENTS = Path(__file__).parent / "clients"


@pytest.fixture
def demo(ws):
    """The demo, undriven, on a graph of this test's own; stopped (and checked) after."""
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")
    proc = ws.start("launch", str(REPO / "launch_files" / "robot.launch.yaml"), "drive:=false",
                    output="demo.out")
    ws.wait_for_output("spawned 'my_robot'", 90, "demo.out")
    yield ws
    proc.send_signal(signal.SIGINT)
    assert proc.wait(30) == 130


def odometry(ws, field: str) -> float:
    result = ws.run("topic", "echo", "/odom", "--once", "--field", field, timeout=60)
    assert result.returncode == 0, result.stderr
    return float(result.stdout.split()[0])


def test_a_second_shell_spawns_into_the_running_demo_and_a_third_sees_it(demo):
    second = demo.run("launch", "robot_description", "spawn.launch.yaml", "x:=6",
                      "name:=second_model", "--duration", "4", timeout=90)
    assert "spawned 'second_model' into world 'robot'" in second.stdout, second.stdout
    models = demo.run("gz", "model", "--list")
    assert "- second_model" in models.stdout and "- my_robot" in models.stdout
    assert odometry(demo, "pose.pose.position.z") == pytest.approx(0.0, abs=0.2)


def test_an_independent_rmw_zenoh_client_lists_hears_and_drives_the_demo(demo, tmp_path):
    settings = demo.run("env", "--zenoh")
    assert settings.returncode == 0, settings.stderr
    config = settings.stdout.strip().removeprefix("export ZENOH_SESSION_CONFIG_URI=")
    assert Path(config).stat().st_mode & 0o077 == 0
    socket_endpoint = f"unixsock-stream/{demo.root / 'run' / 'domain-0.sock'}"
    env = {**demo.env, "ZENOH_SESSION_CONFIG_URI": config,
           "ZENOH_CONFIG_OVERRIDE": f'connect/endpoints=["{socket_endpoint}"]',
           "GIT_PYTHON_REFRESH": "quiet"}
    client = subprocess.Popen([sys.executable, str(CLIENTS / "sdk_client.py"),
                               str(tmp_path / "definitions"), "6"], env=env, cwd=tmp_path,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        lines: list[str] = []
        for line in client.stdout:
            lines.append(line.strip())
            if line.startswith("publishing"):
                break
        topics = {line.split()[1]: line.split()[2] for line in lines
                  if line.startswith("topic ")}
        assert topics.get("/odom") == "nav_msgs/msg/Odometry", lines
        assert topics.get("/robot_description") == "std_msgs/msg/String", lines
        assert topics.get("/clock") == "rosgraph_msgs/msg/Clock", lines  # once: the bridge's
        assert "odom yes" in lines and "robot_description yes" in lines, "\n".join(lines)
        # launcher's own tools see the client's publisher and node, and the robot turns
        time.sleep(1.0)
        info = demo.run("topic", "info", "/cmd_vel", "-v")
        assert "sdk_driver" in info.stdout, info.stdout
        assert "/sdk_driver" in demo.run("node", "list").stdout
        assert odometry(demo, "twist.twist.angular.z") > 1.0  # the client asks for 1.5 rad/s
        assert client.wait(60) == 0, client.stdout.read()
    finally:
        if client.poll() is None:
            client.kill()
            client.wait()


TALKER = """
from launcher.bus.node import Node
node = Node("talker")
pub = node.create_publisher("std_msgs/msg/String", "chatter")
node.create_timer(0.05, lambda: pub.publish(node.message("std_msgs/msg/String", data="hi")))
node.spin()
"""
LISTENER = """
from launcher.bus.node import Node
node = Node("listener")
node.create_subscription("std_msgs/msg/String", "chatter",
                         lambda m: print("heard", m.data, flush=True))
node.spin()
"""


def test_routers_life_one_for_many_starts_and_none_left_after(ws):
    ws.own_bus()
    ws.write("talker.py", TALKER)
    ws.write("listener.py", LISTENER)
    for name in ("talker", "listener"):
        ws.write(f"{name}.launch.yaml", "launch:\n  - executable: {cmd: " + sys.executable +
                 f" {name}.py, output: screen}}\n")
    # two launches at the same instant, with nothing running: one router, both on it
    talker = ws.start("launch", "talker.launch.yaml", output="talker.out")
    listener = ws.start("launch", "listener.launch.yaml", output="listener.out")
    ws.wait_for_output("heard hi", 60, "listener.out")
    # and six CLIs at the same instant
    procs = [subprocess.Popen(launcher_argv() + ["topic", "list"], env=ws.env, cwd=ws.root,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for _ in range(6)]
    for proc in procs:
        out, err = proc.communicate(timeout=60)
        assert proc.returncode == 0 and "/chatter" in out, err
    log = (ws.root / "run" / "domain-0.log").read_text()
    assert log.count("started by pid") == 1, log
    for proc in (talker, listener):
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130
    deadline = time.monotonic() + 20  # and it goes, a few seconds after the last one
    while answers(ws.root / "run" / "domain-0.sock"):
        assert time.monotonic() < deadline, "the router did not stop"
        time.sleep(0.1)
    assert not (ws.root / "run" / "domain-0.sock").exists()


def test_a_launch_starts_the_router_with_its_first_node_and_plain_programs_need_none(ws):
    ws.own_bus()
    ws.write("plain.launch.yaml", "launch:\n  - executable: {cmd: 'true'}\n")
    done = ws.run("launch", "plain.launch.yaml")
    assert done.returncode == 0, done.stderr
    assert not (ws.root / "run" / "domain-0.log").exists()  # no router was started
    ws.write("node.launch.yaml", """
    launch:
      - executable: {cmd: 'sleep 0.5'}
      - node: {pkg: robot_state_publisher, exec: robot_state_publisher, output: screen,
               param: [{name: robot_description, value: "<robot name='r'><link name='a'/></robot>"}]}
      - timer: {period: 3.0, children: [{shutdown: {}}]}
    """)
    done = ws.run("launch", "node.launch.yaml")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "robot 'r': 0 moving joints" in done.stdout
    log = (ws.root / "run" / "domain-0.log").read_text()
    assert log.count("started by pid") == 1, log


def test_a_stale_socket_of_a_dead_router_is_replaced(ws):
    ws.own_bus()
    run = ws.root / "run"
    run.mkdir(mode=0o700)
    with socket.socket(socket.AF_UNIX) as dead:  # bound, never listening, then gone
        dead.bind(str(run / "domain-0.sock"))
    (run / "peer-999999-deadbeef.sock").write_text("")  # a peer killed with SIGKILL
    listed = ws.run("topic", "list")
    assert listed.returncode == 0, listed.stderr
    assert not (run / "peer-999999-deadbeef.sock").exists()


@pytest.mark.parametrize("name, value, expected", [
    ("ROS_DOMAIN_ID", "233", "ROS_DOMAIN_ID='233': expected a whole number from 0 to 232"),
    ("ROS_DOMAIN_ID", "one", "ROS_DOMAIN_ID='one': expected a whole number from 0 to 232"),
    ("LAUNCHER_ROUTER", "tcp/somehost", "LAUNCHER_ROUTER: 'tcp/somehost' is not an endpoint: "
     "expected PROTOCOL/HOST:PORT"),
    ("LAUNCHER_ROUTER", "tcp/10.0.0.1:99999", "'tcp/10.0.0.1:99999' is not an endpoint"),
], ids=["domain-too-big", "domain-not-a-number", "endpoint-no-port", "endpoint-bad-port"])
def test_bad_graph_settings_are_one_clear_error(ws, name, value, expected):
    ws.own_bus().env[name] = value
    ws.write("talk.launch.yaml", "launch:\n  - executable: {cmd: sleep 30}\n")
    for args in (["topic", "list"], ["launch", "talk.launch.yaml"]):
        result = ws.run(*args)
        assert result.returncode == 2, (args, result.stderr)
        assert expected in result.stderr and "Traceback" not in result.stderr, result.stderr
    assert not (ws.root / "run" / "domain-0.sock").exists()  # nothing started


def test_a_malformed_credentials_file_names_its_line(ws):
    ws.own_bus()
    bad = ws.write("credentials", "# the bus\nlauncher secret with spaces\n")
    ws.env.update(LAUNCHER_CREDENTIALS=str(bad), LAUNCHER_ROUTER="tcp/127.0.0.1:9")
    result = ws.run("topic", "list")
    assert result.returncode == 1
    assert f"{bad}:2:1: expected one line 'user:password'" in result.stderr, result.stderr


# --- other users stay out ----------------------------------------------------------------------
def as_nobody(ws, *args: str, env: dict[str, str]) -> subprocess.CompletedProcess:
    """`launcher ARGS` run as the user nobody (root runs the tests in CI and here)."""
    return subprocess.run(["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups",
                           *launcher_argv(), *args], env={**ws.env, **env}, cwd="/",
                          capture_output=True, text=True, timeout=60)


@pytest.mark.skipif(os.geteuid() != 0, reason="needs root to act as another user")
def test_another_local_user_cannot_reach_the_graph_without_the_owners_credentials(ws):
    ws.own_bus()
    ws.write("world.launch.yaml", """
    launch:
      - executable: {cmd: "launcher sim -v 3 -r empty.xml", output: screen}
    """)
    ws.write("empty.xml", "<mujoco><worldbody><geom type='plane' size='5 5 .1'/></worldbody>"
                          "</mujoco>")
    port = free_port()
    standing = ws.start("router", "--listen", f"tcp/127.0.0.1:{port}", output="router.out")
    ws.wait_for_output(f"tcp/127.0.0.1:{port}", 30, "router.out")
    sim = ws.start("launch", "world.launch.yaml", output="sim.out")
    elsewhere = tempfile.mkdtemp(prefix="launcher-nobody-")
    try:
        ws.wait_for_output("running", 60, "sim.out")
        os.chmod(elsewhere, 0o755)
        theirs = Path(elsewhere) / "credentials"
        theirs.write_text("launcher:not-the-owners\n")
        copy = Path(elsewhere) / "owners-credentials"
        shutil.copy(Path.home() / ".launcher" / "credentials", copy)
        for path in (theirs, copy):
            os.chown(path, 65534, 65534)
            os.chmod(path, 0o600)
        home = {"HOME": elsewhere, "LAUNCHER_RUN_DIR": str(Path(elsewhere) / "run")}
        # on this host: the graph's folder is the owner's alone
        local = as_nobody(ws, "topic", "list", env={"LAUNCHER_RUN_DIR": str(ws.root / "run")})
        assert local.returncode == 1 and "cannot use the run folder" in local.stderr, \
            local.stderr
        # through the router's TCP listener: refused without the owner's credentials
        remote = {**home, "LAUNCHER_ROUTER": f"tcp/127.0.0.1:{port}",
                  "LAUNCHER_BUS_TIMEOUT": "2", "LAUNCHER_CREDENTIALS": str(theirs)}
        for args in (["topic", "list"],
                     ["topic", "pub", "/cmd_vel", "geometry_msgs/msg/Twist", "{}", "--once"],
                     ["service", "call", "--sim", "/world/default/control", "mujoco_sim/srv/Control",
                      "{pause: true}"]):
            refused = as_nobody(ws, *args, env=remote)
            assert refused.returncode == 1 and "no router answered" in refused.stderr, \
                refused.stderr
            assert "Traceback" not in refused.stderr
        # the same process with the owner's credentials is on the graph
        remote["LAUNCHER_CREDENTIALS"] = str(copy)
        listed = as_nobody(ws, "topic", "list", "--sim", env=remote)
        assert listed.returncode == 0 and "/clock" in listed.stdout, listed.stderr
        paused = as_nobody(ws, "service", "call", "--sim", "/world/default/control",
                           "mujoco_sim/srv/Control", "{pause: true}", env=remote)
        assert paused.returncode == 0, paused.stderr
        assert re.search(r"success: true", paused.stdout), paused.stdout
    finally:
        shutil.rmtree(elsewhere, ignore_errors=True)
        sim.send_signal(signal.SIGINT)
        assert sim.wait(30) == 130
        standing.send_signal(signal.SIGINT)
        assert standing.wait(30) == 0


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


@pytest.mark.parametrize("endpoint, code, expected", [
    ("tcp/1.2.3", 2, "--listen: 'tcp/1.2.3' is not an endpoint"),
    ("tcp/10.255.255.254:7447", 1, "--listen tcp/10.255.255.254:7447: cannot listen there"),
], ids=["malformed", "not-this-hosts-address"])
def test_a_standing_router_that_cannot_listen_says_why(ws, endpoint, code, expected):
    ws.own_bus()
    result = ws.run("router", "--listen", endpoint)
    assert result.returncode == code and expected in result.stderr, result.stderr
    assert "Traceback" not in result.stderr
    assert not answers(ws.root / "run" / "domain-0.sock")

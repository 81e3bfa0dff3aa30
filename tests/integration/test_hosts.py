"""Two hosts on one graph, for real: two Linux network namespaces joined by a veth pair, with
addresses that exist only inside them. Host A runs the demo's sim, bridge and
robot_state_publisher and a standing router listening on its veth address; host B runs the
demo's driver and `topic echo` through that router; a client without the credentials is
refused. The test makes the namespaces and removes them (root is needed: CI runs as root)."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import time
import uuid

import pytest

from tests.support.environment import REPO
from tests.support.processes import launcher_argv

pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason="network namespaces need root")


def ip(*args: str) -> None:
    subprocess.run(["ip", *args], check=True, capture_output=True, text=True, timeout=30)


@pytest.fixture
def hosts():
    """(namespace A, namespace B, A's address): made, then removed."""
    tag = uuid.uuid4().hex[:6]
    a, b = f"lnA{tag}", f"lnB{tag}"
    subnet = f"10.{200 + int(tag[:2], 16) % 50}.{int(tag[2:4], 16)}"
    ip("netns", "add", a)
    ip("netns", "add", b)
    try:
        ip("link", "add", f"va{tag}", "type", "veth", "peer", "name", f"vb{tag}")
        ip("link", "set", f"va{tag}", "netns", a)
        ip("link", "set", f"vb{tag}", "netns", b)
        for ns, dev, host in ((a, f"va{tag}", 1), (b, f"vb{tag}", 2)):
            ip("-n", ns, "addr", "add", f"{subnet}.{host}/24", "dev", dev)
            ip("-n", ns, "link", "set", dev, "up")
            ip("-n", ns, "link", "set", "lo", "up")
        yield a, b, f"{subnet}.1"
    finally:
        for ns in (a, b):
            subprocess.run(["ip", "netns", "del", ns], capture_output=True, timeout=30)


def in_ns(ws, ns: str, *args: str, env: dict[str, str], output: str) -> subprocess.Popen:
    out = open(ws.root / output, "w")  # noqa: SIM115 - closed with the workspace
    return subprocess.Popen(["ip", "netns", "exec", ns, *launcher_argv(), *args],
                            cwd=ws.root, env={**ws.env, **env}, stdout=out,
                            stderr=subprocess.STDOUT, text=True)


def run_in_ns(ws, ns: str, *args: str, env: dict[str, str]) -> subprocess.CompletedProcess:
    return subprocess.run(["ip", "netns", "exec", ns, *launcher_argv(), *args], cwd=ws.root,
                          env={**ws.env, **env}, capture_output=True, text=True, timeout=90)


def stop(proc: subprocess.Popen) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(30)


def test_a_driver_on_another_host_moves_the_robot_through_an_authenticated_router(ws, hosts):
    ns_a, ns_b, address = hosts
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")
    host_a = {"LAUNCHER_RUN_DIR": str(ws.root / "run-a")}
    host_b = {"LAUNCHER_RUN_DIR": str(ws.root / "run-b"),
              "LAUNCHER_ROUTER": f"tcp/{address}:7447"}
    router = in_ns(ws, ns_a, "router", "--listen", f"tcp/{address}:7447", env=host_a,
                   output="router.out")
    ws.wait_for_output(f"tcp/{address}:7447", 30, "router.out")
    sim = in_ns(ws, ns_a, "launch", str(REPO / "launch_files" / "robot.launch.yaml"),
                "drive:=false", env=host_a, output="a.out")
    driver = None
    try:
        ws.wait_for_output("spawned 'my_robot'", 90, "a.out")
        # host B: odometry crosses, and B's driver moves the robot
        echo = run_in_ns(ws, ns_b, "topic", "echo", "/odom", "--once", "--field",
                         "pose.pose.position.x", env=host_b)
        assert echo.returncode == 0, echo.stderr
        start = float(echo.stdout.split()[0])
        ws.write("drive.launch.yaml", """
        launch:
          - node: {pkg: robot_application, exec: driver, output: screen,
                   param: [{name: speed, value: 0.5}]}
        """)
        driver = in_ns(ws, ns_b, "launch", "drive.launch.yaml", env=host_b, output="b.out")
        text = ws.wait_for_output("X: ", 60, "b.out")
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            xs = [float(x) for x in re.findall(r"X: (-?[\d.]+)", ws.output("b.out"))]
            if xs and xs[-1] > start + 0.5:
                break
            time.sleep(0.2)
        else:
            raise AssertionError(f"the robot did not move from {start}:\n{text}")
        assert not (ws.root / "run-b").exists() or \
            not list((ws.root / "run-b").glob("*.sock"))  # B started no router of its own
        # a client without the credentials is refused
        ws.write("other-credentials", "launcher:not-the-right-one\n")
        os.chmod(ws.root / "other-credentials", 0o600)
        refused = run_in_ns(ws, ns_b, "topic", "list", env={
            **host_b, "LAUNCHER_CREDENTIALS": str(ws.root / "other-credentials"),
            "LAUNCHER_BUS_TIMEOUT": "2"})
        assert refused.returncode == 1 and "no router answered" in refused.stderr, \
            refused.stderr
        assert "Traceback" not in refused.stderr
    finally:
        if driver is not None:
            assert stop(driver) == 130
        assert stop(sim) == 130
        assert stop(router) == 0

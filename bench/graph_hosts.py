"""Graph benchmarks across hosts (issue 14): `launcher topic list` in a second shell while ten
robots run, and Twist one-way latency across two hosts (two network namespaces joined by a
veth pair, through the authenticated gateway router; needs root, otherwise reported as not
run).

Latency is one-way, half a round trip through an echo node at 1 kHz, as in bus.py (which
measures the same on one host).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
import uuid
from pathlib import Path

from _harness import launcher_cmd, summary, table, workdir
from bus import ECHO  # the same echo node as on one host

PY = sys.executable
REPO = Path(__file__).resolve().parent.parent

PINGER = """
import json, sys, time
from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("pinger")
sent, out = {}, []
pub = node.create_publisher("geometry_msgs/msg/Twist", "ping", QoS(depth=1000))
node.create_subscription("geometry_msgs/msg/Twist", "pong",
                         lambda m: out.append((time.perf_counter() - sent[m.linear.x]) / 2),
                         QoS(depth=1000))
while not pub.get_subscription_count():
    node.spin_once(0.05)
node.spin(0.5)
for i in range(int(sys.argv[1])):
    sent[float(i)] = time.perf_counter()
    pub.publish(build("geometry_msgs/msg/Twist", {"linear": {"x": float(i)}}))
    end = time.perf_counter() + 0.001
    while time.perf_counter() < end:
        node.spin_once(max(0.0, end - time.perf_counter()))
node.spin(1.0)
print("RESULT " + json.dumps(sorted(out)), flush=True)
node.destroy_node()
"""


def topic_list_with_ten_robots(root: Path, runs: int) -> list[float]:
    env = {**os.environ, "LAUNCHER_RUN_DIR": str(root / "run"),
           "LAUNCHER_PACKAGE_PATH": str(REPO / "packages")}
    env.pop("LAUNCHER_ROUTER", None)
    launch = subprocess.Popen(launcher_cmd() + [
        "launch", str(REPO / "launch_files" / "multi_robot.launch.yaml"), "count:=10"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 180
        while time.monotonic() < deadline:
            out = subprocess.run(launcher_cmd() + ["topic", "list"], env=env,
                                 capture_output=True, text=True).stdout
            if all(f"/robot_{i}/odom" in out for i in range(10)):
                break
            time.sleep(1.0)
        else:
            raise SystemExit("the ten robots did not all come up")
        times = []
        for _ in range(runs):
            start = time.perf_counter()
            subprocess.run(launcher_cmd() + ["topic", "list"], env=env, check=True,
                           capture_output=True)
            times.append(time.perf_counter() - start)
        return times
    finally:
        launch.send_signal(2)
        launch.wait(60)


def ip(*args: str) -> None:
    subprocess.run(["ip", *args], check=True, capture_output=True)


def across_veth(root: Path, count: int) -> list[float] | None:
    """One-way latencies between two namespaces, or None when not root."""
    if os.geteuid() != 0:
        return None
    tag = uuid.uuid4().hex[:6]
    a, b, address = f"bnA{tag}", f"bnB{tag}", "10.251.77.1"
    ip("netns", "add", a)
    ip("netns", "add", b)
    procs: list[subprocess.Popen] = []
    try:
        ip("link", "add", f"va{tag}", "type", "veth", "peer", "name", f"vb{tag}")
        ip("link", "set", f"va{tag}", "netns", a)
        ip("link", "set", f"vb{tag}", "netns", b)
        for ns, dev, host in ((a, f"va{tag}", 1), (b, f"vb{tag}", 2)):
            ip("-n", ns, "addr", "add", f"10.251.77.{host}/24", "dev", dev)
            ip("-n", ns, "link", "set", dev, "up")
            ip("-n", ns, "link", "set", "lo", "up")
        env_a = {**os.environ, "LAUNCHER_RUN_DIR": str(root / "veth-a")}
        env_a.pop("LAUNCHER_ROUTER", None)
        env_b = {**os.environ, "LAUNCHER_RUN_DIR": str(root / "veth-b"),
                 "LAUNCHER_ROUTER": f"tcp/{address}:7447"}
        router = subprocess.Popen(["ip", "netns", "exec", a, *launcher_cmd(), "router",
                                   "--listen", f"tcp/{address}:7447"], env=env_a,
                                  stdout=subprocess.PIPE, text=True)
        procs.append(router)
        assert router.stdout is not None and "listening" in router.stdout.readline()
        echo = subprocess.Popen(["ip", "netns", "exec", b, PY, "-c", ECHO], env=env_b,
                                stdout=subprocess.PIPE, text=True)
        procs.append(echo)
        assert echo.stdout is not None and echo.stdout.readline().strip() == "ready"
        pinger = subprocess.run(["ip", "netns", "exec", a, PY, "-c", PINGER, str(count)],
                                env=env_a, capture_output=True, text=True, timeout=120)
        return json.loads(pinger.stdout.split("RESULT ", 1)[1])
    finally:
        for proc in procs:
            proc.send_signal(2)
            proc.wait(30)
        for ns in (a, b):
            subprocess.run(["ip", "netns", "del", ns], capture_output=True)


def main() -> None:
    root = workdir()
    listing = topic_list_with_ten_robots(root, 10)
    veth = across_veth(root, 2000)
    rows = [("`launcher topic list`, second shell, 10 robots running, s", "<= 0.3",
             summary(listing))]
    if veth is None:
        rows.append(("Twist one-way latency across a veth pair", "report", "not run (root)"))
    else:
        rows += [("Twist one-way latency across a veth pair, p50, s", "report",
                  f"{veth[len(veth) // 2]:.6f}"),
                 ("Twist one-way latency across a veth pair, p99, s", "report",
                  f"{veth[int(len(veth) * 0.99)]:.6f}")]
    table("graph", rows)


if __name__ == "__main__":
    main()

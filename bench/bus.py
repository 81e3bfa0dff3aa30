"""Bus benchmarks (issue 4): latency, throughput, a 1 MB message, node start, topic list.

Two real processes on one router, as in a launch: a router, an echo/sink process, and this
one. Latency is one-way, measured as half of a round trip through an echo node at 1 kHz.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

from _harness import launcher_cmd, start_router, summary, table

PY = sys.executable
ECHO = """
from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("echo")
pub = node.create_publisher("geometry_msgs/msg/Twist", "pong", QoS(depth=1000))
node.create_subscription("geometry_msgs/msg/Twist", "ping", pub.publish, QoS(depth=1000))
print("ready", flush=True)
node.spin()
"""
SINK = """
import sys, time
from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("sink")
kind = sys.argv[1]
count = [0, 0.0, 0.0]
def on(m):
    count[0] += 1
    count[2] = time.perf_counter()
    if count[0] == 1:
        count[1] = count[2]
node.create_subscription(kind, "flood", on, QoS(depth=100000))
print("ready", flush=True)
while count[0] < int(sys.argv[2]):
    node.spin_once(0.5)
    if count[0] and time.perf_counter() - count[2] > 2.0:
        break  # the rest were lost: report what arrived
rate = (count[0] - 1) / max(count[2] - count[1], 1e-9)
print(f"rate {rate:.1f} received {count[0]}", flush=True)
"""
MANY = """
from launcher.bus.node import Node
node = Node("many")
pubs = [node.create_publisher("std_msgs/msg/String", f"topic_{i}") for i in range(50)]
print("ready", flush=True)
node.spin()
"""


def start(code: str, env: dict, *args: str) -> subprocess.Popen:
    proc = subprocess.Popen([PY, "-c", code, *args], env=env, stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "ready"
    return proc


def latency(env: dict, count: int) -> list[float]:
    from launcher.bus.messages import build
    from launcher.bus.node import Node
    from launcher.bus.qos import QoS

    echo = start(ECHO, env)
    node = Node("pinger", argv=[], parameter_services=False)
    sent: dict[float, float] = {}
    out: list[float] = []
    pub = node.create_publisher("geometry_msgs/msg/Twist", "ping", QoS(depth=1000))
    node.create_subscription("geometry_msgs/msg/Twist", "pong",
                             lambda m: out.append((time.perf_counter() - sent[m.linear.x]) / 2),
                             QoS(depth=1000))
    time.sleep(0.5)
    for i in range(count):
        stamp = float(i)
        sent[stamp] = time.perf_counter()
        pub.publish(build("geometry_msgs/msg/Twist", {"linear": {"x": stamp}}))
        end = time.perf_counter() + 0.001
        while time.perf_counter() < end:
            node.spin_once(max(0.0, end - time.perf_counter()))
    deadline = time.monotonic() + 2
    while len(out) < count and time.monotonic() < deadline:
        node.spin_once(0.05)
    node.destroy_node()
    echo.terminate()
    echo.wait()
    return out


def throughput(env: dict, kind: str, values: dict, count: int) -> float:
    from launcher.bus.messages import build
    from launcher.bus.node import Node
    from launcher.bus.qos import QoS

    sink = start(SINK, env, kind, str(count))
    node = Node("flooder", argv=[], parameter_services=False)
    pub = node.create_publisher(kind, "flood", QoS(depth=100000))
    time.sleep(0.5)
    message = build(kind, values)
    for _ in range(count):
        pub.publish(message)
    line = sink.stdout.readline()
    node.destroy_node()
    sink.terminate()
    sink.wait()
    return float(line.split()[1])


def node_start(env: dict) -> float:
    """From the process's start to its first publish done (its exit is not start-up)."""
    code = ("import time; from launcher.bus.node import Node; "
            "n=Node('s'); p=n.create_publisher('geometry_msgs/msg/Twist','x'); "
            "p.publish(n.message('geometry_msgs/msg/Twist')); print(time.time(), flush=True)")
    began = time.time()
    done = subprocess.run([PY, "-c", code], env=env, check=True, capture_output=True,
                          text=True)
    return float(done.stdout.split()[0]) - began


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=5)
    runs = parser.parse_args().runs
    import compileall

    import launcher  # bytecode written once, as an install does (node start reads it)

    compileall.compile_dir(os.path.dirname(launcher.__file__), quiet=1)
    env, router = start_router()
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    try:
        lat = sorted(latency(env, 2000))
        p50, p99 = lat[len(lat) // 2], lat[int(len(lat) * 0.99)]
        twist = [throughput(env, "geometry_msgs/msg/Twist", {}, 50000) for _ in range(3)]
        image = {"height": 512, "width": 512, "encoding": "rgb8", "step": 1536,
                 "data": list(bytes(512 * 512 * 3 + 213424))[:1000000]}
        big = [throughput(env, "sensor_msgs/msg/Image", image, 300) for _ in range(2)]
        starts = [node_start(env) for _ in range(runs)]
        many = start(MANY, env)
        listing = []
        for _ in range(runs):
            t0 = time.perf_counter()
            out = subprocess.run(launcher_cmd() + ["topic", "list"], env=env, check=True,
                                 capture_output=True, text=True).stdout
            listing.append(time.perf_counter() - t0)
            assert out.count("/topic_") == 50, out
        many.terminate()
        many.wait()
    finally:
        router.terminate()
        router.wait()
    table("bus (seconds; rates in messages/s)", [
        ("Twist one-way latency at 1 kHz, p50", "<= 0.0002", f"{p50:.6f}"),
        ("Twist one-way latency at 1 kHz, p99", "report", f"{p99:.6f}"),
        ("Twist throughput, 1 pub -> 1 sub", ">= 50000", summary(twist)),
        ("1 MB Image throughput", "report", summary(big)),
        ("node start (import+session+publish)", "<= 0.08", summary(starts)),
        ("launcher topic list, 50 topics", "<= 0.3", summary(listing)),
    ])


if __name__ == "__main__":
    main()

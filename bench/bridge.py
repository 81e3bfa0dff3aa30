"""Bridge benchmarks (issue 6): latency the bridge adds at 1 kHz, and Twist throughput.

This process plays the sim (publishing sim-native messages) and the ROS side (receiving the
bridged ones). The bridge path is sim → bridge → ROS: two hops and a conversion. The bus
alone is one hop, measured as half the round trip through a relay node that republishes
the bytes untouched. Added latency = bridge path − one hop.
"""

from __future__ import annotations

import struct
import subprocess
import sys
import time

from _harness import start_router, summary, table

PY = sys.executable
RELAY = """
from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("relay")
out = node.create_publisher("geometry_msgs/msg/Twist", "/relay_out", QoS(depth=1000))
node.create_subscription("geometry_msgs/msg/Twist", "/relay_in", out.publish_raw,
                         QoS(depth=1000), raw=True, inline=True)
print("ready", flush=True)
node.spin()
"""
FIRST = struct.Struct("<4xd")  # the first float64 of a message: Twist.linear.x


def start(args: list[str], env: dict, ready: str) -> subprocess.Popen:
    proc = subprocess.Popen([PY, *args], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    for line in proc.stdout:
        if ready in line:
            return proc
    raise RuntimeError(f"{args} did not start")


def one_way(node, pub_type: str, source: str, sink_type: str, sink: str, count: int,
            payload_of, key_of=lambda payload: FIRST.unpack_from(payload)[0]) -> list[float]:
    """Latencies (s) of `count` messages sent at 1 kHz from `source` and received on `sink`;
    `payload_of(i)` makes message i, `key_of(payload)` finds i in what arrives."""
    from launcher.bus import keys
    from launcher.bus.qos import QoS

    side = keys.SIM if pub_type.startswith("mujoco_sim/") else keys.ROS  # the sim's own side
    sent: dict[float, float] = {}
    out: list[float] = []

    def on(payload: bytes) -> None:
        now = time.perf_counter()
        out.append(now - sent[key_of(payload)])

    subscription = node.create_subscription(sink_type, sink, on, QoS(depth=1000), raw=True,
                                            inline=True)
    publisher = node.create_publisher(pub_type, source, QoS(depth=1000), space=side)
    time.sleep(0.5)
    start_time = time.perf_counter()
    for i in range(count):
        stamp = float(i)
        payload = payload_of(stamp)
        sent[stamp] = time.perf_counter()
        publisher.publish_raw(payload)
        wait = start_time + (i + 1) / 1000 - time.perf_counter()
        if wait > 0:
            time.sleep(wait)
    time.sleep(0.5)
    subscription.destroy()
    publisher.destroy()
    return sorted(out)


def throughput(node, count: int) -> float:
    from launcher.bus import keys
    from launcher.bus.messages import build
    from launcher.bus.qos import QoS
    from launcher.bus.types import registry

    received = [0, 0.0, 0.0]

    def on(payload: bytes) -> None:
        received[0] += 1
        received[2] = time.perf_counter()
        if received[0] == 1:
            received[1] = received[2]

    subscription = node.create_subscription("geometry_msgs/msg/Twist", "/flood", on,
                                            QoS(depth=100000), raw=True, inline=True)
    publisher = node.create_publisher("mujoco_sim/msg/Twist", "/flood", QoS(depth=100000),
                                      space=keys.SIM)  # the sim's side
    time.sleep(0.5)
    payload = registry().serialize(build("mujoco_sim/msg/Twist", {}), "mujoco_sim/msg/Twist")
    for _ in range(count):
        publisher.publish_raw(payload)
    deadline = time.monotonic() + 10
    while received[0] < count and time.monotonic() < deadline:
        time.sleep(0.05)
    subscription.destroy()
    publisher.destroy()
    return (received[0] - 1) / max(received[2] - received[1], 1e-9)


def main() -> None:
    env, router = start_router()
    procs = []
    try:
        procs.append(start(["-c", RELAY], env, "ready"))
        procs.append(start(["-m", "launcher.nodes.parameter_bridge",
                            "/twist@geometry_msgs/msg/Twist[gz.msgs.Twist",
                            "/odom@nav_msgs/msg/Odometry[gz.msgs.Odometry",
                            "/flood@geometry_msgs/msg/Twist[gz.msgs.Twist"], env,
                           "bridging 3 of 3"))
        from launcher.bus.messages import build
        from launcher.bus.node import Node
        from launcher.bus.types import registry

        node = Node("bench_bridge", argv=[], parameter_services=False)
        types = registry()

        def twist(kind):
            return lambda x: types.serialize(build(kind, {"linear": {"x": x}}), kind)

        def odometry(x):  # the send time's key rides in pose.position.x
            message = build("mujoco_sim/msg/Odometry", {"pose": {"position": {"x": x}}})
            return types.serialize(message, "mujoco_sim/msg/Odometry")

        relay = one_way(node, "geometry_msgs/msg/Twist", "/relay_in", "geometry_msgs/msg/Twist",
                        "/relay_out", 2000, twist("geometry_msgs/msg/Twist"))
        bridged = one_way(node, "mujoco_sim/msg/Twist", "/twist", "geometry_msgs/msg/Twist",
                          "/twist", 2000, twist("mujoco_sim/msg/Twist"))
        rates = [throughput(node, 50000) for _ in range(3)]
        odom = one_way(node, "mujoco_sim/msg/Odometry", "/odom", "nav_msgs/msg/Odometry",
                       "/odom", 1000, odometry, lambda payload: types.deserialize(
                           payload, "nav_msgs/msg/Odometry").pose.pose.position.x)
        node.destroy_node()
    finally:
        for proc in procs:
            proc.terminate()
            proc.wait(10)
        router.terminate()
        router.wait()
    hop = relay[len(relay) // 2] / 2
    p50 = bridged[len(bridged) // 2]
    table("bridge (seconds; rates in messages/s)", [
        ("bus, one hop (half a relay round trip), p50", "report", f"{hop:.6f}"),
        ("sim -> bridge -> ROS, Twist at 1 kHz, p50", "report", f"{p50:.6f}"),
        ("latency added by the bridge, Twist, p50", "<= 0.0002", f"{p50 - hop:.6f}"),
        ("latency added by the bridge, Odometry, p50", "report",
         f"{odom[len(odom) // 2] - hop:.6f}"),
        ("Twist throughput through the bridge", ">= 20000", summary(rates)),
    ])


if __name__ == "__main__":
    main()

"""robot_state_publisher benchmark (issue 6): a 20-joint chain, joint_states at 1 kHz.

A real robot_state_publisher process with publish_frequency 1000; this process publishes
joint_states at 1 kHz (stamps 1 ms apart) for the run and counts the /tf messages that come
back; the node's CPU is read from the kernel.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

import psutil
from _harness import start_router, table

PY = sys.executable
JOINTS = 20


def chain(joints: int) -> str:
    links = "".join(f'<link name="l{i}"/>' for i in range(joints + 1))
    body = "".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        f'<origin xyz="0 0 0.1" rpy="0 0.1 0"/><axis xyz="0 {i % 2} {1 - i % 2}"/>'
        f'<limit lower="-3" upper="3" effort="1" velocity="1"/></joint>' for i in range(joints))
    return f'<robot name="chain">{links}{body}</robot>'


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=10.0)
    args = parser.parse_args()
    env, router = start_router()
    rsp = subprocess.Popen([PY, "-m", "launcher.nodes.robot_state_publisher", "--ros-args",
                            "-p", "publish_frequency:=1000.0", "-p",
                            f"robot_description:={chain(JOINTS)}"], env=env,
                           stdout=subprocess.DEVNULL)
    from launcher.bus.node import Node
    from launcher.bus.qos import QoS

    node = Node("bench_joint_states", argv=[])
    try:
        received = [0]
        # counted as they arrive (on Zenoh's thread): this loop does not spin while it sends,
        # and the executor's queue would keep only the last `depth`
        node.create_subscription("tf2_msgs/msg/TFMessage", "/tf",
                                 lambda payload: received.__setitem__(0, received[0] + 1),
                                 QoS(depth=1000), raw=True, inline=True)
        publisher = node.create_publisher("sensor_msgs/msg/JointState", "joint_states",
                                          QoS(depth=1000))
        message = node.message("sensor_msgs/msg/JointState",
                               name=[f"j{i}" for i in range(JOINTS)],
                               position=[0.0] * JOINTS)
        from launcher.bus.types import registry

        types = registry()
        deadline = time.monotonic() + 20
        while received[0] == 0 and time.monotonic() < deadline:  # the node is up
            publisher.publish(message)
            node.spin(0.1)
        process = psutil.Process(rsp.pid)
        total = int(args.seconds * 1000)
        received[0] = 0
        cpu0 = sum(process.cpu_times()[:2])
        start = time.monotonic()
        for i in range(total):
            message.header.stamp.sec, message.header.stamp.nanosec = 100 + i // 1000, \
                (i % 1000) * 1_000_000
            message.position[:] = [0.001 * i] * JOINTS
            publisher.publish_raw(types.serialize(message, "sensor_msgs/msg/JointState"))
            wait = start + (i + 1) / 1000 - time.monotonic()
            if wait > 0:
                time.sleep(wait)
        elapsed = time.monotonic() - start
        node.spin(0.5)
        cpu = (sum(process.cpu_times()[:2]) - cpu0) / elapsed * 100
        if os.environ.get("BENCH_THREADS"):
            for thread in process.threads():
                print(thread.id, thread.user_time + thread.system_time)
    finally:
        node.destroy_node()
        rsp.terminate()
        rsp.wait(10)
        router.terminate()
        router.wait()
    table("robot_state_publisher (20-joint chain, joint_states at 1 kHz)", [
        ("joint_states sent per second", "1000", f"{total / elapsed:.1f}"),
        ("/tf out / joint_states in", "1.00", f"{received[0] / total:.3f}"),
        ("robot_state_publisher CPU % of one core", "<= 25", f"{cpu:.1f}"),
    ])


if __name__ == "__main__":
    main()

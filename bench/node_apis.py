#!/usr/bin/env python3
"""ROS node code on launcher (issue 16): node start and Twist latency/throughput with the
rclpy API, the rospy API and launcher's own node API, measured in the same run on the same
router. Real rclpy and rospy are not installed here: their figures are the ones measured on
this machine (REFERENCE.md §9: rclpy Kilted wheels with FastDDS, Debian's ROS 1 rospy), shown
beside ours.

  start      a new process: import, init, a node, a publisher, the first publish
  latency    one-way, Twist at 1 kHz for 3 s (the send time travels in the message), p50;
             the median of 3 rounds, the APIs taken in turn
  throughput Twist sent as fast as one process can for 3 s, received per second (idem)
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time

from _harness import start_router, table

from launcher.compat import SITE

REAL = {"rclpy": {"start": 0.26, "p50": 0.195, "rate": 3400.0},
        "rospy": {"start": 0.24, "p50": 0.062, "rate": 15400.0}}
RUNS = 7
ROUNDS = 3  # of each exchange, per API

START = {
    "launcher": """
import time, sys
from launcher.bus.node import Node
node = Node('starter')
pub = node.create_publisher('geometry_msgs/msg/Twist', 'start_topic')
pub.publish(node.message('geometry_msgs/msg/Twist'))
print(time.time(), flush=True)
node.destroy_node()
""",
    "rclpy": """
import time
import rclpy
from geometry_msgs.msg import Twist
rclpy.init()
node = rclpy.create_node('starter')
pub = node.create_publisher(Twist, 'start_topic', 10)
pub.publish(Twist())
print(time.time(), flush=True)
node.destroy_node()
rclpy.shutdown()
""",
    "rospy": """
import time
import rospy
from geometry_msgs.msg import Twist
rospy.init_node('starter', disable_signals=True)
pub = rospy.Publisher('start_topic', Twist, queue_size=10)
pub.publish(Twist())
print(time.time(), flush=True)
rospy.signal_shutdown('done')
""",
}

# argv: mode (latency|flood), seconds. Prints one line when done. Each API makes `pub` and
# `message`; the loop is the same for all.
SEND_LOOP = """
time.sleep(1.0)
end = time.monotonic() + seconds
period, next_at, sent = 0.001, time.monotonic(), 0
while time.monotonic() < end:
    message.linear.x = time.time()
    pub.publish(message)
    sent += 1
    if mode == 'latency':
        next_at += period
        delay = next_at - time.monotonic()
        if delay > 0:
            time.sleep(delay)
print('sent', sent, flush=True)
time.sleep(0.5)
"""
SEND_SETUP = {
    "launcher": ("""
from launcher.bus.node import Node
node = Node('sender')
pub = node.create_publisher('geometry_msgs/msg/Twist', 'bench_twist')
message = node.message('geometry_msgs/msg/Twist')
""", "node.destroy_node()"),
    "rclpy": ("""
import rclpy
from geometry_msgs.msg import Twist
rclpy.init()
node = rclpy.create_node('sender')
pub = node.create_publisher(Twist, 'bench_twist', 10)
message = Twist()
""", "node.destroy_node()\nrclpy.shutdown()"),
    "rospy": ("""
import rospy
from geometry_msgs.msg import Twist
rospy.init_node('sender', disable_signals=True)
pub = rospy.Publisher('bench_twist', Twist, queue_size=10)
message = Twist()
""", "rospy.signal_shutdown('done')"),
}
PUBLISH = {api: "import sys, time\nmode, seconds = sys.argv[1], float(sys.argv[2])\n" + setup +
           SEND_LOOP + end for api, (setup, end) in SEND_SETUP.items()}

# Receives for `seconds` after the first message; prints the p50 latency (ms) and the rate.
RECEIVE = {
    "launcher": """
import sys, time, statistics
from launcher.bus.node import Node
seconds = float(sys.argv[1])
node = Node('receiver')
delays, first = [], []
def got(message):
    now = time.time()
    first or first.append(time.monotonic())
    delays.append((now - message.linear.x) * 1000)
node.create_subscription('geometry_msgs/msg/Twist', 'bench_twist', got)
print('ready', flush=True)
while not first:
    node.spin_once(0.1)
node.spin(seconds)
span = time.monotonic() - first[0]
print('result', statistics.median(delays), len(delays) / span, flush=True)
node.destroy_node()
""",
    "rclpy": """
import sys, time, statistics
import rclpy
from geometry_msgs.msg import Twist
seconds = float(sys.argv[1])
rclpy.init()
node = rclpy.create_node('receiver')
delays, first = [], []
def got(message):
    now = time.time()
    first or first.append(time.monotonic())
    delays.append((now - message.linear.x) * 1000)
node.create_subscription(Twist, 'bench_twist', got, 10)
print('ready', flush=True)
while not first:
    rclpy.spin_once(node, timeout_sec=0.1)
end = first[0] + seconds
while time.monotonic() < end:
    rclpy.spin_once(node, timeout_sec=0.1)
span = time.monotonic() - first[0]
print('result', statistics.median(delays), len(delays) / span, flush=True)
node.destroy_node()
rclpy.shutdown()
""",
    "rospy": """
import sys, time, statistics
import rospy
from geometry_msgs.msg import Twist
seconds = float(sys.argv[1])
delays, first = [], []
def got(message):
    now = time.time()
    first or first.append(time.monotonic())
    delays.append((now - message.linear.x) * 1000)
rospy.init_node('receiver', disable_signals=True)
rospy.Subscriber('bench_twist', Twist, got, queue_size=10)
print('ready', flush=True)
while not first:
    time.sleep(0.01)
time.sleep(seconds)
span = time.monotonic() - first[0]
print('result', statistics.median(delays), len(delays) / span, flush=True)
rospy.signal_shutdown('done')
""",
}


def python(code: str, *args: str, env: dict[str, str]) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-c", code, *args], env=env, text=True,
                            stdout=subprocess.PIPE)


def start_time(api: str, env: dict[str, str]) -> float:
    began = time.time()
    proc = python(START[api], env=env)
    out, _ = proc.communicate(timeout=60)
    return float(out.split()[0]) - began


def exchange(api: str, mode: str, env: dict[str, str], seconds: float = 3.0
             ) -> tuple[float, float]:
    receiver = python(RECEIVE[api], str(seconds), env=env)
    assert receiver.stdout is not None
    assert receiver.stdout.readline().strip() == "ready"
    sender = python(PUBLISH[api], mode, str(seconds + 1.0), env=env)
    out, _ = receiver.communicate(timeout=60)
    sender.communicate(timeout=60)
    words = out.split()
    return float(words[-2]), float(words[-1])


def main() -> None:
    import compileall

    # bytecode written once, as an install does (a checkout's first runs compile every module)
    import launcher

    compileall.compile_dir(os.path.dirname(launcher.__file__), quiet=1)
    env, router = start_router()
    env = {**env, "PYTHONPATH": SITE}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    try:
        for api in START:  # warm the caches (type definitions, bytecode) once
            start_time(api, env)
        starts = {api: statistics.median(start_time(api, env) for _ in range(RUNS))
                  for api in START}
        # rounds taken in turn and the median kept: the machine's load drifts within a run
        latency = {api: [] for api in START}
        rate = {api: [] for api in START}
        for _ in range(ROUNDS):
            for api in START:
                latency[api].append(exchange(api, "latency", env)[0])
                rate[api].append(exchange(api, "flood", env)[1])
        latency = {api: statistics.median(values) for api, values in latency.items()}
        rate = {api: statistics.median(values) for api, values in rate.items()}
    finally:
        router.terminate()
        router.wait()
    own = "launcher"
    rows = []
    for api in ("rclpy", "rospy"):
        rows += [
            (f"{api} API node start (median of {RUNS})", "<= 0.15 s" if api == "rclpy" else
             f"< real {REAL[api]['start']:.2f} s",
             f"{starts[api]:.3f} s  (launcher API {starts[own]:.3f} s; real {api} "
             f"{REAL[api]['start']:.2f} s)"),
            (f"{api} API Twist p50 at 1 kHz", f"< real {REAL[api]['p50']:.3f} ms",
             f"{latency[api]:.3f} ms  ({latency[api] / latency[own]:.2f}x launcher API "
             f"{latency[own]:.3f} ms)"),
            (f"{api} API Twist throughput", f"> real {REAL[api]['rate'] / 1000:.1f} k/s",
             f"{rate[api] / 1000:.1f} k msg/s  (launcher API {rate[own] / 1000:.1f} k; "
             f"{rate[own] / rate[api]:.2f}x slower)"),
        ]
    table("ROS node APIs on launcher's bus (targets: beat real rclpy; within 1.2x of "
          "launcher's API)", rows)


if __name__ == "__main__":
    os.chdir(os.path.dirname(os.path.abspath(__file__)))
    main()

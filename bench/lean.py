#!/usr/bin/env python3
"""Lean processes (issue 17): the first message of a topic against the hundredth, and what a
node imports.

  first message  a receiver subscribed to five topics of five types it has not used yet; a
                 sender publishes each type's first message once the topic matches, then 99
                 more 10 ms apart: the delay of the first against the median of the rest
                 (each message carries its send time)
  heavy modules  numpy, MuJoCo and rosbags in a node that publishes and subscribes (rclpy API),
                 a robot_state_publisher set up beside it, and the bridge's and create's
                 modules
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys

from _harness import start_router, table

from launcher.compat import SITE

TYPES = {  # topic -> (type, the field that carries the send time)
    "lean_odom": ("nav_msgs/msg/Odometry", "pose.pose.position.x"),
    "lean_imu": ("sensor_msgs/msg/Imu", "linear_acceleration.x"),
    "lean_fix": ("sensor_msgs/msg/NavSatFix", "latitude"),
    "lean_pose": ("geometry_msgs/msg/PoseStamped", "pose.position.x"),
    "lean_wrench": ("geometry_msgs/msg/WrenchStamped", "wrench.force.x"),
}
COUNT = 100

RECEIVE = """
import json, sys, time
from launcher.bus.node import Node
types = json.loads(sys.argv[1])
node = Node('lean_receiver')
delays = {topic: [] for topic in types}
def field(message, path):
    for part in path.split('.'):
        message = getattr(message, part)
    return message
def heard(topic, path):
    return lambda message: delays[topic].append(time.time() - field(message, path))
for topic, (type_name, path) in types.items():
    node.create_subscription(type_name, topic, heard(topic, path), 200)
print('ready', flush=True)
end = time.monotonic() + 60
while time.monotonic() < end and any(len(d) < COUNT for d in delays.values()):
    node.spin_once(0.1)
print(json.dumps(delays), flush=True)
node.destroy_node()
""".replace("COUNT", str(COUNT))

SEND = """
import json, sys, time
from launcher.bus.node import Node
types = json.loads(sys.argv[1])
node = Node('lean_sender')
publishers = {t: node.create_publisher(n, t, 200) for t, (n, _) in types.items()}
messages = {t: node.message(n) for t, (n, _) in types.items()}
end = time.monotonic() + 20
while time.monotonic() < end and not all(p.get_subscription_count() for p in publishers.values()):
    time.sleep(0.01)
time.sleep(0.5)  # both up and matched
def put(message, path, value):
    parts = path.split('.')
    for part in parts[:-1]:
        message = getattr(message, part)
    setattr(message, parts[-1], value)
for i in range(COUNT):
    for topic, (_, path) in types.items():
        put(messages[topic], path, time.time())
        publishers[topic].publish(messages[topic])
    time.sleep(0.01)
time.sleep(0.5)
node.destroy_node()
""".replace("COUNT", str(COUNT))

HEAVY = """
import sys, time
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('lean')
heard = []
node.create_subscription(String, 'lean_check', heard.append, 10)
pub = node.create_publisher(String, 'lean_check', 10)
end = time.monotonic() + 20
while not heard and time.monotonic() < end:
    pub.publish(String(data='x'))
    rclpy.spin_once(node, timeout_sec=0.05)
import launcher.nodes.parameter_bridge, launcher.nodes.create
from launcher.bus.node import Node
from launcher.nodes.robot_state_publisher import RobotStatePublisher
urdf = ('<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute">'
        '<parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint></robot>')
rsp = Node('rsp', argv=['--ros-args', '-p', 'robot_description:=' + urdf])
RobotStatePublisher(rsp)  # running: its subscriptions and first publications made
rsp.destroy_node()
print(sorted({m.split('.')[0] for m in sys.modules} & {'numpy', 'mujoco', 'rosbags'}))
"""


def main() -> None:
    env, router = start_router()
    try:
        spec = json.dumps(TYPES)
        receiver = subprocess.Popen([sys.executable, "-c", RECEIVE, spec], env=env, text=True,
                                    stdout=subprocess.PIPE)
        assert receiver.stdout is not None
        assert receiver.stdout.readline().strip() == "ready"
        sender = subprocess.Popen([sys.executable, "-c", SEND, spec], env=env)
        out, _ = receiver.communicate(timeout=120)
        sender.wait(60)
        delays = json.loads(out.splitlines()[-1])
        heavy = subprocess.run([sys.executable, "-c", HEAVY], env={**env, "PYTHONPATH": SITE},
                               capture_output=True, text=True, timeout=60)
    finally:
        router.terminate()
        router.wait()
    firsts = [values[0] * 1000 for values in delays.values() if values]
    rests = [statistics.median(values[1:]) * 1000 for values in delays.values()
             if len(values) > 1]
    table("lean processes (ms)", [
        ("first message of a new topic+type, worst of 5", "<= 5 ms",
         f"{max(firsts):.2f}  (each: {', '.join(f'{f:.2f}' for f in firsts)})"),
        ("the messages after it, median", "report", f"{statistics.median(rests):.2f}"),
        ("heavy modules in an rclpy node and the built-in nodes", "none",
         (heavy.stdout.strip().splitlines() or [heavy.stderr.strip()[-200:]])[-1]),
    ])


if __name__ == "__main__":
    os.chdir(os.path.dirname(os.path.abspath(__file__)))
    main()

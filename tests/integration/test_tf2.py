"""tf2 on the bus: a broadcaster's /tf and a static broadcaster's latched /tf_static reach a
TransformListener's Buffer in another process, a listener that starts late included."""

from __future__ import annotations

import signal

from tests.support.nodes import node_package

BROADCASTER = """
import math
import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from tf2_ros import StaticTransformBroadcaster, TransformBroadcaster

rclpy.init()
node = Node("broadcaster")
static = StaticTransformBroadcaster(node)
moving = TransformBroadcaster(node)


def transform(parent, child, x, yaw=0.0):
    t = TransformStamped()
    t.header.stamp = node.get_clock().now().to_msg()
    t.header.frame_id, t.child_frame_id = parent, child
    t.transform.translation.x = x
    t.transform.rotation.z, t.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return t


static.sendTransform(transform("map", "odom", 1.0))
static.sendTransform(transform("base_link", "laser", 0.25))  # both kept, as tf2_ros does
node.create_timer(0.05, lambda: moving.sendTransform(transform("odom", "base_link", 2.0,
                                                               math.pi / 2)))
print("broadcasting", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""

LISTENER = """
import sys
import rclpy
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time
from tf2_ros import Buffer, LookupException, TransformListener

rclpy.init()
node = Node("listener")
buffer = Buffer()
listener = TransformListener(buffer, node, spin_thread=True)
t = buffer.lookup_transform("map", "laser", Time(), timeout=Duration(seconds=20))
v = t.transform.translation
print(f"map->laser {v.x:.3f} {v.y:.3f} {v.z:.3f} {t.header.frame_id} {t.child_frame_id}")
try:
    buffer.lookup_transform("map", "gripper", Time())
except LookupException as exc:
    print("lookup:", exc)
rclpy.shutdown()
"""


def test_transforms_broadcast_in_one_process_are_looked_up_in_another(ws):
    ws.own_bus()
    node_package(ws, "tf_nodes", {"broadcaster.py": BROADCASTER, "listener.py": LISTENER})
    broadcaster = ws.start("run", "tf_nodes", "broadcaster.py", output="broadcaster.txt")
    try:
        ws.wait_for_output("broadcasting", 30, "broadcaster.txt")
        done = ws.run("run", "tf_nodes", "listener.py", timeout=60)
        assert done.returncode == 0, done.stderr
        assert "map->laser 3.000 0.250 0.000 map laser" in done.stdout, done.stdout
        assert 'lookup: "gripper" passed to lookupTransform argument source_frame does not ' \
               "exist. Known frames: base_link, laser, map, odom" in done.stdout, done.stdout
    finally:
        broadcaster.send_signal(signal.SIGINT)
        assert broadcaster.wait(20) == 0, ws.output("broadcaster.txt")


def test_static_transform_publisher_and_tf2_echo_as_ros_2_has_them(ws):
    ws.own_bus()
    new = ws.start("run", "tf2_ros", "static_transform_publisher", "--x", "1", "--y", "2",
                   "--yaw", "1.5707963", "--frame-id", "map", "--child-frame-id", "odom",
                   output="new.txt")
    old = ws.start("run", "tf2_ros", "static_transform_publisher", "0.5", "0", "0", "0", "0",
                   "0", "odom", "base_link", output="old.txt")
    try:
        said = ws.wait_for_output("from 'map' to 'odom'", 30, "new.txt")
        assert "Spinning until stopped - publishing transform\ntranslation: ('1.000000', " \
               "'2.000000', '0.000000')\nrotation: ('0.000000', '0.000000', '0.707107', " \
               "'0.707107')" in said, said
        assert "Old-style arguments are deprecated" in ws.wait_for_output(
            "from 'odom' to 'base_link'", 30, "old.txt")
        echo = ws.start("run", "tf2_ros", "tf2_echo", "map", "base_link", "5",
                        output="echo.txt")
        try:
            shown = ws.wait_for_output("- Matrix:", 30, "echo.txt")
            # base_link is 0.5 m ahead of odom, which is turned 90° at (1, 2): (1, 2.5)
            assert "- Translation: [1.000, 2.500, 0.000]" in shown, shown
            assert "- Rotation: in Quaternion (xyzw) [0.000, 0.000, 0.707, 0.707]" in shown
            assert "- Rotation: in RPY (degree) [0.000, 0.000, 90.000]" in shown, shown
        finally:
            echo.send_signal(signal.SIGINT)
            assert echo.wait(20) in (0, 130)
        bad = ws.run("run", "tf2_ros", "static_transform_publisher", "--x", "one",
                     "--frame-id", "a", "--child-frame-id", "b")
        assert bad.returncode != 0 and "Traceback" not in bad.stderr
        assert "usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX]" \
            in bad.stderr, bad.stderr
        few = ws.run("run", "tf2_ros", "static_transform_publisher", "1", "2", "map")
        assert "expected 8 or 9 positional arguments" in few.stderr, few.stderr
    finally:
        for proc in (new, old):
            proc.send_signal(signal.SIGINT)
            assert proc.wait(20) in (0, 130)


def test_tf2_monitor_reports_each_frames_rate_and_delay(ws):
    ws.own_bus()
    node_package(ws, "tf_nodes", {"broadcaster.py": BROADCASTER})
    broadcaster = ws.start("run", "tf_nodes", "broadcaster.py", output="broadcaster.txt")
    monitor = ws.start("run", "tf2_ros", "tf2_monitor", "map", "base_link",
                       output="monitor.txt")
    try:
        ws.wait_for_output("broadcasting", 30, "broadcaster.txt")
        said = ws.wait_for_output("Frame: base_link", 30, "monitor.txt")
        assert "RESULTS: for map to base_link" in said, said
        import re
        import time

        time.sleep(2.5)
        rates = re.findall(r"Frame: base_link, .*Rate: ([\d.]+) Hz", ws.output("monitor.txt"))
        assert rates and 10.0 < float(rates[-1]) < 30.0, rates  # a transform every 0.05 s
        assert "Chain is: map -> base_link" in ws.output("monitor.txt")
    finally:
        for proc in (monitor, broadcaster):
            proc.send_signal(signal.SIGINT)
            proc.wait(20)


def test_view_frames_writes_the_tree_as_graphviz_and_pdf(ws):
    """(graphviz's dot comes with the test set-up, as Debian's package, as users install it)"""
    import os
    import subprocess

    from tests.support.processes import launcher_argv

    ws.own_bus()
    node_package(ws, "tf_nodes", {"broadcaster.py": BROADCASTER})
    broadcaster = ws.start("run", "tf_nodes", "broadcaster.py", output="broadcaster.txt")
    try:
        ws.wait_for_output("broadcasting", 30, "broadcaster.txt")
        done = ws.run("run", "tf2_tools", "view_frames", "--wait-time", "1.5", timeout=60)
        assert done.returncode == 0, done.stderr
        said = done.stdout + done.stderr
        assert "Listening to tf data for 1.5 seconds..." in said, said
        gv = sorted(ws.root.glob("frames_*.gv"))
        pdf = sorted(ws.root.glob("frames_*.pdf"))
        assert len(gv) == 1 and len(pdf) == 1, said
        text = gv[0].read_text()
        assert '"map" -> "odom"' in text and '"odom" -> "base_link"' in text, text
        assert '"base_link" -> "laser"' in text and '}->"map";' in text, text
        assert pdf[0].read_bytes().startswith(b"%PDF")
        assert f"Generating graph in {pdf[0].name} file..." in said
        # no dot on PATH: the .gv, and how to get the PDF
        env = dict(ws.env, PATH=os.pathsep.join(
            p for p in ws.env["PATH"].split(os.pathsep) if not os.path.exists(f"{p}/dot")))
        (ws.root / "nodot").mkdir()
        bare = subprocess.run([*launcher_argv(), "run", "tf2_tools", "view_frames", "-t", "0.5"],
                              cwd=ws.root / "nodot", env=env, capture_output=True, text=True,
                              timeout=60)
        assert bare.returncode == 1 and "apt-get install graphviz" in bare.stderr, bare.stderr
        assert len(list((ws.root / "nodot").glob("frames_*.gv"))) == 1
    finally:
        broadcaster.send_signal(signal.SIGINT)
        broadcaster.wait(20)


SYNCED = """
import rclpy
import message_filters
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image

rclpy.init()
node = Node("synced")
pairs = []
images = message_filters.Subscriber(node, Image, "image")
infos = message_filters.Subscriber(node, CameraInfo, "camera_info")
sync = message_filters.ApproximateTimeSynchronizer([images, infos], 10, 0.02)
sync.registerCallback(lambda i, c: pairs.append((i.header.frame_id, c.header.frame_id)))
image_pub = node.create_publisher(Image, "image", 10)
info_pub = node.create_publisher(CameraInfo, "camera_info", 10)


def send():
    stamp = node.get_clock().now().to_msg()
    image, info = Image(), CameraInfo()
    image.header.stamp = info.header.stamp = stamp
    image.header.frame_id, info.header.frame_id = "cam", "cam_info"
    image_pub.publish(image)
    info_pub.publish(info)


node.create_timer(0.05, send)
while len(pairs) < 3:
    rclpy.spin_once(node, timeout_sec=1.0)
print("pairs", pairs[:3], images.getTopic())
"""


def test_message_filters_subscribers_on_the_bus_are_synchronised(ws):
    ws.own_bus()
    node_package(ws, "synced", {"synced.py": SYNCED})
    done = ws.run("run", "synced", "synced.py", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "pairs [('cam', 'cam_info'), ('cam', 'cam_info'), ('cam', 'cam_info')] /image" \
        in done.stdout, done.stdout

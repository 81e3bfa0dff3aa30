"""The ROS libraries users' nodes import (issue 32), measured on the real bus.

Action round trip: an rclpy ActionServer with a trivial execute callback in a process of its
own, and an ActionClient here: send_goal → accepted → result, one goal after another; each
round trip timed, p50 and p99 reported.

tf2: `Buffer.lookup_transform` through a chain of ten frames (each 0.1 m and 0.1 rad from its
parent, dynamic), at the latest common time, as fast as it goes for two seconds: worked out
each time (as after a new transform), then repeated with nothing new (the buffer's cache).

Data: `point_cloud2.read_points_numpy` of a 57,600-point xyz+intensity cloud (a 32 × 1800
lidar's), and `CvBridge.imgmsg_to_cv2` of a 640 × 480 rgb8 image; the median of 200 calls.
"""

from __future__ import annotations

import contextlib
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from _harness import start_router, table

SERVER = """
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer
from rclpy.node import Node


def execute(goal_handle):
    goal_handle.succeed()
    return Fibonacci.Result(sequence=[0, 1])


rclpy.init()
node = Node("bench_action_server")
ActionServer(node, Fibonacci, "bench_fibonacci", execute)
print("ready", flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""
ROUND_TRIPS = 500


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def action_round_trips(env: dict[str, str]) -> list[float]:
    """Milliseconds of each send_goal → accepted → result, after a warm-up."""
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-actions-"))
    script = folder / "server.py"
    script.write_text(SERVER)
    site = Path(__file__).resolve().parent.parent / "launcher" / "compat" / "site"
    server = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE,
                              text=True, env={**env, "PYTHONPATH": str(site)})
    try:
        assert server.stdout is not None and server.stdout.readline().strip() == "ready"
        from launcher.compat import finder

        finder.install()
        import rclpy
        from example_interfaces.action import Fibonacci
        from rclpy.action import ActionClient
        from rclpy.executors import MultiThreadedExecutor
        from rclpy.node import Node

        rclpy.init()
        node = Node("bench_action_client")
        client = ActionClient(node, Fibonacci, "bench_fibonacci")
        executor = MultiThreadedExecutor()
        executor.add_node(node)
        def spin() -> None:
            with contextlib.suppress(Exception):  # (the executor shut down at the end)
                executor.spin()
        threading.Thread(target=spin, daemon=True).start()
        assert client.wait_for_server(30)
        times = []
        for n in range(ROUND_TRIPS + 50):
            start = time.perf_counter()
            result = client.send_goal(Fibonacci.Goal(order=2))
            took = (time.perf_counter() - start) * 1000
            assert result is not None and result.status == 4
            if n >= 50:  # (the first ones pay for imports and first messages)
                times.append(took)
        executor.shutdown()
        node.destroy_node()
        rclpy.shutdown()
        return times
    finally:
        server.send_signal(2)
        server.wait(10)


def tf2_lookups_per_second(seconds: float = 2.0) -> tuple[float, float]:
    import math

    from launcher.compat import finder

    finder.install()
    import tf2_ros
    from geometry_msgs.msg import TransformStamped
    from rclpy.time import Time

    buffer = tf2_ros.Buffer()
    for i in range(10):
        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = f"f{i}", f"f{i + 1}"
        t.header.stamp.sec = 1
        t.transform.translation.x = 0.1
        t.transform.rotation.z, t.transform.rotation.w = math.sin(0.05), math.cos(0.05)
        buffer.set_transform(t, "bench")
    count, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        buffer.core._cache.clear()  # each lookup worked out, as after a new transform
        buffer.lookup_transform("f0", "f10", Time())
        count += 1
    uncached = count / (time.perf_counter() - start)
    count, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:  # again, no transform having come
        buffer.lookup_transform("f0", "f10", Time())
        count += 1
    return uncached, count / (time.perf_counter() - start)


def data_conversions() -> tuple[float, float]:
    """(ms a read_points_numpy of 57,600 points, ms an imgmsg_to_cv2 of 640 × 480 rgb8)."""
    import numpy as np

    from launcher.compat import finder

    finder.install()
    from cv_bridge import CvBridge
    from sensor_msgs.msg import PointField
    from sensor_msgs_py import point_cloud2
    from std_msgs.msg import Header

    fields = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
              for i, n in enumerate(("x", "y", "z", "intensity"))]
    points = np.random.default_rng(1).random((57_600, 4), dtype=np.float32)
    layout = [(n, np.float32) for n in ("x", "y", "z", "intensity")]
    cloud = point_cloud2.create_cloud(Header(), fields, points.view(layout).ravel())
    bridge = CvBridge()
    image = bridge.cv2_to_imgmsg(np.zeros((480, 640, 3), np.uint8), "rgb8")

    def median_ms(call) -> float:
        times = []
        for _ in range(200):
            start = time.perf_counter()
            call()
            times.append((time.perf_counter() - start) * 1000)
        return statistics.median(times)
    return (median_ms(lambda: point_cloud2.read_points_numpy(cloud)),
            median_ms(lambda: bridge.imgmsg_to_cv2(image)))


def main() -> None:
    env, router = start_router()
    try:
        cloud_ms, image_ms = data_conversions()
        table("ROS libraries: data", [
            ("point_cloud2.read_points_numpy, 57,600 points, ms", "<= 5", f"{cloud_ms:.3f}"),
            ("CvBridge.imgmsg_to_cv2, 640 x 480 rgb8 (a view), ms", "<= 1", f"{image_ms:.4f}"),
        ])
        lookups, repeated = tf2_lookups_per_second()
        table("ROS libraries: tf2", [
            ("Buffer.lookup_transform through a 10-frame chain, lookups/s", ">= 50000",
             f"{lookups:.0f}"),
            ("  the same lookup again before any new transform (cached), lookups/s", "report",
             f"{repeated:.0f}")])
        times = action_round_trips(env)
        table("ROS libraries: actions", [
            (f"action round trip (send_goal → accepted → result), {ROUND_TRIPS} goals, "
             "p50 ms", "<= 1.5", f"{statistics.median(times):.3f}"),
            ("  p99 ms", "<= 5", f"{percentile(times, 0.99):.3f}"),
        ])
    finally:
        router.terminate()
        router.wait(10)


if __name__ == "__main__":
    main()

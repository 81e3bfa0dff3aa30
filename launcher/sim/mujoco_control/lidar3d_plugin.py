"""mujoco_ros2_control's Mujoco3dLidarPlugin: every MJCF lidar sensor (`mujoco.plugin.lidar`,
cast by sim/plugins/mjcf_lidar.py) on ROS.

One row of rays is a LaserScan (the ranges as the sensor writes them, -1 where nothing is in
range; angle_min/max the azimuth range) on `/scan`; several rows a PointCloud2 of x, y, z
float32 in the sensor's frame, `resolution` wide and high, NaN where nothing is in range, on
`/points`. Each sensor's `frame_name` (its site's name) and `topic` are read under
`mujoco_plugins.mujoco_3d_lidar_plugin.<sensor>.`, the prefix the plugin's code reads whatever
its instance is called. A scan is published once, stamped with the sim time it was taken, and
only while someone subscribes.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from launcher.bus.declarations import Param
from launcher.bus.wire import fill_stamp
from launcher.sim.mujoco_control.ros_plugin import Context, RosPlugin
from launcher.sim.plugins.mjcf_lidar import MjcfLidar

FLOAT32 = 7  # sensor_msgs/PointField


class Mujoco3dLidar(RosPlugin):
    PARAMETERS = (
        Param("{sensor}.frame_name", "string", "", "the frame of its messages (default: its "
              "site's name)"),
        Param("{sensor}.topic", "string", "", "where it is published (default: /scan for one "
              "row of rays, /points for several)"),
    )
    SCOPE = "mujoco_plugins.mujoco_3d_lidar_plugin."  # (fixed in the plugin's code)

    def __init__(self, context: Context, name: str) -> None:
        lidars = [p for p in context.world.plugins.world if isinstance(p, MjcfLidar)]
        defaults = {}
        for lidar in lidars:
            defaults[f"{lidar.label}.frame_name"] = lidar.site_name
            defaults[f"{lidar.label}.topic"] = "/points" if _three_d(lidar) else "/scan"
        super().__init__(context, name, defaults, sensor=[lidar.label for lidar in lidars])
        self.lidars = lidars
        self.outputs = [self._output(lidar) for lidar in lidars]
        if not lidars:
            self.log.info("No lidar sensors found")

    def _output(self, lidar: MjcfLidar) -> tuple[Any, str, float]:
        frame = self.values[f"{lidar.label}.frame_name"]
        topic = self.values[f"{lidar.label}.topic"]
        kind = "sensor_msgs/msg/PointCloud2" if _three_d(lidar) else "sensor_msgs/msg/LaserScan"
        publisher = self.node.create_publisher(kind, topic, 1)
        self.log.info(f"Adding lidar sensor: '{lidar.label}' ({lidar.resolution[0]} x "
                      f"{lidar.resolution[1]} rays) on {topic}, frame '{frame}'")
        return publisher, frame, 0.0

    def update(self, model: Any, data: Any, now: float) -> None:
        for index, lidar in enumerate(self.lidars):
            publisher, frame, published = self.outputs[index]
            if not lidar.stamp > published:
                continue
            self.outputs[index] = (publisher, frame, lidar.stamp)
            if not publisher.get_subscription_count():
                continue
            message = self._cloud(lidar) if _three_d(lidar) else self._scan(lidar)
            message.header.frame_id = frame
            fill_stamp(message.header.stamp, lidar.stamp)
            publisher.publish(message)

    def _scan(self, lidar: MjcfLidar) -> Any:
        low, high = lidar.azimuth_range
        step = (high - low) / (lidar.resolution[0] - 1) if lidar.resolution[0] > 1 \
            else math.inf
        scan = self.node.message(
            "sensor_msgs/msg/LaserScan", angle_min=low, angle_max=high, angle_increment=step,
            time_increment=0.0, range_min=lidar.min_range, range_max=lidar.max_range)
        scan.ranges = lidar.ranges.astype(np.float32)  # (as an array: no per-ray conversion)
        return scan

    def _cloud(self, lidar: MjcfLidar) -> Any:
        ranges = lidar.ranges.astype(np.float32)
        points = lidar.directions.astype(np.float32) * ranges[:, None]
        points[(ranges < lidar.min_range) | (ranges > lidar.max_range)] = np.nan
        width, height = lidar.resolution
        fields = [self.node.message("sensor_msgs/msg/PointField", name=name, offset=4 * i,
                                    datatype=FLOAT32, count=1)
                  for i, name in enumerate("xyz")]
        cloud = self.node.message(
            "sensor_msgs/msg/PointCloud2", height=height, width=width, fields=fields,
            is_bigendian=False, point_step=12, row_step=12 * width, is_dense=False)
        cloud.data = points.astype("<f4").reshape(-1).view(np.uint8)
        return cloud


def _three_d(lidar: MjcfLidar) -> bool:
    """Several rows of rays: a point cloud (one: a scan)."""
    return lidar.resolution[1] > 1

"""The lidar (`gpu_lidar`, `lidar`, classic `ray` and `gpu_ray`): one `mj_multiRay` call per scan
from the sensor's site, the rays' directions worked out once in the sensor frame, the sensor's
own body left out. Published as Gazebo does: a LaserScan on `…/scan` (every ray, row after
row, when there are several vertical ones: `count` a row, `vertical_count` rows, as
gz-sensors fills gz.msgs.LaserScan) and the points as a PointCloudPacked on `…/scan/points`,
each only while someone listens."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from launcher.sim import schedule
from launcher.sim.sdf.pose import child_number
from launcher.sim.sdf.xmltree import SdfError
from launcher.sim.sensors.base import Sensor
from launcher.sim.sensors.noise import NONE, Noise, noise_of

MAX_RAYS = 2_000_000  # rays in one scan: beyond it a scan would hold the sim up


@dataclass(frozen=True)
class Axis:
    samples: int = 1
    min_angle: float = 0.0
    max_angle: float = 0.0

    def angles(self) -> Any:
        if self.samples == 1:
            return np.array([self.min_angle])
        return np.linspace(self.min_angle, self.max_angle, self.samples)

    @property
    def increment(self) -> float:
        return (self.max_angle - self.min_angle) / (self.samples - 1) if self.samples > 1 \
            else 0.0


def _axis(scan: Any, tag: str, label: str) -> Axis:
    element = scan.find(tag) if scan is not None else None
    if element is None:
        return Axis()

    samples = child_number(element, "samples", 1)
    resolution = child_number(element, "resolution", 1)
    if samples < 1 or samples != int(samples):
        raise SdfError(f"{label}: <{tag}><samples> must be a whole number ≥ 1, got "
                       f"{element.value('samples')}", element.find("samples").location)
    if resolution <= 0:
        raise SdfError(f"{label}: <{tag}><resolution> must be > 0", element.location)
    low, high = child_number(element, "min_angle", 0.0), child_number(element, "max_angle", 0.0)
    if low > high:
        raise SdfError(f"{label}: <{tag}><min_angle> {low:g} is above <max_angle> {high:g}",
                       element.location)
    return Axis(max(1, round(samples * resolution)) if resolution > 1 else int(samples),
                low, high)


class Lidar(Sensor):
    message_type = "mujoco_sim/msg/LaserScan"
    suffix = "scan"

    def configure(self) -> None:
        element = self.config.element
        ray = element.find("lidar")
        if ray is None:
            ray = element.find("ray")
        scan = ray.find("scan") if ray is not None else None
        self.horizontal = _axis(scan, "horizontal", self.label)
        self.vertical = _axis(scan, "vertical", self.label)
        count = self.horizontal.samples * self.vertical.samples
        if count > MAX_RAYS:
            raise SdfError(f"{self.label}: {count} rays a scan is more than the "
                           f"{MAX_RAYS} the sim casts at once", element.location)
        limits = ray.find("range") if ray is not None else None
        self.range_min = float(limits.value("min", "0") or 0) if limits is not None else 0.0
        self.range_max = float(limits.value("max", "inf") or math.inf) \
            if limits is not None else math.inf
        if not 0 <= self.range_min < self.range_max:
            raise SdfError(f"{self.label}: <range> needs 0 ≤ min < max, got "
                           f"{self.range_min:g} and {self.range_max:g}", element.location)
        self.noise: Noise = noise_of(ray, self.rng) if ray is not None else NONE
        v, h = np.meshgrid(self.vertical.angles(), self.horizontal.angles(), indexing="ij")
        self.directions = np.stack([np.cos(v) * np.cos(h), np.cos(v) * np.sin(h), np.sin(v)],
                                   axis=-1).reshape(-1, 3)
        self.distances = np.zeros(count)
        self.geoms = np.zeros(count, dtype=np.int32)

    points_publisher: Any = None

    def make_publishers(self) -> None:
        super().make_publishers()
        self.points_publisher = self.sim.transport.publisher(
            "mujoco_sim/msg/PointCloudPacked", f"{self.topic_name()}/points")

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        self.body = int(model.site_bodyid[self.site])

    def watched(self) -> bool:
        return super().watched() or self.points_publisher.get_subscription_count() > 0

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        if not schedule.serve(self, now, self.period, self.watched()):
            return
        ranges = self.cast(model, data)
        if self.config.always_on or self.publisher.get_subscription_count() > 0:
            self.publisher.publish(self.scan_message(data, ranges))
        if self.points_publisher.get_subscription_count() > 0:
            self.points_publisher.publish(self.points_message(data, ranges))
        self.ros.publish(self, ranges, data, self.config.always_on)

    def cast(self, model: Any, data: Any) -> Any:
        """The range of each ray (inf past range_max or with nothing there), noise added."""
        rotation = data.site_xmat[self.site].reshape(3, 3)
        vectors = np.ascontiguousarray(self.directions @ rotation.T).reshape(-1)
        mujoco.mj_multiRay(model, data, data.site_xpos[self.site], vectors, None, 1,
                           self.body, self.geoms, self.distances, None, len(self.distances),
                           self.range_max if math.isfinite(self.range_max) else 1e10)
        ranges = self.distances.copy()
        if self.noise is not NONE and self.noise.stddev > 0:
            ranges += self.rng.normal(self.noise.mean, self.noise.stddev, ranges.shape)
        elif self.noise is not NONE:
            ranges += self.noise.mean
        ranges[(self.distances < 0) | (ranges > self.range_max)] = np.inf
        ranges[(self.distances >= 0) & (ranges < self.range_min)] = -np.inf
        return ranges.astype(np.float32)

    def scan_message(self, data: Any, ranges: Any) -> Any:
        scan = self.scan_message_of(ranges)
        scan.header = self.header(data)
        return scan

    def scan_message_of(self, ranges: Any, ros: bool = False) -> Any:
        """A scan of `ranges`, its header to be set: the sim's (all the rows, with gz's row
        fields), or, `ros`, a sensor_msgs/LaserScan (one row)."""
        h, v = self.horizontal, self.vertical
        fields = dict(header=None, angle_min=h.min_angle, angle_max=h.max_angle,
                      angle_increment=h.increment, time_increment=0.0, scan_time=self.period,
                      range_min=self.range_min, range_max=self.max_range_written,
                      ranges=ranges, intensities=np.zeros(len(ranges), dtype=np.float32))
        if ros:
            return self.sim.transport.message("sensor_msgs/msg/LaserScan", **fields)
        return self.sim.transport.message(
            self.message_type, **fields, count=h.samples, vertical_angle_min=v.min_angle,
            vertical_angle_max=v.max_angle, vertical_angle_step=v.increment,
            vertical_count=v.samples)

    @property
    def max_range_written(self) -> float:
        """range_max as a message carries it (a finite number)."""
        return self.range_max if math.isfinite(self.range_max) else 1e9

    def points_message(self, data: Any, ranges: Any) -> Any:
        """x, y, z (float32) and intensity per ray, in the sensor frame, rows as the scan's."""
        finite = np.where(np.isfinite(ranges), ranges, np.nan).astype(np.float32)
        cloud = np.zeros((len(ranges), 4), dtype=np.float32)
        cloud[:, :3] = self.directions.astype(np.float32) * finite[:, None]
        transport = self.sim.transport
        fields = [transport.message("sensor_msgs/msg/PointField", name=name, offset=4 * i,
                                    datatype=7, count=1)  # 7: FLOAT32
                  for i, name in enumerate(("x", "y", "z", "intensity"))]
        width, height = self.horizontal.samples, self.vertical.samples
        return transport.message(
            "mujoco_sim/msg/PointCloudPacked", header=self.header(data), height=height,
            width=width, fields=fields, is_bigendian=False, point_step=16,
            row_step=16 * width, data=cloud.tobytes(), is_dense=False)

    def close(self) -> None:
        super().close()
        if self.points_publisher is not None:
            self.points_publisher.destroy()

"""An MJCF's own sensors on the ROS graph, with no plugin to write: what MuJoCo computes for
them each step, published as the ROS messages a user of those sensors expects.

  rangefinder                        sensor_msgs/Range on `/<sensor>` (+inf: nothing within
                                     its cutoff), frame the site
  accelerometer, gyro, framequat     one sensor_msgs/Imu per site on `/<site>/imu` (what the
  on one site                        site lacks has covariance[0] = -1, as REP 145 says)
  touch                              std_msgs/Float64 on `/<sensor>`: the normal force, N
  force, torque on one site          geometry_msgs/WrenchStamped on `/<site>/wrench`

Names are the MuJoCo names (a spawned robot's carry its `<entity>/` prefix, so each robot's
topics are its own), made ROS names (characters ROS refuses become `_`). Each publishes at its
sensor's `interval` where the MJCF gives one, else at DEFAULT_RATE, in sim time, and only
while someone subscribes. A world file's sensors are the world's plugin's, a spawned model's
its entity's. mujoco_ros2_control's worlds leave their sensors to its hardware interface
(the loader adds this plugin, and mjcf_cameras.py's, to the other MJCF worlds and models:
sim/loading.py, sim/templates.py).
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from launcher.sim import schedule
from launcher.sim.mjcf import PluginConfig
from launcher.sim.plugins import Plugin

NAME = "mjcf_sensors"
DEFAULT_RATE = 100.0  # Hz, for a sensor whose MJCF gives no interval
RANGE, IMU, TOUCH, WRENCH = "range", "imu", "touch", "wrench"
S = mujoco.mjtSensor
PARTS = {int(S.mjSENS_RANGEFINDER): (RANGE, "range"), int(S.mjSENS_TOUCH): (TOUCH, "touch"),
         int(S.mjSENS_ACCELEROMETER): (IMU, "accel"), int(S.mjSENS_GYRO): (IMU, "gyro"),
         int(S.mjSENS_FRAMEQUAT): (IMU, "quat"), int(S.mjSENS_FORCE): (WRENCH, "force"),
         int(S.mjSENS_TORQUE): (WRENCH, "torque")}
TYPES = {RANGE: "sensor_msgs/msg/Range", IMU: "sensor_msgs/msg/Imu",
         TOUCH: "std_msgs/msg/Float64", WRENCH: "geometry_msgs/msg/WrenchStamped"}
INFRARED = 1  # sensor_msgs/Range: a ray, not a cone


@dataclass
class Output:
    kind: str
    name: str  # the sensor's (range, touch) or the site's (imu, wrench) MuJoCo name
    period: float
    sensors: dict[str, str] = field(default_factory=dict)  # part -> sensor name
    addresses: dict[str, int] = field(default_factory=dict)  # part -> sensordata address
    cutoff: float = math.inf
    frame: str = ""  # a rangefinder's site
    publisher: Any = None
    next_update: float = 0.0


def configs(label: str) -> list[PluginConfig]:
    """The configs that put an MJCF's sensors, and its declared cameras (mjcf_cameras.py),
    on ROS: what the loader adds to an MJCF world or model."""
    return [PluginConfig(name, name, ET.Element("plugin"), label)
            for name in (NAME, "mjcf_cameras")]


def ros_name(name: str) -> str:
    return "/" + re.sub(r"[^A-Za-z0-9_/]", "_", name).strip("/")


class MjcfSensors(Plugin):
    def __init__(self, sim: Any, entity: Any, config: Any) -> None:
        super().__init__(sim, entity, config)
        self.outputs: list[Output] | None = None  # found at the first bind

    def bind(self, model: Any, data: Any) -> None:
        if self.outputs is None:
            self.outputs = self._find(model)
            for output in self.outputs:
                suffix = {IMU: "/imu", WRENCH: "/wrench"}.get(output.kind, "")
                output.publisher = self.sim.transport.publisher(
                    TYPES[output.kind], ros_name(output.name) + suffix, ros=True)
        for output in self.outputs:
            output.addresses = {part: int(model.sensor_adr[model.sensor(name).id])
                                for part, name in output.sensors.items()}
        if not self.outputs:
            self.next_update = math.inf

    def _find(self, model: Any) -> list[Output]:
        prefix = f"{self.entity.name}/" if self.entity is not None else ""
        found: dict[tuple[str, str], Output] = {}
        for i in range(model.nsensor):
            part = PARTS.get(int(model.sensor_type[i]))
            name = model.sensor(i).name
            if part is None or not name or not name.startswith(prefix):
                continue
            kind, role = part
            interval = float(model.sensor_interval[i][0])
            period = interval if interval > 0 else schedule.period(DEFAULT_RATE)
            if kind in (RANGE, TOUCH):
                key = name
            elif int(model.sensor_objtype[i]) == int(mujoco.mjtObj.mjOBJ_SITE):
                key = model.site(int(model.sensor_objid[i])).name
            else:
                continue  # an orientation of a body or a geom: no site to name an Imu by
            output = found.setdefault((kind, key), Output(kind, key, period))
            output.period = min(output.period, period)
            output.sensors[role] = name
            if kind == RANGE:
                output.cutoff = float(model.sensor_cutoff[i]) or math.inf
                output.frame = model.site(int(model.sensor_objid[i])).name
        return list(found.values())

    def reset(self) -> None:
        for output in self.outputs or ():
            output.next_update = 0.0
        self.next_update = 0.0

    def close(self) -> None:  # (its entity removed, or its world replaced)
        for output in self.outputs or ():
            output.publisher.destroy()

    def post_step(self, model: Any, data: Any) -> None:
        now = float(data.time)
        soonest = math.inf
        for output in self.outputs or ():
            if schedule.is_due(now, output.next_update):
                if output.publisher.get_subscription_count():
                    output.publisher.publish(self._message(output, data, now))
                output.next_update = schedule.following(
                    output.next_update, now, max(output.period, schedule.LAZY_LOOK)
                    if not output.publisher.get_subscription_count() else output.period)
            soonest = min(soonest, output.next_update)
        self.next_update = soonest

    def _message(self, output: Output, data: Any, now: float) -> Any:
        transport = self.sim.transport
        values = data.sensordata
        at = output.addresses
        if output.kind == TOUCH:
            return transport.message(TYPES[TOUCH], data=float(values[at["touch"]]))
        if output.kind == RANGE:
            distance = float(values[at["range"]])
            return transport.message(
                TYPES[RANGE], header=transport.header(now, output.frame),
                radiation_type=INFRARED, field_of_view=0.0, min_range=0.0,
                max_range=output.cutoff, range=distance if distance >= 0 else math.inf,
                variance=0.0)
        header = transport.header(now, output.name)
        if output.kind == WRENCH:
            wrench = transport.message("geometry_msgs/msg/Wrench",
                                       force=self._vector(values, at, "force"),
                                       torque=self._vector(values, at, "torque"))
            return transport.message(TYPES[WRENCH], header=header, wrench=wrench)
        if "quat" in at:
            w, x, y, z = (float(v) for v in values[at["quat"]:at["quat"] + 4])
        else:
            w, x, y, z = 1.0, 0.0, 0.0, 0.0
        orientation = transport.message("geometry_msgs/msg/Quaternion", x=x, y=y, z=z, w=w)
        return transport.message(
            TYPES[IMU], header=header, orientation=orientation,
            orientation_covariance=_covariance("quat" in at),
            angular_velocity=self._vector(values, at, "gyro"),
            angular_velocity_covariance=_covariance("gyro" in at),
            linear_acceleration=self._vector(values, at, "accel"),
            linear_acceleration_covariance=_covariance("accel" in at))

    def _vector(self, values: Any, at: dict[str, int], part: str) -> Any:
        if part not in at:
            return self.sim.transport.vector(0.0, 0.0, 0.0)
        return self.sim.transport.vector(*values[at[part]:at[part] + 3])


def _covariance(known: bool) -> Any:
    """Unknown covariance (zeros), or REP 145's "no such reading" (-1 first)."""
    covariance = np.zeros(9)
    if not known:
        covariance[0] = -1.0
    return covariance

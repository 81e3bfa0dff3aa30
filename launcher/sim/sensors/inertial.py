"""The IMU and the magnetometer, read from MuJoCo's own sensors at the sensor's site: its
accelerometer (proper acceleration: at rest it reads +9.8 m/s² up, as Gazebo's IMU does), gyro
and magnetometer (the world's `<magnetic_field>`, as model.opt.magnetic, in the site frame)."""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from launcher.sim.sdf.pose import numbers
from launcher.sim.sensors.base import Sensor
from launcher.sim.sensors.noise import noise_of
from launcher.sim.transform import from_rpy

AXES = ("x", "y", "z")


class MuJoCoSensors(Sensor):
    """A sensor made of MuJoCo sensors at its site, one 3-vector each."""

    readings: tuple[tuple[str, Any], ...] = ()  # (suffix, mjtSensor)

    def prepare(self, spec: Any) -> None:
        super().prepare(spec)
        site = self.in_spec(self.config.site)
        for suffix, kind in self.readings:
            spec.add_sensor(name=f"{site}/{suffix}", type=kind,
                            objtype=mujoco.mjtObj.mjOBJ_SITE, objname=site)

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        site = f"{self.entity.name}/{self.config.site}"
        self.addresses = {suffix: int(model.sensor(f"{site}/{suffix}").adr[0])
                          for suffix, _ in self.readings}

    def vector(self, data: Any, suffix: str, noises: list[Any]) -> Any:
        start = self.addresses[suffix]
        values = data.sensordata[start:start + 3]
        return self.sim.transport.vector(*(n.apply(float(v), self.rng)
                                           for n, v in zip(noises, values, strict=True)))

    def axis_noises(self, *tags: str) -> list[Any]:
        """The `<x|y|z><noise>` of the element at `tags` below the sensor's, per axis."""
        element = self.config.element.path(*tags) if tags else None
        return [noise_of(element.find(axis) if element is not None else None, self.rng)
                for axis in AXES]


ZERO9 = [0.0] * 9  # covariances: Gazebo's messages carry none


class Imu(MuJoCoSensors):
    message_type = "mujoco_sim/msg/IMU"
    suffix = "imu"
    orientation = True  # <enable_orientation>
    fixed_reference: Any = None  # <orientation_reference_frame>'s, where it names one
    reference: Any = None  # the orientation readings are against (set at the first bind)
    readings = (("accelerometer", mujoco.mjtSensor.mjSENS_ACCELEROMETER),
                ("gyro", mujoco.mjtSensor.mjSENS_GYRO))

    def configure(self) -> None:
        self.linear_noise = self.axis_noises("imu", "linear_acceleration")
        self.angular_noise = self.axis_noises("imu", "angular_velocity")
        imu = self.config.element.find("imu")
        self.orientation = _flag(imu.value("enable_orientation") if imu is not None else None,
                                 True)
        self.fixed_reference = _reference_frame(
            imu.find("orientation_reference_frame") if imu is not None else None,
            getattr(getattr(self.sim, "spherical_coordinates", None), "heading_deg", 0.0),
            self._warn)

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        if self.reference is None:  # (once: a recompile keeps what it was measured against)
            self.reference = self.fixed_reference if self.fixed_reference is not None else \
                self._site_quat(data)

    def _site_quat(self, data: Any) -> Any:
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, data.site_xmat[self.site])
        return quat

    def measure(self, model: Any, data: Any) -> Any:
        inverse, relative = np.zeros(4), np.zeros(4)
        mujoco.mju_negQuat(inverse, self.reference)
        mujoco.mju_mulQuat(relative, inverse, self._site_quat(data))
        transport = self.sim.transport
        w, x, y, z = (float(v) for v in relative) if self.orientation else (0.0,) * 4
        return transport.message(
            self.message_type, header=self.header(data),
            orientation=transport.message("geometry_msgs/msg/Quaternion", x=x, y=y, z=z, w=w),
            orientation_covariance=ZERO9 if self.orientation else NO_ORIENTATION,
            angular_velocity=self.vector(data, "gyro", self.angular_noise),
            angular_velocity_covariance=ZERO9,
            linear_acceleration=self.vector(data, "accelerometer", self.linear_noise),
            linear_acceleration_covariance=ZERO9)


class Magnetometer(MuJoCoSensors):
    message_type = "mujoco_sim/msg/Magnetometer"
    suffix = "magnetometer"
    readings = (("magnetometer", mujoco.mjtSensor.mjSENS_MAGNETOMETER),)

    def configure(self) -> None:
        self.noise = self.axis_noises("magnetometer")

    def measure(self, model: Any, data: Any) -> Any:
        return self.sim.transport.message(
            self.message_type, header=self.header(data),
            magnetic_field=self.vector(data, "magnetometer", self.noise),
            magnetic_field_covariance=ZERO9)


# <enable_orientation>false: no orientation, which ROS says with a covariance of -1 (REP 145)
NO_ORIENTATION = [-1.0] + [0.0] * 8
# ENU → each named frame, as gz-sensors turns the world's east-north-up (roll, pitch, yaw)
LOCALIZATIONS = {"ENU": (0.0, 0.0, 0.0), "NED": (math.pi, 0.0, math.pi / 2),
                 "NWU": (0.0, 0.0, math.pi / 2)}


def _flag(text: str | None, default: bool) -> bool:
    return default if text in (None, "") else text.strip().lower() in ("true", "1")


def _reference_frame(element: Any, heading_deg: float, warn: Any) -> Any:
    """The orientation an IMU's readings are against, as gz-sim and gz-sensors set it:
    `<localization>` ENU, NED or NWU (the world's, turned by the spherical coordinates'
    heading), CUSTOM with `<custom_rpy parent_frame="world">`; None (its first orientation)
    without one, or with a localization Gazebo does not know."""
    if element is None:
        return None
    localization = (element.value("localization") or "").strip().upper()
    heading = from_rpy(0, 0, 0, 0, 0, math.radians(heading_deg))
    if localization in LOCALIZATIONS:
        turned = heading * from_rpy(0, 0, 0, *LOCALIZATIONS[localization])
    elif localization == "CUSTOM":
        custom = element.find("custom_rpy")
        if custom is None or custom.get("parent_frame", "world") != "world":
            warn(custom if custom is not None else element,
                 "<custom_rpy> needs parent_frame=\"world\" (as in Gazebo); the IMU's "
                 "orientation is against its first one")
            return None
        turned = heading * from_rpy(0, 0, 0, *numbers(custom, 3, "<custom_rpy>"))
    else:
        if localization:
            warn(element.find("localization"),
                 f"<localization> '{localization}' is not one Gazebo knows (ENU, NED, NWU, "
                 "CUSTOM); the IMU's orientation is against its first one")
        return None
    return np.array(turned.quat, dtype=float)

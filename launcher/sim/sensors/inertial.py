"""The IMU and the magnetometer, read from MuJoCo's own sensors at the sensor's site: its
accelerometer (proper acceleration: at rest it reads +9.8 m/s² up, as Gazebo's IMU does), gyro
and magnetometer (the world's `<magnetic_field>`, as model.opt.magnetic, in the site frame)."""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from launcher.sim.sensors.base import Sensor
from launcher.sim.sensors.noise import noise_of

AXES = ("x", "y", "z")


class _MuJoCoSensors(Sensor):
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


class Imu(_MuJoCoSensors):
    message_type = "mujoco_sim/msg/IMU"
    suffix = "imu"
    world_reference = False
    reference: Any = None  # the orientation readings are against (set at the first bind)
    readings = (("accelerometer", mujoco.mjtSensor.mjSENS_ACCELEROMETER),
                ("gyro", mujoco.mjtSensor.mjSENS_GYRO))

    def configure(self) -> None:
        self.linear_noise = self.axis_noises("imu", "linear_acceleration")
        self.angular_noise = self.axis_noises("imu", "angular_velocity")
        # Gazebo reports the orientation against the sensor's first one, or against the
        # world's (east-north-up) with <orientation_reference_frame>
        self.world_reference = self.config.element.path("imu", "orientation_reference_frame") \
            is not None

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        if self.reference is None:
            self.reference = np.array([1.0, 0, 0, 0]) if self.world_reference else \
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
        w, x, y, z = (float(v) for v in relative)
        return transport.message(
            self.message_type, header=self.header(data),
            orientation=transport.message("geometry_msgs/msg/Quaternion", x=x, y=y, z=z, w=w),
            orientation_covariance=ZERO9,
            angular_velocity=self.vector(data, "gyro", self.angular_noise),
            angular_velocity_covariance=ZERO9,
            linear_acceleration=self.vector(data, "accelerometer", self.linear_noise),
            linear_acceleration_covariance=ZERO9)


class Magnetometer(_MuJoCoSensors):
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

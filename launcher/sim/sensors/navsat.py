"""The satellite navigation sensor: the sensor's place in the world's `<spherical_coordinates>`
(geodesy.py), and its velocity in the local east-north-up frame."""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from launcher.sim.sensors.base import Sensor
from launcher.sim.sensors.geodesy import SEMI_MAJOR, SphericalCoordinates
from launcher.sim.sensors.noise import noise_of


class NavSat(Sensor):
    message_type = "mujoco_sim/msg/NavSat"
    suffix = "navsat"

    def configure(self) -> None:
        self.coordinates: SphericalCoordinates = getattr(self.sim, "spherical_coordinates",
                                                         SphericalCoordinates())
        element = self.config.element.find("navsat")
        if element is None:
            element = self.config.element.find("gps")  # classic Gazebo's
        noises = {}
        for part in ("horizontal", "vertical"):
            for what in ("position", "velocity"):
                found = element.path(f"{what}_sensing", part) if element is not None else None
                noises[(what, part)] = noise_of(found, self.rng)
        self.noises = noises

    def measure(self, model: Any, data: Any) -> Any:
        x, y, z = (float(v) for v in data.site_xpos[self.site])
        latitude, longitude, altitude = self.coordinates.geodetic(x, y, z)
        velocity = np.zeros(6)
        mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_SITE, self.site, velocity, 0)
        east, north, up = self.coordinates.enu(*(float(v) for v in velocity[3:6]))
        n = self.noises
        metres_per_degree = math.pi * SEMI_MAJOR / 180.0
        latitude += n[("position", "horizontal")].apply(0.0, self.rng) / metres_per_degree
        longitude += n[("position", "horizontal")].apply(0.0, self.rng) / (
            metres_per_degree * max(math.cos(math.radians(latitude)), 1e-9))
        return self.sim.transport.message(
            self.message_type, header=self.header(data), latitude_deg=latitude,
            longitude_deg=longitude,
            altitude=n[("position", "vertical")].apply(altitude, self.rng),
            velocity_east=n[("velocity", "horizontal")].apply(east, self.rng),
            velocity_north=n[("velocity", "horizontal")].apply(north, self.rng),
            velocity_up=n[("velocity", "vertical")].apply(up, self.rng))

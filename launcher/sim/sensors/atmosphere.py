"""The altimeter, the air pressure and the air speed sensors: the sensor's height and vertical
speed against where it started; the air pressure of the International Standard Atmosphere at
its height above `<reference_altitude>`; and the dynamic pressure of the air flowing along the
sensor's x axis in still air, with the air's temperature at its height (the formulas
gz-sensors uses)."""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from launcher.sim.sensors.base import Sensor
from launcher.sim.sensors.noise import noise_of

SEA_LEVEL_PRESSURE = 101325.0  # Pa
SEA_LEVEL_TEMPERATURE = 288.15  # K
LAPSE_RATE = 0.0065  # K/m
EARTH_RADIUS = 6356766.0  # m, for the geopotential height
EXPONENT = 9.80665 * 0.0289644 / (8.3144598 * LAPSE_RATE)  # g·M / (R·L)


def pressure_at(height: float) -> float:
    """The standard atmosphere's pressure at `height` metres above sea level (troposphere)."""
    geopotential = EARTH_RADIUS * height / (EARTH_RADIUS + height)
    temperature = SEA_LEVEL_TEMPERATURE - LAPSE_RATE * geopotential
    return SEA_LEVEL_PRESSURE * (temperature / SEA_LEVEL_TEMPERATURE) ** EXPONENT


class Altimeter(Sensor):
    message_type = "mujoco_sim/msg/Altimeter"
    suffix = "altimeter"
    reference: float | None = None  # the height readings are against (the first bind's)

    def configure(self) -> None:
        self.position_noise = noise_of(self.config.element.path("altimeter",
                                                                "vertical_position"), self.rng)
        self.velocity_noise = noise_of(self.config.element.path("altimeter",
                                                                "vertical_velocity"), self.rng)

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        if self.reference is None:  # where it starts (Gazebo's vertical reference)
            self.reference = float(data.site_xpos[self.site][2])

    def measure(self, model: Any, data: Any) -> Any:
        velocity = np.zeros(6)
        mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_SITE, self.site, velocity, 0)
        height = float(data.site_xpos[self.site][2]) - (self.reference or 0.0)
        return self.sim.transport.message(
            self.message_type, header=self.header(data),
            vertical_position=self.position_noise.apply(height, self.rng),
            vertical_velocity=self.velocity_noise.apply(float(velocity[5]), self.rng),
            vertical_reference=self.reference or 0.0)


class AirPressure(Sensor):
    message_type = "mujoco_sim/msg/FluidPressure"
    suffix = "air_pressure"

    def configure(self) -> None:
        element = self.config.element.find("air_pressure")
        text = element.value("reference_altitude", "0") if element is not None else "0"
        try:
            self.reference_altitude = float(text or 0)
        except ValueError:
            raise element.find("reference_altitude").error(
                f"{self.label}: <reference_altitude> must be a number of metres, got "
                f"'{text}'") from None
        self.noise = noise_of(self.config.element.path("air_pressure", "pressure"), self.rng)

    def measure(self, model: Any, data: Any) -> Any:
        height = self.reference_altitude + float(data.site_xpos[self.site][2])
        # ROS's variance is the noise's stddev squared (Gazebo writes its square root)
        return self.sim.transport.message(
            self.message_type, header=self.header(data),
            fluid_pressure=self.noise.apply(pressure_at(height), self.rng),
            variance=self.noise.stddev ** 2)


AIR_DENSITY = 1.225  # kg/m³ at sea level


class AirSpeed(Sensor):
    message_type = "mujoco_sim/msg/AirSpeedSensor"
    suffix = "air_speed"

    def configure(self) -> None:
        self.noise = noise_of(self.config.element.path("air_speed", "pressure"), self.rng)

    def measure(self, model: Any, data: Any) -> Any:
        velocity = np.zeros(6)  # in the sensor's frame: the air comes at it along -x
        mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_SITE, self.site, velocity, 1)
        forward = float(velocity[3])
        temperature = SEA_LEVEL_TEMPERATURE - LAPSE_RATE * float(data.site_xpos[self.site][2])
        density = AIR_DENSITY / (SEA_LEVEL_TEMPERATURE / temperature) ** 4.256
        # gz-sensors adds the noise in hPa and publishes pascals
        hectopascals = float(np.sign(forward)) * 0.005 * density * forward * forward
        return self.sim.transport.message(
            self.message_type, header=self.header(data),
            diff_pressure=self.noise.apply(hectopascals, self.rng) * 100.0,
            temperature=temperature)


__all__ = ["AirPressure", "AirSpeed", "Altimeter", "pressure_at"]

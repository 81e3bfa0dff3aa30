"""The force-torque sensor of a joint, read from MuJoCo's force and torque sensors at a site on
the joint's child body: the force and torque the parent exerts on the child across the joint
(what holds a hanging link up reads +z), about the sensor's point, as gz-sim's ForceTorque
system reports them. `<force_torque><frame>` (child, parent or sensor) turns them into that
frame; `<measure_direction>parent_to_child</measure_direction>` turns them around."""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from launcher.errors import did_you_mean
from launcher.sim.sensors.inertial import AXES, MuJoCoSensors
from launcher.sim.sensors.noise import noise_of

FRAMES = ("child", "parent", "sensor")
DIRECTIONS = ("child_to_parent", "parent_to_child")


class ForceTorque(MuJoCoSensors):
    message_type = "mujoco_sim/msg/Wrench"
    suffix = "forcetorque"
    readings = (("force", mujoco.mjtSensor.mjSENS_FORCE),
                ("torque", mujoco.mjtSensor.mjSENS_TORQUE))

    def configure(self) -> None:
        settings = self.config.element.find("force_torque")
        self.frame = self._choice(settings, "frame", FRAMES)
        self.sign = -1.0 if self._choice(settings, "measure_direction", DIRECTIONS) \
            == "parent_to_child" else 1.0
        self.noises = {part: [noise_of(settings.path(part, axis) if settings is not None
                                       else None, self.rng) for axis in AXES]
                       for part in ("force", "torque")}

    def _choice(self, settings: Any, tag: str, choices: tuple[str, ...]) -> str:
        element = settings.find(tag) if settings is not None else None
        value = element.stripped if element is not None else ""
        if not value:
            return choices[0]
        if value not in choices:
            raise element.error(f"<{tag}> '{value}' is not one of {', '.join(choices)}"
                                f"{did_you_mean(value, list(choices))}")
        return value

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        child = int(model.site_bodyid[self.site])
        self.frame_body = {"child": child, "parent": int(model.body_parentid[child]),
                           "sensor": None}[self.frame]

    def measure(self, model: Any, data: Any) -> Any:
        turn = np.eye(3) if self.frame_body is None else \
            data.xmat[self.frame_body].reshape(3, 3).T @ data.site_xmat[self.site].reshape(3, 3)
        transport = self.sim.transport
        parts = {}
        for part in ("force", "torque"):
            start = self.addresses[part]
            values = turn @ (self.sign * np.asarray(data.sensordata[start:start + 3]))
            parts[part] = transport.vector(*(n.apply(float(v), self.rng) for n, v in
                                             zip(self.noises[part], values, strict=True)))
        wrench = transport.message("geometry_msgs/msg/Wrench", **parts)
        return transport.message(self.message_type, header=self.header(data), wrench=wrench)

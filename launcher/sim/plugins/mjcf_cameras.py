"""An MJCF's cameras declared ROS cameras, with no plugin to write:

    <custom>
      <text name="ros_cameras" data="front rear"/>       (the cameras, by name)
      <numeric name="ros_camera_rate" data="30"/>        (Hz of sim time; DEFAULT_RATE)
    </custom>

Each is published as mujoco_ros2_control's CameraPlugin publishes a camera
(sim/sensors/mjcf_camera.py): colour on `/<camera>/color`, aligned depth on `/<camera>/depth`,
`/<camera>/camera_info`, frame `<camera>_frame`, at the camera's `resolution` and `fovy`,
drawn by the sim's renderer only while someone watches. A spawned model's declaration names
its own cameras (their topics carry its `<entity>/` prefix). A name that is not one of the
model's cameras is a warning with the nearest, and the others are published.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.errors import did_you_mean
from launcher.sim import schedule
from launcher.sim.plugins import Plugin
from launcher.sim.plugins.mjcf_sensors import ros_name
from launcher.sim.sensors.mjcf_camera import MjcfCamera
from launcher.sim.sensors.rendering import rendering_of

NAME = "mjcf_cameras"
DECLARATION, RATE = "ros_cameras", "ros_camera_rate"
DEFAULT_RATE = 30.0


class MjcfCameras(Plugin):
    def __init__(self, sim: Any, entity: Any, config: Any) -> None:
        super().__init__(sim, entity, config)
        self.cameras: list[MjcfCamera] | None = None  # found at the first bind
        self.rate = DEFAULT_RATE

    def bind(self, model: Any, data: Any) -> None:
        if self.cameras is None:
            self.cameras = self._declared(model)
            self.next_update = 0.0 if self.cameras else math.inf

    def _declared(self, model: Any) -> list[MjcfCamera]:
        prefix = f"{self.entity.name}/" if self.entity is not None else ""
        text = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_TEXT, prefix + DECLARATION)
        if text < 0:
            return []
        start = int(model.text_adr[text])
        wanted = bytes(model.text_data[start:start + int(model.text_size[text])]) \
            .rstrip(b"\0").decode().split()
        rate = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_NUMERIC, prefix + RATE)
        if rate >= 0:
            self.rate = float(model.numeric_data[model.numeric_adr[rate]])
        if not (math.isfinite(self.rate) and self.rate > 0):
            self.sim.transport.logger.warning(
                f"{self.config.where}: {RATE} {self.rate:g} is no rate; {DEFAULT_RATE:g} Hz")
            self.rate = DEFAULT_RATE
        names = [model.camera(i).name for i in range(model.ncam)]
        rendering = rendering_of(self.sim)
        found = []
        for name in wanted:
            if prefix + name not in names:
                self.sim.transport.logger.warning(
                    f"{self.config.where}: {DECLARATION}: '{name}' is not a camera of the model"
                    f"{did_you_mean(name, [n.removeprefix(prefix) for n in names])}")
                continue
            camera = MjcfCamera(model, names.index(prefix + name), {}, self.rate, ros_name)
            rendering.add(camera)
            found.append(camera)
            self.sim.transport.logger.info(
                f"camera '{camera.camera_name}' ({camera.width}x{camera.height}) on "
                f"{camera.topics['image']}, {camera.topics['depth_image']}, "
                f"{camera.topics['camera_info']}")
        return found

    def reset(self) -> None:
        self.next_update = 0.0 if self.cameras else math.inf

    def post_step(self, model: Any, data: Any) -> None:
        if not schedule.tick(self, float(data.time), self.rate):
            return
        rendering = rendering_of(self.sim)
        rendering.sync(model)  # (the renderer's model, again after a spawn's recompile)
        drawn = [c.camera_name for c in self.cameras or () if rendering.wants(c.camera_name)]
        if drawn:
            rendering.request(drawn, data)

    def close(self) -> None:
        for camera in self.cameras or ():
            rendering_of(self.sim).remove(camera)

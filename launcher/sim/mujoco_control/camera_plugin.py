"""mujoco_ros2_control's CameraPlugin: the MJCF's `<camera>`s as ROS cameras, each a colour
image (rgb8), a depth image aligned to it (32FC1, metres along the optical axis; past the far
clip it reads the far clip, as the plugin's linearised depth buffer does) and its
camera_info (focal length from the camera's `fovy`, the centre of the picture), stamped in
sim time, in the frame `frame_name`.

Its parameters are read under `mujoco_plugins.mujoco_camera_plugin.` whatever the plugin's
own name, as the plugin reads them: `camera_publish_rate` (Hz of sim time, 5) and per camera
`<camera>.policy` (streaming: at the rate; polled: once per call of its
`trigger_service_name` std_srvs/Trigger; disabled), `.frame_name` (`<camera>_frame`),
`.image_topic` (`<camera>/color`), `.depth_topic` (`<camera>/depth`), `.info_topic`
(`<camera>/camera_info`). Settings for a camera the model does not have are said, with the
place they are written and the model's cameras, and the sim runs on.

Drawing is the sim's renderer's (sim/sensors/rendering.py, nodes/renderer.py): a process of
its own, never the stepping thread, and only for cameras someone watches.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.control.yaml_places import key_place
from launcher.errors import LaunchError, did_you_mean
from launcher.sim.mujoco_control.ros_plugin import RosPlugin
from launcher.sim.sensors.mjcf_camera import MjcfCamera
from launcher.sim.sensors.rendering import rendering_of

PARAMETERS = "mujoco_plugins.mujoco_camera_plugin."
POLICIES = ("streaming", "polled", "disabled")


class CameraPlugin(RosPlugin):
    def __init__(self, *args: Any, files: list[str] | None = None) -> None:
        super().__init__(*args)
        params = {k[len(PARAMETERS):]: v for k, v in self.node.parameters.items()
                  if k.startswith(PARAMETERS)}
        self.rate = float(params.get("camera_publish_rate", 5.0))
        if not (math.isfinite(self.rate) and self.rate > 0):
            raise LaunchError(f"{self.where}: {PARAMETERS}camera_publish_rate must be a rate "
                              f"in Hz above 0, got {self.rate}")
        model = self.world.model
        names = [model.camera(i).name for i in range(model.ncam)]
        self._unknown(params, names, files or [])
        self.rendering = rendering_of(self.world)
        self.cameras: list[MjcfCamera] = []
        for index, name in enumerate(names):
            config = {k[len(name) + 1:]: v for k, v in params.items()
                      if k.startswith(f"{name}.")}
            policy = str(config.get("policy", "streaming"))
            if policy not in POLICIES:
                raise LaunchError(f"{self.where}: {PARAMETERS}{name}.policy: '{policy}' is not "
                                  f"a policy{did_you_mean(policy, list(POLICIES))} (expected "
                                  f"{', '.join(POLICIES)})")
            if policy == "disabled":
                continue
            camera = MjcfCamera(self.world.model, index, config, self.rate, self.topic)
            self.cameras.append(camera)
            self.rendering.add(camera)
            if policy == "polled":
                service = self.topic(str(config.get("trigger_service_name",
                                                    f"{name}/trigger")))
                self.node.create_service("std_srvs/srv/Trigger", service,
                                         self._trigger(camera))
            self.log.info(f"camera '{name}' ({policy}, {camera.width}x{camera.height}): "
                          f"{camera.topics['image']}, {camera.topics['depth_image']}, "
                          f"{camera.topics['camera_info']} in frame '{camera.frame}'")
        self.period = 1.0 / self.rate
        self.last = -math.inf

    def _unknown(self, params: dict[str, Any], names: list[str], files: list[str]) -> None:
        """Settings for a camera the model does not have: said once each, with their place."""
        for name in sorted({k.split(".")[0] for k in params if "." in k} - set(names)):
            setting = next(k for k in params if k.startswith(f"{name}."))
            place = key_place(files, "/**", f"{PARAMETERS}{setting}") or \
                key_place(files, "mujoco_ros2_control_node", f"{PARAMETERS}{setting}") or \
                self.where
            self.log.warning(f"{place}: {PARAMETERS}{name}: the MuJoCo model has no camera "
                             f"'{name}'{did_you_mean(name, names)} (its cameras: "
                             f"{', '.join(names) or 'none'}); these settings are unused")

    def _trigger(self, camera: MjcfCamera) -> Any:
        def triggered(request: Any, response: Any) -> Any:
            camera.requested = True
            response.success = True
            return response
        return triggered

    def update(self, model: Any, data: Any, now: float) -> None:
        due = now - self.last >= self.period - 1e-9
        if due:
            self.last = now
        rendering = self.rendering
        drawn = []
        for camera in self.cameras:
            if camera.policy == "streaming" and due and rendering.wants(camera.camera_name):
                drawn.append(camera.camera_name)
            elif camera.requested:
                camera.requested = False
                drawn.append(camera.camera_name)
        if drawn:
            rendering.request(drawn, data)
        else:
            rendering.sync(model)  # (the renderer knows the model before the first frame)

    def close(self) -> None:
        for camera in self.cameras:
            self.rendering.remove(camera)

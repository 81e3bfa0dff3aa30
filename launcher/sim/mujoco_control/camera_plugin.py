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

from typing import Any

from launcher.bus.declarations import Param
from launcher.errors import did_you_mean
from launcher.sim import schedule
from launcher.sim.mujoco_control.ros_plugin import Context, RosPlugin
from launcher.sim.sensors.mjcf_camera import MjcfCamera
from launcher.sim.sensors.rendering import rendering_of

POLICIES = ("streaming", "polled", "disabled")
SETTINGS = ("policy", "frame_name", "image_topic", "depth_topic", "info_topic",
            "trigger_service_name")  # each camera's


class CameraPlugin(RosPlugin):
    PARAMETERS = (
        Param("camera_publish_rate", "double", 5.0, "pictures a second of sim time, every "
              "streaming camera's (Hz)", above=0.0),
        Param("{camera}.policy", "string", "streaming", "streaming: at the rate; polled: once "
              "per call of its trigger service; disabled",
              choices=POLICIES),
        Param("{camera}.frame_name", "string", "{camera}_frame", "the frame of its pictures"),
        Param("{camera}.image_topic", "string", "{camera}/color", "its colour images"),
        Param("{camera}.depth_topic", "string", "{camera}/depth", "its aligned depth images"),
        Param("{camera}.info_topic", "string", "{camera}/camera_info", "its camera_info"),
        Param("{camera}.trigger_service_name", "string", "{camera}/trigger",
              "a polled camera's std_srvs/Trigger"),
    )
    SCOPE = "mujoco_plugins.mujoco_camera_plugin."  # (fixed in the plugin's code)
    RATE = "camera_publish_rate"

    def __init__(self, context: Context, name: str) -> None:
        model = context.world.model
        names = [model.camera(i).name for i in range(model.ncam)]
        super().__init__(context, name, camera=names)
        self._unknown(names)
        self.rendering = rendering_of(self.world)
        self.cameras: list[MjcfCamera] = []
        for index, camera_name in enumerate(names):
            config = {key: self.values[f"{camera_name}.{key}"] for key in SETTINGS}
            if config["policy"] != "disabled":
                self._add(MjcfCamera(model, index, config, self.rate, self.topic), config)

    def _add(self, camera: MjcfCamera, config: dict[str, Any]) -> None:
        self.cameras.append(camera)
        self.rendering.add(camera)
        if camera.policy == "polled":
            self.node.create_service("std_srvs/srv/Trigger",
                                     self.topic(config["trigger_service_name"]),
                                     self._trigger(camera))
        self.log.info(f"camera '{camera.camera_name}' ({camera.policy}, {camera.width}x"
                      f"{camera.height}): {camera.topics['image']}, "
                      f"{camera.topics['depth_image']}, {camera.topics['camera_info']} in "
                      f"frame '{camera.frame}'")

    def _unknown(self, names: list[str]) -> None:
        """Settings for a camera the model does not have: said once each, with their place."""
        prefix = self.prefix
        given = [k.removeprefix(prefix) for k in self.node.parameters if k.startswith(prefix)]
        for name in sorted({k.split(".")[0] for k in given if "." in k} - set(names)):
            setting = next(k for k in given if k.startswith(f"{name}."))
            self.log.warning(f"{self.place(prefix + setting)}: {prefix}{name}: the MuJoCo "
                             f"model has no camera '{name}'{did_you_mean(name, names)} (its "
                             f"cameras: {', '.join(names) or 'none'}); these settings are "
                             f"unused")

    def _trigger(self, camera: MjcfCamera) -> Any:
        def triggered(request: Any, response: Any) -> Any:
            camera.requested = True
            response.success = True
            return response
        return triggered

    def update(self, model: Any, data: Any, now: float) -> None:
        """Every control cycle: a polled camera's request; the streaming ones when due."""
        due = schedule.tick(self, now, self.rate)
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

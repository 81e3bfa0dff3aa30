"""An MJCF `<camera>` as a ROS camera: colour (rgb8), depth aligned to it (32FC1, metres along
the optical axis; past the far clip the far clip) and camera_info (focal length from its
`fovy`, the centre of the picture), at its `resolution`, in frame `frame_name`
(`<camera>_frame`), on `image_topic` (`<camera>/color`), `depth_topic` (`<camera>/depth`) and
`info_topic` (`<camera>/camera_info`), drawn by the sim's renderer (rendering.py) at `rate`.
mujoco_ros2_control's CameraPlugin and an MJCF world's declared cameras (sim/plugins/
mjcf_cameras.py) are these.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any


class MjcfCamera:
    """One MJCF camera as the renderer draws it (its settings) and a plugin schedules it."""

    def __init__(self, model: Any, index: int, config: dict[str, Any], rate: float,
                 topic: Callable[[str], str]) -> None:
        self.camera_name = model.camera(index).name
        self.policy = str(config.get("policy", "streaming"))
        self.width, self.height = (int(v) for v in model.cam_resolution[index])
        self.fovy = float(model.cam_fovy[index])
        name = self.camera_name
        self.frame = str(config.get("frame_name", f"{name}_frame"))
        self.topics = {stream: topic(str(config.get(key, default))) for stream, key,
                       default in (("image", "image_topic", f"{name}/color"),
                                   ("depth_image", "depth_topic", f"{name}/depth"),
                                   ("camera_info", "info_topic", f"{name}/camera_info"))}
        extent = float(model.stat.extent)
        self.near = float(model.vis.map.znear) * extent
        self.far = float(model.vis.map.zfar) * extent
        self.rate = rate
        self.requested = False  # a polled camera's trigger, not yet drawn

    def settings(self) -> dict[str, Any]:
        """What the renderer needs of this camera (sent with the model)."""
        near, far = self.near, self.far
        focal = self.height / 2 / math.tan(math.radians(self.fovy) / 2)
        types = {"image": "sensor_msgs/msg/Image", "depth_image": "sensor_msgs/msg/Image",
                 "camera_info": "sensor_msgs/msg/CameraInfo"}
        return {"camera": self.camera_name, "kind": "camera", "width": self.width,
                "height": self.height, "encoding": "rgb8", "near": near, "far": far,
                "depth_near": near, "depth_far": far, "beyond_far": "far",
                "k": [focal, 0.0, self.width / 2, 0.0, focal, self.height / 2, 0.0, 0.0, 1.0],
                "frame_id": self.frame, "topics": {}, "always_on": False,
                "name": self.camera_name, "noise": [0.0, 0.0], "seed": 0,
                "segmentation": "semantic", "distortion": [0.0] * 5, "update_rate": self.rate,
                "ros": [{"stream": stream, "type": types[stream], "topic": topic,
                         "frame_id": self.frame} for stream, topic in self.topics.items()]}

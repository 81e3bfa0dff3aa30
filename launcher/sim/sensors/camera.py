"""Cameras (`camera`, `depth_camera`, `rgbd_camera`, `segmentation_camera`): a MuJoCo camera
at the sensor's site, with Gazebo's optics (`<horizontal_fov>`, `<image>`, `<clip>`, `<lens>`
intrinsics), drawn by a renderer of its own (rendering.py, nodes/renderer.py), never on the
stepping thread. The sim decides when each camera is due, in sim time at its update rate or
when its `<trigger_topic>` says so, and sends the renderer the state to draw; a frame the
renderer is still busy with when the next comes is dropped, and the physics never waits."""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from launcher.sim import schedule
from launcher.sim.sdf.xmltree import SdfError
from launcher.sim.sensors.base import Sensor
from launcher.sim.sensors.metrics import SUFFIX, enabled
from launcher.sim.sensors.noise import noise_of

MAX_SIDE = 8192  # pixels a side
MAX_PIXELS = 16_777_216  # 4096 × 4096: past it one frame would be hundreds of MB
# SDF's <image><format> → the image encoding published (depth cameras give 32FC1 metres)
FORMATS = {"R8G8B8": "rgb8", "RGB_INT8": "rgb8", "B8G8R8": "bgr8", "BGR_INT8": "bgr8",
           "L8": "mono8", "L_INT8": "mono8", "L16": "mono16", "L_INT16": "mono16",
           "R_FLOAT32": "32FC1", "R_FLOAT16": "32FC1"}
# The camera's axes in the sensor frame: Gazebo's looks along +x with +z up, MuJoCo's along
# -z with +y up
_ALIGN = np.zeros(4)
mujoco.mju_mat2Quat(_ALIGN, np.array([[0, 0, -1], [-1, 0, 0], [0, 1, 0]], dtype=float)
                    .reshape(-1))
# <segmentation_type> → how a segmentation camera's labels map is laid out (gz-rendering's)
SEGMENTATION_TYPES = {"semantic": "semantic", "panoptic": "panoptic", "instance": "panoptic"}
COLOUR_STREAMS = ("image", "camera_info")  # what gazebo_ros_camera gives of a plain camera
SUFFIXES = {"camera": ("image",), "depth_camera": ("depth_image",),
            "rgbd_camera": ("image", "depth_image"),
            "segmentation_camera": ("segmentation/labels_map", "segmentation/colored_map")}


class Camera(Sensor):
    message_type = "mujoco_sim/msg/Image"
    suffix = "image"

    def load(self) -> None:
        self.rendering = self.sim_rendering()
        super().load()
        self.rendering.add(self)

    def sim_rendering(self) -> Any:
        from launcher.sim.sensors.rendering import rendering_of

        return rendering_of(self.sim)

    # --- configuration ------------------------------------------------------------------------
    def configure(self) -> None:
        element = self.config.element
        camera = element.find("camera")
        self.width = self._whole(camera, ("image", "width"), 320)
        self.height = self._whole(camera, ("image", "height"), 240)
        if self.width * self.height > MAX_PIXELS:
            raise SdfError(f"{self.label}: {self.width} x {self.height} pixels is more than "
                           f"the {MAX_PIXELS} a frame may hold", element.location)
        written = (camera.path("image", "format").stripped if camera is not None and
                   camera.path("image", "format") is not None else "") or \
            ("R_FLOAT32" if self.config.kind == "depth_camera" else "R8G8B8")
        if written not in FORMATS:
            from launcher.errors import did_you_mean

            raise SdfError(f"{self.label}: unknown image format '{written}'"
                           f"{did_you_mean(written, list(FORMATS))}; launcher writes "
                           f"{', '.join(FORMATS)}", camera.path("image", "format").location)
        self.encoding = FORMATS[written]
        self.hfov = self._number(camera, ("horizontal_fov",), 1.047, 1e-3, math.pi - 1e-3)
        self.near = self._number(camera, ("clip", "near"), 0.1, 1e-6, math.inf)
        self.far = self._number(camera, ("clip", "far"), 100.0, self.near, math.inf)
        self.depth_near = self._number(camera, ("depth_camera", "clip", "near"), self.near,
                                       1e-6, math.inf)
        self.depth_far = self._number(camera, ("depth_camera", "clip", "far"), self.far,
                                      self.depth_near, math.inf)
        fx = self.width / (2 * math.tan(self.hfov / 2))
        intrinsics = camera.path("lens", "intrinsics") if camera is not None else None
        self.fx = self._number(intrinsics, ("fx",), fx, 1e-6, math.inf)
        self.fy = self._number(intrinsics, ("fy",), fx, 1e-6, math.inf)
        self.cx = self._number(intrinsics, ("cx",), self.width / 2, -math.inf, math.inf)
        self.cy = self._number(intrinsics, ("cy",), self.height / 2, -math.inf, math.inf)
        # gz-sensors' image noise: gaussian, per channel, in colour units of 0..1 (depth: metres)
        self.noise = noise_of(camera, self.rng)
        # Brown's distortion (gz-sensors' camera_info order: k1, k2, p1, p2, k3)
        self.distortion = [self._number(camera, ("distortion", tag), 0.0, -math.inf, math.inf)
                           for tag in ("k1", "k2", "p1", "p2", "k3")]
        written = (camera.value("segmentation_type") or "semantic") if camera is not None \
            else "semantic"
        if written.lower() not in SEGMENTATION_TYPES:
            from launcher.errors import did_you_mean

            raise SdfError(f"{self.label}: unknown <segmentation_type> '{written}'"
                           f"{did_you_mean(written, list(SEGMENTATION_TYPES))}; expected "
                           f"{', '.join(SEGMENTATION_TYPES)}",
                           camera.find("segmentation_type").location)
        self.segmentation = SEGMENTATION_TYPES[written.lower()]
        self.triggered = (camera is not None and (camera.value("triggered", "") or "")
                          .strip().lower() in ("true", "1"))
        trigger = camera.value("trigger_topic") if camera is not None else None
        self.trigger_topic = trigger if trigger and trigger.startswith("/") else \
            f"/{trigger}" if trigger else f"{self.topic_name()}/trigger"
        self.pending_trigger = False

    def _number(self, parent: Any, tags: tuple[str, ...], default: float, low: float,
                high: float) -> float:
        element = parent.path(*tags) if parent is not None else None
        if element is None or not element.stripped:
            return default
        try:
            value = float(element.stripped)
        except ValueError:
            value = math.nan
        if not low <= value <= high:
            raise SdfError(f"{self.label}: <{'><'.join(tags)}> must be a number from {low:g} "
                           f"to {high:g}, got '{element.stripped}'", element.location)
        return value

    def _whole(self, parent: Any, tags: tuple[str, ...], default: int) -> int:
        value = self._number(parent, tags, default, -math.inf, math.inf)
        element = parent.path(*tags) if parent is not None else None
        if value != int(value) or not 1 <= value <= MAX_SIDE:
            raise SdfError(f"{self.label}: <{'><'.join(tags)}> must be a whole number of pixels "
                           f"from 1 to {MAX_SIDE}, got '{element.stripped}'",
                           element.location if element is not None else None)
        return int(value)

    # --- the MuJoCo camera ----------------------------------------------------------------------
    @property
    def camera_name(self) -> str:
        return f"{self.entity.name}/{self.config.site}"

    def prepare(self, spec: Any) -> None:
        super().prepare(spec)
        site = spec.site(self.in_spec(self.config.site))
        quat = np.zeros(4)
        mujoco.mju_mulQuat(quat, np.asarray(site.quat, dtype=float), _ALIGN)
        fovy = math.degrees(2 * math.atan(self.height / (2 * self.fy)))
        site.parent.add_camera(name=self.in_spec(self.config.site), pos=list(site.pos),
                               quat=list(quat), fovy=fovy)

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        self.camera = model.camera(self.camera_name).id

    def topics(self) -> dict[str, str]:
        """Each stream this camera publishes, on gz-sensors' topics: a camera's image on its
        topic (default `<scoped>/image`) and camera_info beside it; a depth camera's image on its
        topic (`<scoped>/depth_image`), its points below it; an rgbd or segmentation camera's
        streams below its topic (`<scoped>`, `<scoped>/segmentation`)."""
        kind, given = self.config.kind, self.config.topic
        scoped = self.default_topic()
        if kind in ("camera", "depth_camera"):
            main = self.topic_name() if given else \
                f"{scoped}/{'image' if kind == 'camera' else 'depth_image'}"
            found = {"image" if kind == "camera" else "depth_image": main,
                     "camera_info": f"{main.rsplit('/', 1)[0]}/camera_info"}
            if kind == "depth_camera":
                found["points"] = f"{main}/points"
            return self._with_metrics(found, main)
        base = self.topic_name() if given else \
            (scoped if kind == "rgbd_camera" else f"{scoped}/segmentation")
        streams = ("image", "depth_image", "points") if kind == "rgbd_camera" else \
            ("labels_map", "colored_map")
        return self._with_metrics({**{s: f"{base}/{s}" for s in streams},
                                   "camera_info": f"{base}/camera_info"}, base)

    def _with_metrics(self, streams: dict[str, str], topic: str) -> dict[str, str]:
        """`<camera_info_topic>` where given; `<enable_metrics>`: the renderer publishes
        them below the sensor's topic."""
        camera = self.config.element.find("camera")
        info = camera.value("camera_info_topic") if camera is not None else None
        if info:
            streams["camera_info"] = info if info.startswith("/") else f"/{info}"
        if enabled(self.config.element):
            streams[SUFFIX] = f"{topic}/{SUFFIX}"
        return streams

    def settings(self) -> dict[str, Any]:
        """What the renderer needs of this camera (sent with the model)."""
        return {"camera": self.camera_name, "kind": self.config.kind, "width": self.width,
                "height": self.height, "encoding": self.encoding, "near": self.near,
                "far": self.far, "depth_near": self.depth_near, "depth_far": self.depth_far,
                "k": [self.fx, 0.0, self.cx, 0.0, self.fy, self.cy, 0.0, 0.0, 1.0],
                "frame_id": self.frame_id, "topics": self.topics(),
                "always_on": self.config.always_on, "name": self.scoped_name,
                "noise": [self.noise.mean + self.noise.bias, self.noise.stddev],
                "seed": getattr(self.sim, "seed", 0), "segmentation": self.segmentation,
                "distortion": self.distortion,
                "update_rate": self.config.update_rate,
                "ros": [{"stream": o.stream, "type": o.type_name, "topic": o.topic,
                         "frame_id": o.frame_id} for o in self.ros.outputs
                        if self.config.kind != "camera" or o.stream in COLOUR_STREAMS]}

    # --- scheduling: the sim decides when, the renderer draws -------------------------------
    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        self.rendering.sync(model)  # (a spawn or removal recompiled it: the renderer's too)
        wanted = self.config.always_on or self.rendering.wants(self.camera_name)
        if self.triggered:
            self.next_update = now + 0.01 if not self.pending_trigger else now
            if self.pending_trigger and wanted:
                self.pending_trigger = False
                self.rendering.request([self.camera_name], data)
            return
        if not schedule.serve(self, now, self.period, wanted):
            return
        self.rendering.request([self.camera_name], data)

    def trigger(self, _message: Any) -> None:
        self.pending_trigger = True

    def make_publishers(self) -> None:
        """The sim publishes no image itself (the renderer does); a triggered camera listens
        on its trigger topic."""
        if self.triggered:
            self.trigger_subscription = self.sim.transport.subscribe(
                "mujoco_sim/msg/Boolean", self.trigger_topic, self.trigger)

    def close(self) -> None:
        self.claims.release(self)
        self.rendering.remove(self)
        subscription = getattr(self, "trigger_subscription", None)
        if subscription is not None:
            subscription.destroy()

"""`renderer --world W`: draws a sim's cameras, in a process of its own (sim/sensors/rendering.py).

It takes the world's compiled model and cameras from `/world/W/render/model`, draws each
camera the sim says is due from the state on `/world/W/render/state` (only the latest one:
a state that comes while it draws is dropped, and counted), and publishes Gazebo's streams on
the cameras' topics: images (rgb8, bgr8, mono8, mono16), depth images (32FC1, metres: +inf past
the far clip, -inf before the near one), points, segmentation maps, and camera_info. It says
which cameras anyone watches, and which model version it holds, on `/world/W/render/wanted`,
so the sim sends states for those alone, and sends the model again to a renderer that lacks
it (one whose route to the sim formed after the model's one publication). MuJoCo renders
offscreen (`MUJOCO_GL`, egl unless set): on a GPU where there is one, else in software; the
log names the GL renderer it got.
"""

from __future__ import annotations

import json
import os
import sys
import time
from typing import Any

import numpy as np

from launcher.arguments import Parser
from launcher.bus import keys
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED, QoS
from launcher.bus.wire import image_cdr, split_time
from launcher.errors import reported
from launcher.sim.sensors.metrics import MESSAGE as METRICS
from launcher.sim.sensors.metrics import SUFFIX as METRICS_STREAM
from launcher.sim.sensors.metrics import Metrics
from launcher.sim.sensors.noise import generator
from launcher.sim.sensors.offscreen import Offscreen
from launcher.sim.sensors.pictures import (
    Lens,
    add_noise,
    distort,
    lens,
    segment,
    segmentation_tables,
)

NAME = "renderer"
WANTED_PERIOD = 0.5  # s: the wanted cameras are said again this often (and on each change)
LACKING_GRACE = 1.0  # s: states of a model not here yet are dropped quietly this long


def build_parser() -> Parser:
    parser = Parser(prog="renderer", description="Draw a running sim's cameras.")
    parser.add_argument("--world", required=True, help="the world whose cameras to draw")
    parser.add_argument("--parent", type=int, default=0, metavar="PID",
                        help="stop when this process (the sim that started it) is gone")
    return parser

COLOUR_ENCODINGS = ("rgb8", "bgr8", "mono8", "mono16")  # what a picture may be written as


class Renderer:
    def __init__(self, node: Node, world: str) -> None:
        self.node, self.world = node, world
        self.logger = node.get_logger()
        self.model: Any = None
        self.data: Any = None
        self.version = -1
        self.cameras: dict[str, dict[str, Any]] = {}
        self.geom_label = self.geom_instance = np.zeros(0, dtype=np.int64)
        self.metrics: dict[str, Metrics] = {}  # the cameras with <enable_metrics>
        self.noise: dict[str, Any] = {}  # the generators of the cameras with <noise>
        self.lenses: dict[str, Lens] = {}  # the cameras with a <distortion>
        self.publishers: dict[tuple[str, str], Any] = {}
        self.contexts: dict[tuple[int, int], Any] = {}  # mujoco.Renderers (segmentation)
        self.drawers: dict[tuple[int, int], Offscreen] = {}  # colour and depth
        self.wanted: list[str] = []
        self.drawn = self.dropped = self.sequence = 0
        self.lacking: tuple[int, float] | None = None  # (a model version lacked, since when)
        self.classes: dict[str, type] = {}
        self.wanted_publisher = node.create_publisher(
            "mujoco_sim/msg/StringMsg", f"/world/{world}/render/wanted", space=keys.SIM)
        node.create_subscription("mujoco_sim/msg/RenderModel", f"/world/{world}/render/model",
                                 self.on_model, LATCHED, space=keys.SIM)
        node.create_subscription("mujoco_sim/msg/RenderState", f"/world/{world}/render/state",
                                 self.on_state, QoS(depth=1), space=keys.SIM)
        node.create_timer(WANTED_PERIOD, self.say_wanted)

    # --- the model ---------------------------------------------------------------------------
    def on_model(self, message: Any) -> None:
        import mujoco

        first = self.model is None
        self.model = mujoco.MjModel.from_binary_path(
            "world.mjb", {"world.mjb": bytes(message.model)})
        self.data = mujoco.MjData(self.model)
        self.version = message.version
        cameras = {c["camera"]: c for c in json.loads(message.cameras)}
        for key in [k for k in self.publishers if k[0] not in cameras]:
            self.publishers.pop(key).destroy()
        for name, camera in cameras.items():
            for stream, topic in camera["topics"].items():
                if (name, stream) not in self.publishers:
                    self.publishers[(name, stream)] = self.node.create_publisher(
                        _TYPES.get(stream, "mujoco_sim/msg/Image"), topic,
                        QoS(depth=1, reliable=False), space=keys.SIM)
            for index, output in enumerate(camera.get("ros", ())):  # gazebo_ros_camera's
                if (name, f"ros:{index}") not in self.publishers:
                    self.publishers[(name, f"ros:{index}")] = self.node.create_publisher(
                        output["type"], output["topic"], QoS(depth=1), space=keys.ROS)
        self.cameras = cameras
        self.geom_label, self.geom_instance = segmentation_tables(
            self.model, json.loads(message.labels or "{}"))
        self.lenses = {name: lens(c["width"], c["height"], c["k"], c["distortion"])
                       for name, c in cameras.items() if any(c["distortion"])}
        self.metrics = {name: self.metrics.get(name) or Metrics(c["name"], c["update_rate"])
                        for name, c in cameras.items() if METRICS_STREAM in c["topics"]}
        self.noise = {name: self.noise.get(name) or generator(c["seed"], c["name"])
                      for name, c in cameras.items() if any(c["noise"])}
        self.contexts.clear()  # (they hold the old model)
        for drawer in self.drawers.values():
            drawer.close()
        self.drawers.clear()
        self.say_wanted()
        if first:
            self.prepare()

    def prepare(self) -> None:
        """Make the colour and depth drawers of the first model now, not at its first frame:
        a GL context and MuJoCo's are most of a first picture's cost (about 0.6 s in software
        GL), and the renderer is idle until someone watches. Later models are prepared at
        their first frame, as before, so a world whose cameras nobody watches spends nothing
        on each spawn. A GL that fails here fails again at the first frame, where it is said."""
        try:
            for camera in self.cameras.values():
                if camera["kind"] != "segmentation_camera":
                    self.offscreen(*self.size(camera))
        except Exception as exc:  # (only the head start is lost)
            self.logger.debug(f"drawers not prepared ahead: {exc}")

    def say_wanted(self) -> None:
        wanted = sorted(name for name, camera in self.cameras.items()
                        if camera["always_on"] or any(
                            self.publishers[(name, s)].get_subscription_count() > 0
                            for s in _streams(camera)))
        if wanted != self.wanted:
            self.logger.debug(f"cameras watched: {', '.join(wanted) or 'none'}")
        self.wanted = wanted  # (said again each time: the sim may have started since)
        self.wanted_publisher.publish(self.message(
            "mujoco_sim/msg/StringMsg",
            data=json.dumps({"cameras": wanted, "version": self.version})))

    # --- drawing -------------------------------------------------------------------------------
    def on_state(self, message: Any) -> None:
        import mujoco

        if message.version != self.version or self.model is None:
            self.lacks(message.version)
            return
        self.lacking = None
        if self.sequence and message.sequence > self.sequence + 1:
            self.dropped += message.sequence - self.sequence - 1  # came while we drew
            self.logger.debug(f"{self.dropped} frames dropped so far (drawn: {self.drawn})")
        self.sequence = message.sequence
        model, data = self.model, self.data
        data.qpos[:] = message.qpos
        if model.nmocap:
            data.mocap_pos[:] = np.asarray(message.mocap_pos).reshape(-1, 3)
            data.mocap_quat[:] = np.asarray(message.mocap_quat).reshape(-1, 4)
        mujoco.mj_kinematics(model, data)
        mujoco.mj_camlight(model, data)
        for name in message.cameras:
            camera = self.cameras.get(name)
            if camera is not None:
                self.draw(name, camera, message.time)
        self.drawn += 1

    def lacks(self, version: int) -> None:
        """A state of model `version`, which this renderer does not hold, is dropped: said
        once per pair of versions, when it has lasted LACKING_GRACE (at a start or a spawn
        the model may come just after the first states)."""
        now = time.monotonic()
        if self.lacking is None or self.lacking[0] != version:
            self.lacking = (version, now)
        elif now - self.lacking[1] >= LACKING_GRACE:
            held = "no model" if self.model is None else f"model version {self.version}"
            self.logger.info(f"dropping the states of model version {version}: this renderer "
                             f"holds {held} (it says so to the sim, which sends the model "
                             f"again)", once=True)

    def draw(self, name: str, camera: dict[str, Any], stamp: float) -> None:
        kind, topics = camera["kind"], camera["topics"]
        ros = [(f"ros:{i}", output) for i, output in enumerate(camera.get("ros", ()))
               if camera["always_on"] or self.watched(name, f"ros:{i}")]
        wanted = {output["stream"] for _, output in ros}
        header = self.header(camera, stamp)
        colour = depth = None
        if "image" in topics or wanted & {"image", "points"}:
            colour = self.render(camera, "rgb")
        if "image" in topics:
            self.publish(name, "image", self.image(header, colour, camera["encoding"]
                                                   if kind == "camera" else "rgb8"))
        if "depth_image" in topics or wanted & {"depth_image", "points"}:
            depth = self.render(camera, "depth")
        if "depth_image" in topics:
            self.publish(name, "depth_image", self.image(header, depth, "32FC1"))
        if "points" in topics and depth is not None and self.watched(name, "points"):
            self.publish(name, "points", self.points(header, camera, depth, colour))
        if "labels_map" in topics:
            labels, colours = self.segment(camera, self.render(camera, "segmentation"))
            self.publish(name, "labels_map", self.image(header, labels, "rgb8"))
            self.publish(name, "colored_map", self.image(header, colours, "rgb8"))
        if "camera_info" in topics:
            self.publish(name, "camera_info", self.camera_info(header, camera))
        for key, output in ros:
            self.publish(name, key, self.ros_message(output, camera, stamp, colour, depth))
        if name in self.metrics:
            fields = self.metrics[name].update(stamp, frame=True)
            if self.watched(name, METRICS_STREAM):
                self.publish(name, METRICS_STREAM, self.message(METRICS, **fields))

    def ros_message(self, output: dict[str, Any], camera: dict[str, Any], stamp: float,
                    colour: Any, depth: Any) -> Any:
        """A gazebo_ros_camera stream, in the plugin's frame."""
        header = self.header(camera, stamp, output["frame_id"])
        stream = output["stream"]
        if stream == "image":  # gazebo_ros: the <format> decides, a depth camera's too
            return self.image(header, colour, camera["encoding"] if camera["encoding"] in
                              COLOUR_ENCODINGS else "rgb8")
        if stream == "depth_image":
            return self.image(header, depth, "32FC1")
        if stream == "points":
            return self.optical_points(header, camera, depth, colour)
        return self.camera_info(header, camera)  # camera_info, depth_camera_info

    def render(self, camera: dict[str, Any], what: str) -> Any:
        """The camera's picture: RGB (uint8 H×W×3), depth (float32 metres, ±inf outside the
        clip) or segmentation (int32 H×W×2: each pixel's object id and type). A camera with a
        lens is drawn wider, then seen through it (finish)."""
        found = self.lenses.get(camera["camera"])
        width, height = self.size(camera)
        camera_id = self.model.camera(camera["camera"]).id
        if found:
            nominal, self.model.cam_fovy[camera_id] = \
                float(self.model.cam_fovy[camera_id]), found.fovy
        near, far = (camera["depth_near"], camera["depth_far"]) if what == "depth" else \
            (camera["near"], camera["far"])
        extent = max(float(self.model.stat.extent), 1e-9)
        self.model.vis.map.znear, self.model.vis.map.zfar = near / extent, min(far, 1e9) / extent
        try:
            if what == "segmentation":
                renderer = self.context(width, height)
                renderer.enable_segmentation_rendering()
                try:
                    renderer.update_scene(self.data, camera=camera_id)
                    picture = renderer.render()
                finally:
                    renderer.disable_segmentation_rendering()
            elif what == "depth":
                picture = self.offscreen(width, height).depth(self.data, camera_id)
            else:
                picture = self.offscreen(width, height).colour(self.data, camera_id)
        finally:
            if found:
                self.model.cam_fovy[camera_id] = nominal
        if what == "depth":
            # past the far clip: +inf (gz-sensors'), or the far clip (mujoco_ros2_control's)
            if camera.get("beyond_far") == "far":
                np.minimum(picture, far, out=picture)
            else:
                picture[picture >= far * 0.999] = np.inf
            if picture.min() < near:  # (rare: one pass to look, a second only then)
                picture[picture < near] = -np.inf
            picture = self.finish(camera, picture, 1.0, np.inf)
        elif what == "segmentation":  # (each pixel's object id and type: segment() reads them)
            picture = self.finish(camera, picture, 0.0, -1)
        else:
            picture = self.finish(camera, picture, 255.0, 0)
        return picture

    def size(self, camera: dict[str, Any]) -> tuple[int, int]:
        """The size it is drawn at: its own, or its lens's (wider, seen through it)."""
        found = self.lenses.get(camera["camera"])
        return (found.width, found.height) if found else (camera["width"], camera["height"])

    def segment(self, camera: dict[str, Any], segmentation: Any) -> tuple[Any, Any]:
        return segment(segmentation, self.geom_label, self.geom_instance,
                       camera.get("segmentation") == "panoptic")

    def finish(self, camera: dict[str, Any], picture: Any, unit: float, fill: Any) -> Any:
        """The picture through the camera's lens (`<distortion>`) and with its `<noise>`
        (`unit`: 255 a colour channel, 1 a metre of depth; `fill` where the lens shows
        nothing)."""
        found = self.lenses.get(camera["camera"])
        if found is not None:
            shape = (camera["height"], camera["width"], *picture.shape[2:])
            picture = distort(picture, found, shape, fill)
        rng = self.noise.get(camera["camera"])
        if rng is not None and unit:
            picture = add_noise(picture, rng, *camera["noise"], unit)
        return picture

    def context(self, width: int, height: int) -> Any:
        """A mujoco.Renderer of that size, made once: segmentation maps (its decoding of
        the segmented picture)."""
        import mujoco

        found = self.contexts.get((width, height))
        if found is None:
            self._fit(width, height)
            found = self.contexts[(width, height)] = mujoco.Renderer(self.model, height, width)
        return found

    def offscreen(self, width: int, height: int) -> Offscreen:
        """MuJoCo's renderer on a context of that size, made once: colour and depth."""
        found = self.drawers.get((width, height))
        if found is None:
            self._fit(width, height)
            found = self.drawers[(width, height)] = Offscreen(self.model, width, height)
            if len(self.drawers) == 1:
                self.logger.info(f"drawing the cameras of world '{self.world}' with "
                                 f"{os.environ.get('MUJOCO_GL', 'egl')}: {_gl_renderer()}")
        return found

    def _fit(self, width: int, height: int) -> None:
        self.model.vis.global_.offwidth = max(self.model.vis.global_.offwidth, width)
        self.model.vis.global_.offheight = max(self.model.vis.global_.offheight, height)

    # --- messages ------------------------------------------------------------------------------
    def message(self, type_name: str, **fields: Any) -> Any:
        """A message made straight from its class (byte fields taken as they are)."""
        found = self.classes.get(type_name)
        if found is None:
            from launcher.bus.types import registry

            found = self.classes[type_name] = registry().message_class(type_name)
        return found(**fields)

    def header(self, camera: dict[str, Any], stamp: float, frame_id: str | None = None) -> Any:
        sec, nanosec = split_time(stamp)
        return self.message(
            "std_msgs/msg/Header",
            stamp=self.message("builtin_interfaces/msg/Time", sec=sec, nanosec=nanosec),
            frame_id=camera["frame_id"] if frame_id is None else frame_id)

    def image(self, header: Any, picture: Any, encoding: str) -> Any:
        if encoding == "bgr8":
            picture = picture[..., ::-1]
        elif encoding in ("mono8", "mono16"):
            grey = picture[..., :3] @ np.array([0.299, 0.587, 0.114])
            picture = grey.astype(np.uint8) if encoding == "mono8" else \
                (grey * 257).astype("<u2")
        height, width = picture.shape[:2]
        picture = np.ascontiguousarray(picture)
        return image_cdr(header.stamp.sec, header.stamp.nanosec, header.frame_id, height,
                         width, encoding, picture.strides[0], picture)

    def points(self, header: Any, camera: dict[str, Any], depth: Any, colour: Any) -> Any:
        """The depth image as points in the sensor frame (x ahead, y left, z up), with the
        colour of each where there is one (rgbd)."""
        fx, _, cx, _, fy, cy = camera["k"][:6]
        height, width = depth.shape
        u, v = np.meshgrid(np.arange(width), np.arange(height))
        finite = np.where(np.isfinite(depth), depth, np.nan)
        cloud = np.zeros((height, width, 4), dtype=np.float32)
        cloud[..., 0] = finite
        cloud[..., 1] = -(u - cx) / fx * finite
        cloud[..., 2] = -(v - cy) / fy * finite
        if colour is not None:
            packed = (colour[..., 0].astype(np.uint32) << 16 | colour[..., 1].astype(np.uint32)
                      << 8 | colour[..., 2].astype(np.uint32))
            cloud[..., 3] = packed.view(np.float32)
        names = ("x", "y", "z", "rgb")
        fields = [self.message("sensor_msgs/msg/PointField", name=n, offset=4 * i,
                                    datatype=7, count=1) for i, n in enumerate(names)]
        return self.message(
            "mujoco_sim/msg/PointCloudPacked", header=header, height=height, width=width,
            fields=fields, is_bigendian=False, point_step=16, row_step=16 * width,
            data=cloud.tobytes(), is_dense=False)

    def optical_points(self, header: Any, camera: dict[str, Any], depth: Any,
                       colour: Any) -> Any:
        """gazebo_ros_camera's cloud: every pixel in the optical frame (x right, y down, z
        ahead), ±inf outside the clip, x y z at 0, 4, 8 and rgb at 16 of 32 bytes."""
        fx, _, cx, _, fy, cy = camera["k"][:6]
        height, width = depth.shape
        u, v = np.meshgrid(np.arange(width), np.arange(height))
        cloud = np.zeros((height, width, 8), dtype=np.float32)
        cloud[..., 2] = depth
        with np.errstate(invalid="ignore"):
            cloud[..., 0] = np.where(np.isfinite(depth), (u - cx) / fx * depth, depth)
            cloud[..., 1] = np.where(np.isfinite(depth), (v - cy) / fy * depth, depth)
        if colour is not None:
            packed = (colour[..., 0].astype(np.uint32) << 16 | colour[..., 1].astype(np.uint32)
                      << 8 | colour[..., 2].astype(np.uint32))
            cloud[..., 4] = packed.view(np.float32)
        fields = [self.message("sensor_msgs/msg/PointField", name=n, offset=o, datatype=7,
                               count=1) for n, o in (("x", 0), ("y", 4), ("z", 8), ("rgb", 16))]
        return self.message(
            "sensor_msgs/msg/PointCloud2", header=header, height=height, width=width,
            fields=fields, is_bigendian=False, point_step=32, row_step=32 * width,
            data=cloud.tobytes(), is_dense=bool(np.isfinite(depth).all()))

    def camera_info(self, header: Any, camera: dict[str, Any]) -> Any:
        k = camera["k"]
        roi = self.message("sensor_msgs/msg/RegionOfInterest", x_offset=0, y_offset=0,
                                height=0, width=0, do_rectify=False)
        return self.message(
            "mujoco_sim/msg/CameraInfo", header=header, height=camera["height"],
            width=camera["width"], distortion_model="plumb_bob", d=list(camera["distortion"]),
            k=k,
            r=[1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0],
            p=[k[0], 0.0, k[2], 0.0, 0.0, k[4], k[5], 0.0, 0.0, 0.0, 1.0, 0.0], binning_x=0,
            binning_y=0, roi=roi)

    def watched(self, name: str, stream: str) -> bool:
        return self.publishers[(name, stream)].get_subscription_count() > 0

    def publish(self, name: str, stream: str, message: Any) -> None:
        """A message, or an image already packed as CDR (image())."""
        if isinstance(message, bytearray):
            self.publishers[(name, stream)].publish_raw(message)
        else:
            self.publishers[(name, stream)].publish(message)


def _streams(camera: dict[str, Any]) -> list[str]:
    """The keys of a camera's publishers: its Gazebo streams and its gazebo_ros outputs."""
    return [*camera["topics"], *(f"ros:{i}" for i in range(len(camera.get("ros", ()))))]


_TYPES = {"camera_info": "mujoco_sim/msg/CameraInfo", METRICS_STREAM: METRICS,
          "points": "mujoco_sim/msg/PointCloudPacked"}


def _gl_renderer() -> str:
    try:
        from OpenGL import GL

        return GL.glGetString(GL.GL_RENDERER).decode()
    except Exception as exc:  # the picture still comes: only the name is unknown
        return f"(the GL renderer's name is unknown: {type(exc).__name__})"


def _die_with(parent: int) -> None:
    """End when the sim that started us does (SIGTERM from the kernel)."""
    if not parent:
        return
    try:
        import ctypes
        import signal

        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM, 0, 0, 0)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent:  # it went before we could ask
        sys.exit(0)


def run(argv: list[str]) -> int:
    args = build_parser().parse_args(argv)
    _die_with(args.parent)
    os.environ.setdefault("MUJOCO_GL", "egl")
    node = Node(NAME, argv=[], space=keys.SIM)
    try:
        Renderer(node, args.world)
        node.spin()
    finally:
        node.destroy_node()
    return 0


def main(argv: list[str] | None = None) -> int:
    words = sys.argv[1:] if argv is None else argv
    if "--ros-args" in words:
        words = words[:words.index("--ros-args")]
    return reported(lambda: run(words), NAME)


if __name__ == "__main__":
    sys.exit(main())

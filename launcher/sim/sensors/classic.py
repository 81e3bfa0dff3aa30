"""gazebo_ros's sensor plugins (Gazebo classic's ROS interface) on launcher's sensors.

A `<plugin filename="libgazebo_ros_ray_sensor.so">` (and the camera, imu, gps and bumper ones)
inside a `<sensor>`, in a world or a URDF's `<gazebo reference>` block, publishes that sensor's
readings straight onto the ROS graph, as it does in Gazebo classic (no bridge): in the plugin's
node (named after the plugin, in `<ros><namespace>`, ROS 1's `<robotNamespace>`), on its topics
after `<ros><remapping>from:=to</remapping>` as ROS 2 applies remappings, with the frame id
`<frame_name>` (ROS 1 `<frameName>`) or the sensor's link's name.

- gazebo_ros_ray_sensor (a lidar): `~/out`, a LaserScan, PointCloud, PointCloud2 or Range
  by `<output_type>`; ROS 1's gazebo_ros_laser and gazebo_ros_gpu_laser: a LaserScan on
  `<topicName>`;
- gazebo_ros_camera (and _depth_camera, _openni_kinect, _multicamera): `<camera_name>/image_raw`
  and `/camera_info`, and for a depth camera `/depth/image_raw`, `/depth/camera_info`, `/points`;
- gazebo_ros_imu_sensor: `~/out`, an Imu;
- gazebo_ros_gps_sensor (a navsat): `~/out`, a NavSatFix, and `~/vel`, a Vector3Stamped;
- gazebo_ros_bumper (a contact sensor): `bumper_states`, gazebo_msgs/ContactsState, every
  update, touching or not.

This module reads the plugins into outputs and turns a sensor's reading into each output's
message; the sensors publish them (base.py), the renderer a camera's (nodes/renderer.py).
"""

from __future__ import annotations

import copy
import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from launcher.bus.names import InvalidName
from launcher.errors import did_you_mean
from launcher.sim.plugins.gazebo_ros import RosNode, ros_node

# plugin file stem → (family, the sensor kinds it serves)
PLUGINS = {
    "gazebo_ros_ray_sensor": ("ray", ("lidar",)),
    "gazebo_ros_laser": ("laser", ("lidar",)),
    "gazebo_ros_gpu_laser": ("laser", ("lidar",)),
    **dict.fromkeys(("gazebo_ros_camera", "gazebo_ros_depth_camera", "gazebo_ros_openni_kinect",
                     "gazebo_ros_multicamera"),
                    ("camera", ("camera", "depth_camera", "rgbd_camera"))),
    "gazebo_ros_imu_sensor": ("imu", ("imu",)),
    "gazebo_ros_imu": ("imu", ("imu",)),
    "gazebo_ros_gps_sensor": ("gps", ("navsat",)),
    "gazebo_ros_bumper": ("bumper", ("contact",)),
}
RAY_OUTPUTS = {"sensor_msgs/LaserScan": ("laserscan", "sensor_msgs/msg/LaserScan"),
               "sensor_msgs/PointCloud": ("pointcloud", "sensor_msgs/msg/PointCloud"),
               "sensor_msgs/PointCloud2": ("pointcloud2", "sensor_msgs/msg/PointCloud2"),
               "sensor_msgs/Range": ("range", "sensor_msgs/msg/Range")}
RADIATION = {"ultrasound": 0, "infrared": 1}


@dataclass(frozen=True)
class RosOutput:
    stream: str  # which of the sensor's readings (see CONVERT)
    type_name: str
    topic: str
    frame_id: str
    options: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class _Site:
    """A plugin where it stands: what each family reads its outputs from."""
    plugin: Any  # its element
    node: RosNode
    frame: str
    label: str
    warn: Any
    sensor: Any  # the <sensor> element it is in


def classic_outputs(element: Any, kind: str, link: str, label: str, warn: Any,
                    entity_namespace: str = "") -> list[RosOutput]:
    """The ROS outputs of the gazebo_ros plugins in a `<sensor>` element; a plugin launcher
    does not know, or one for another kind of sensor, is a warning at its line, left out."""
    outputs: list[RosOutput] = []
    for plugin in element.iterfind("plugin"):
        filename = plugin.get("filename", "")
        stem = re.sub(r"^lib|\.so$", "", filename.rsplit("/", 1)[-1])
        found = PLUGINS.get(stem)
        if found is None:
            warn(plugin, f"{label}: plugin '{filename}' is not a sensor plugin launcher runs"
                         f"{did_you_mean(f'lib{stem}.so', [f'lib{p}.so' for p in PLUGINS])} "
                         f"(it runs {', '.join(f'lib{p}.so' for p in PLUGINS)}); it is left "
                         "out")
            continue
        family, kinds = found
        if kind not in kinds:
            warn(plugin, f"{label}: plugin '{filename}' serves {' or '.join(kinds)} sensors, "
                         "not this one; it is left out")
            continue
        node = ros_node(plugin, entity_namespace)
        frame = plugin.value("frame_name") or plugin.value("frameName") or \
            link.rsplit("::", 1)[-1]
        try:
            outputs.extend(_FAMILIES[family](_Site(plugin, node, frame, label, warn,
                                                    element)))
        except InvalidName as exc:
            warn(plugin, f"{label}: plugin '{filename}': {exc}; it is left out")
    return outputs


def _ray(site: _Site) -> list[RosOutput]:
    plugin = site.plugin
    written = plugin.value("output_type") or "sensor_msgs/PointCloud2"
    if written.replace("/msg/", "/") not in RAY_OUTPUTS:
        site.warn(plugin.find("output_type"), f"{site.label}: <output_type> '{written}' is not "
                  f"one of {', '.join(RAY_OUTPUTS)}{did_you_mean(written, list(RAY_OUTPUTS))}; "
                  "the plugin is left out")
        return []
    stream, type_name = RAY_OUTPUTS[written.replace("/msg/", "/")]
    radiation = (plugin.value("radiation_type") or "infrared").strip().lower()
    return [RosOutput(stream, type_name, site.node.topic("~/out"), site.frame, {
        "radiation_type": RADIATION.get(radiation, 1),
        "min_intensity": float(plugin.value("min_intensity") or 0.0)})]


def _laser(site: _Site) -> list[RosOutput]:
    topic = site.plugin.value("topicName") or "scan"
    return [RosOutput("laserscan", "sensor_msgs/msg/LaserScan", site.node.topic(topic),
                      site.frame)]


def _camera(site: _Site) -> list[RosOutput]:
    plugin, frame = site.plugin, site.frame
    name = plugin.value("camera_name") or plugin.value("cameraName") or \
        site.sensor.get("name", "camera")

    def topic(ros1: str, default: str) -> str:
        given = plugin.value(ros1)
        return site.node.topic(given if given else f"{name}/{default}")

    image, info = "sensor_msgs/msg/Image", "sensor_msgs/msg/CameraInfo"
    return [RosOutput("image", image, topic("imageTopicName", "image_raw"), frame),
            RosOutput("camera_info", info, topic("cameraInfoTopicName", "camera_info"), frame),
            RosOutput("depth_image", image, topic("depthImageTopicName", "depth/image_raw"),
                      frame),
            RosOutput("depth_camera_info", info,
                      topic("depthImageCameraInfoTopicName", "depth/camera_info"), frame),
            RosOutput("points", "sensor_msgs/msg/PointCloud2",
                      topic("pointCloudTopicName", "points"), frame)]


def _imu(site: _Site) -> list[RosOutput]:
    topic = site.plugin.value("topicName") or "~/out"
    return [RosOutput("imu", "sensor_msgs/msg/Imu", site.node.topic(topic), site.frame)]


def _gps(site: _Site) -> list[RosOutput]:
    node, frame = site.node, site.frame
    return [RosOutput("navsatfix", "sensor_msgs/msg/NavSatFix", node.topic("~/out"), frame),
            RosOutput("velocity", "geometry_msgs/msg/Vector3Stamped", node.topic("~/vel"),
                      frame)]


def _bumper(site: _Site) -> list[RosOutput]:
    plugin = site.plugin
    topic = plugin.value("bumperTopicName") or "bumper_states"
    world = plugin.value("frame_name") or plugin.value("frameName") or "world"
    return [RosOutput("contacts_state", "gazebo_msgs/msg/ContactsState", site.node.topic(topic),
                      world)]


_FAMILIES = {"ray": _ray, "laser": _laser, "camera": _camera, "imu": _imu, "gps": _gps,
             "bumper": _bumper}


class ClassicOutputs:
    """A sensor's gazebo_ros plugins: the ROS topics they publish, and each reading as they
    publish it (to those someone listens to, or all with `<always_on>`)."""

    def __init__(self, outputs: list[RosOutput]) -> None:
        self.outputs = outputs
        self.publishers: list[tuple[RosOutput, Any]] = []

    def open(self, transport: Any) -> None:
        self.publishers = [(output, transport.publisher(output.type_name, output.topic,
                                                        ros=True))
                           for output in self.outputs]

    def wanted(self) -> bool:
        return any(p.get_subscription_count() > 0 for _, p in self.publishers)

    def publish(self, sensor: Any, reading: Any, data: Any, always: bool) -> None:
        for output, publisher in self.publishers:
            if always or publisher.get_subscription_count() > 0:
                publisher.publish(convert(sensor, output, reading, data))

    def close(self) -> None:
        for _, publisher in self.publishers:
            publisher.destroy()
        self.publishers = []


# --- a reading as each output's message -------------------------------------------------------
def convert(sensor: Any, output: RosOutput, reading: Any, data: Any) -> Any:
    """The message `output` publishes for the sensor's `reading` (a lidar's ranges, the
    others' sim message)."""
    return CONVERT[output.stream](sensor, output, reading, sensor.sim.transport.header(
        data.time, output.frame_id))


def _laserscan(lidar: Any, output: RosOutput, ranges: Any, header: Any) -> Any:
    """The middle row of the scan, as gazebo_ros takes it from a scan of several."""
    count = lidar.horizontal.samples
    start = (lidar.vertical.samples // 2) * count
    row = ranges[start:start + count]
    scan = lidar.scan_message_of(row, ros=True)
    scan.header = header
    return scan


def _points(lidar: Any, output: RosOutput, ranges: Any) -> tuple[Any, Any]:
    hit = np.isfinite(ranges)
    return (lidar.directions[hit] * ranges[hit, None]).astype(np.float32), \
        max(0.0, output.options.get("min_intensity", 0.0))


def _pointcloud2(lidar: Any, output: RosOutput, ranges: Any, header: Any) -> Any:
    """gazebo_ros's: x, y, z, intensity (float32) of the rays that hit, unordered, dense."""
    points, intensity = _points(lidar, output, ranges)
    cloud = np.empty((len(points), 4), dtype=np.float32)
    cloud[:, :3], cloud[:, 3] = points, intensity
    transport = lidar.sim.transport
    fields = [transport.message("sensor_msgs/msg/PointField", name=name, offset=4 * i,
                                datatype=7, count=1)
              for i, name in enumerate(("x", "y", "z", "intensity"))]
    return transport.message(
        "sensor_msgs/msg/PointCloud2", header=header, height=1, width=len(points),
        fields=fields, is_bigendian=False, point_step=16, row_step=16 * len(points),
        data=cloud.tobytes(), is_dense=True)


def _pointcloud(lidar: Any, output: RosOutput, ranges: Any, header: Any) -> Any:
    points, intensity = _points(lidar, output, ranges)
    transport = lidar.sim.transport
    return transport.message(
        "sensor_msgs/msg/PointCloud", header=header,
        points=[transport.message("geometry_msgs/msg/Point32", x=float(x), y=float(y),
                                  z=float(z)) for x, y, z in points],
        channels=[transport.message("sensor_msgs/msg/ChannelFloat32", name="intensity",
                                    values=[intensity] * len(points))])


def _range(lidar: Any, output: RosOutput, ranges: Any, header: Any) -> Any:
    """The nearest of the rays (REP 117: +inf when none hits, -inf when too near)."""
    h, v = lidar.horizontal, lidar.vertical
    return lidar.sim.transport.message(
        "sensor_msgs/msg/Range", header=header,
        radiation_type=output.options.get("radiation_type", 1),
        field_of_view=max(h.max_angle - h.min_angle, v.max_angle - v.min_angle),
        min_range=lidar.range_min, max_range=lidar.max_range_written,
        range=float(np.min(ranges)) if len(ranges) else float("inf"), variance=0.0)


def _restamped(sensor: Any, output: RosOutput, message: Any, header: Any) -> Any:
    """The sim's message, laid out as ROS's, with the plugin's frame."""
    ros = copy.copy(message)
    ros.header = header
    return ros


def _navsatfix(sensor: Any, output: RosOutput, fix: Any, header: Any) -> Any:
    transport = sensor.sim.transport
    horizontal = sensor.noises[("position", "horizontal")].stddev
    vertical = sensor.noises[("position", "vertical")].stddev
    return transport.message(
        "sensor_msgs/msg/NavSatFix", header=header,
        status=transport.message("sensor_msgs/msg/NavSatStatus", status=0, service=1),
        latitude=fix.latitude_deg, longitude=fix.longitude_deg, altitude=fix.altitude,
        position_covariance=[horizontal ** 2, 0.0, 0.0, 0.0, horizontal ** 2, 0.0, 0.0, 0.0,
                             vertical ** 2],
        position_covariance_type=2)  # COVARIANCE_TYPE_DIAGONAL_KNOWN


def _velocity(sensor: Any, output: RosOutput, fix: Any, header: Any) -> Any:
    transport = sensor.sim.transport
    return transport.message("geometry_msgs/msg/Vector3Stamped", header=header,
                             vector=transport.vector(fix.velocity_east, fix.velocity_north,
                                                     fix.velocity_up))


def _contacts_state(sensor: Any, output: RosOutput, contacts: Any, header: Any) -> Any:
    """gazebo_msgs/ContactsState: each pair's forces on its first body, and their sum."""
    transport = sensor.sim.transport
    states = []
    for pair in contacts.contacts:
        wrenches = [w.body_1_wrench for w in pair.wrenches]
        total = [sum(getattr(w.force, a) for w in wrenches) for a in "xyz"]
        states.append(transport.message(
            "gazebo_msgs/msg/ContactState", info="",
            collision1_name=pair.collision1.name, collision2_name=pair.collision2.name,
            wrenches=wrenches, total_wrench=transport.message(
                "geometry_msgs/msg/Wrench", force=transport.vector(*total),
                torque=transport.vector(0.0, 0.0, 0.0)),
            contact_positions=pair.positions, contact_normals=pair.normals,
            depths=pair.depths))
    return transport.message("gazebo_msgs/msg/ContactsState", header=header, states=states)


CONVERT = {"laserscan": _laserscan, "pointcloud2": _pointcloud2, "pointcloud": _pointcloud,
           "range": _range, "imu": _restamped, "navsatfix": _navsatfix,
           "velocity": _velocity, "contacts_state": _contacts_state}

"""Conversions between the sim's native messages and ROS 2 messages, on CDR payloads.

`gz.msgs.Name` (and `mujoco_sim/msg/Name`) name the sim's types (`gz.msgs.Pose_V` is
`mujoco_sim/msg/PoseV`). Where both sides have the same layout (Twist, Float64/Double, Bool,
Int32, String, Empty) the bytes pass through untouched; Clock is a prefix of the sim's Clock;
the others are decoded, rebuilt and encoded.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

from launcher.bus import messages
from launcher.bus.types import registry
from launcher.errors import LaunchError, did_you_mean

SIM = "mujoco_sim"
SIM_MESSAGES = ("Clock", "Twist", "Odometry", "Pose", "PoseV", "Model", "ModelStates",
                "Double", "Float", "Boolean", "Int32", "StringMsg", "Empty", "EntityFactory",
                "WorldControl", "Entity", "IMU", "Magnetometer", "FluidPressure", "Altimeter",
                "NavSat", "LaserScan", "PointCloudPacked", "Image", "CameraInfo", "Wrench",
                "Contacts", "AirSpeedSensor", "PerformanceSensorMetrics", "BatteryState",
                "JointTrajectory")
# (request, response) of Gazebo's services → the sim's service type
SIM_SERVICES = {("WorldControl", "Boolean"): f"{SIM}/srv/Control",
                ("EntityFactory", "Boolean"): f"{SIM}/srv/Create",
                ("Entity", "Boolean"): f"{SIM}/srv/Remove",
                ("Pose", "Boolean"): f"{SIM}/srv/SetPose"}

Convert = Callable[[bytes], bytes]
Build = Callable[[Any], dict[str, Any]]  # a message read as objects → the other's fields


def gz_short_name(name: str) -> str:
    name = name.strip()
    for prefix in ("gz.msgs.", "ignition.msgs.", f"{SIM}/msg/", f"{SIM}/"):
        if name.startswith(prefix):
            name = name[len(prefix):]
            break
    else:
        return ""
    return "PoseV" if name == "Pose_V" else name


def sim_type(name: str) -> str:
    """The sim's type for a `gz.msgs.*` name; `REQ|REP` names a service."""
    if "|" in name:
        request, response = (gz_short_name(part) for part in name.split("|", 1))
        if not response:  # the command-line form names the request only
            response = "Boolean"
        found = SIM_SERVICES.get((request, response))
        if found is None:
            known = ", ".join(f"gz.msgs.{a} -> gz.msgs.{b}" for a, b in SIM_SERVICES)
            raise LaunchError(f"the sim has no service taking '{name.split('|')[0]}' and "
                              f"answering '{name.split('|')[1] or 'gz.msgs.Boolean'}' "
                              f"(services: {known})")
        return found
    short = gz_short_name(name)
    if short not in SIM_MESSAGES:
        raise LaunchError(f"unknown sim type '{name}'"
                          f"{did_you_mean(name, [f'gz.msgs.{m}' for m in SIM_MESSAGES])}"
                          f" (sim types: gz.msgs.{', gz.msgs.'.join(SIM_MESSAGES)})")
    return f"{SIM}/msg/{short}"


@dataclass(frozen=True)
class Conversion:
    to_ros: Convert | None  # sim payload → ROS payload
    to_sim: Convert | None


def _same(payload: bytes) -> bytes:
    return payload


def _via(source: str, target: str, build: Callable[[Any], dict[str, Any]]) -> Convert:
    """Read `source` as plain objects, `build` the target's fields, write them: no message
    classes (rosbags' would import numpy for arrays at the first message)."""
    made: list[Callable[..., Any]] = []  # reader and writer, made at the first use

    def convert(payload: bytes) -> bytes:
        if not made:
            made[:] = registry().reader(source, _plain), registry().writer(target)
        read, write = made
        return write(messages.build(target, build(read(payload)), plain=True))

    return convert


_names: dict[str, tuple[str, ...]] = {}


def _plain(type_name: str, values: list[Any]) -> SimpleNamespace:
    """A message read as an object with its fields (the CDR reader's `make`)."""
    names = _names.get(type_name)
    if names is None:
        names = _names[type_name] = tuple(f for f, _ in registry().fields(type_name))
    return SimpleNamespace(**dict(zip(names, values, strict=True)))


def _pose(p: Any) -> dict[str, Any]:
    return {"position": {"x": p.position.x, "y": p.position.y, "z": p.position.z},
            "orientation": {"x": p.orientation.x, "y": p.orientation.y,
                            "z": p.orientation.z, "w": p.orientation.w}}


def _twist(t: Any) -> dict[str, Any]:
    return {"linear": {"x": t.linear.x, "y": t.linear.y, "z": t.linear.z},
            "angular": {"x": t.angular.x, "y": t.angular.y, "z": t.angular.z}}


def _wrench(w: Any) -> dict[str, Any]:
    return {"force": {"x": w.force.x, "y": w.force.y, "z": w.force.z},
            "torque": {"x": w.torque.x, "y": w.torque.y, "z": w.torque.z}}


def _header(h: Any) -> dict[str, Any]:
    return {"stamp": {"sec": h.stamp.sec, "nanosec": h.stamp.nanosec}, "frame_id": h.frame_id}


def _odometry_to_ros(m: Any) -> dict[str, Any]:
    return {"header": _header(m.header), "child_frame_id": m.child_frame_id,
            "pose": {"pose": _pose(m.pose)}, "twist": {"twist": _twist(m.twist)}}


def _odometry_to_sim(m: Any) -> dict[str, Any]:
    return {"header": _header(m.header), "child_frame_id": m.child_frame_id,
            "pose": _pose(m.pose.pose), "twist": _twist(m.twist.twist)}


def _tf(m: Any) -> dict[str, Any]:
    return {"transforms": [
        {"header": {"stamp": _header(m.header)["stamp"], "frame_id": parent},
         "child_frame_id": name,
         "transform": {"translation": _pose(pose)["position"],
                       "rotation": _pose(pose)["orientation"]}}
        for name, parent, pose in zip(m.name, m.parent, m.pose, strict=False)]}


def _scan_to_ros(s: Any) -> dict[str, Any]:
    """ros_gz_bridge's: of several rows, the middle one (the point cloud keeps them all);
    no time_increment or scan_time (gz.msgs.LaserScan has neither)."""
    count = s.count or len(s.ranges)
    start = (s.vertical_count // 2) * count
    return {"header": _header(s.header), "angle_min": s.angle_min, "angle_max": s.angle_max,
            "angle_increment": s.angle_increment, "time_increment": 0.0, "scan_time": 0.0,
            "range_min": s.range_min, "range_max": s.range_max,
            "ranges": s.ranges[start:start + count],
            "intensities": s.intensities[start:start + count]}


def _scan_to_sim(s: Any) -> dict[str, Any]:
    """A ROS scan for the sim: one row of all its ranges (ros_gz_bridge counts the rays from
    the angles, and drops the last: here every ray is kept)."""
    return {"header": _header(s.header), "angle_min": s.angle_min, "angle_max": s.angle_max,
            "angle_increment": s.angle_increment, "time_increment": s.time_increment,
            "scan_time": s.scan_time, "range_min": s.range_min, "range_max": s.range_max,
            "ranges": s.ranges, "intensities": s.intensities, "count": len(s.ranges),
            "vertical_angle_min": 0.0, "vertical_angle_max": 0.0, "vertical_angle_step": 0.0,
            "vertical_count": 0}


def _joint_state(m: Any) -> dict[str, Any]:
    return {"header": _header(m.header), "name": list(m.joint_name), "position": m.position,
            "velocity": m.velocity, "effort": m.effort}


def _pose_offset(payload: bytes) -> int:
    """Where an Odometry's pose starts: after the stamp, frame_id and child_frame_id."""
    position = 4 + 8
    for _ in range(2):
        position += -(position - 4) % 4
        position += 4 + int.from_bytes(payload[position:position + 4], "little")
    return position + -(position - 4) % 8


_COVARIANCE = bytes(36 * 8)


def _odometry_bytes_to_ros(payload: bytes) -> bytes:
    """The sim's Odometry → nav_msgs: the same bytes with zero covariances inserted."""
    if payload[1] != 1:  # big-endian: the general path
        return _odometry_objects_to_ros(payload)
    at = _pose_offset(payload)
    return payload[:at + 56] + _COVARIANCE + payload[at + 56:at + 104] + _COVARIANCE


def _odometry_bytes_to_sim(payload: bytes) -> bytes:
    if payload[1] != 1:
        return _odometry_objects_to_sim(payload)
    at = _pose_offset(payload)
    return payload[:at + 56] + payload[at + 344:at + 392]


def _clock(payload: bytes) -> bytes:
    return payload[:12]  # the CDR header and the first field, `sim`: rosgraph's `clock`


def _clock_to_sim(payload: bytes) -> bytes:
    return payload[:12] + bytes(24)


def _odometry_objects_to_ros(payload: bytes) -> bytes:
    return _via(f"{SIM}/msg/Odometry", "nav_msgs/msg/Odometry", _odometry_to_ros)(payload)


def _odometry_objects_to_sim(payload: bytes) -> bytes:
    return _via("nav_msgs/msg/Odometry", f"{SIM}/msg/Odometry", _odometry_to_sim)(payload)


def _nav_sat_fix(n: Any) -> dict[str, Any]:
    """gz.msgs.NavSat as ros_gz_bridge writes NavSatFix: a fix from GPS, its covariance
    unknown."""
    return {"header": _header(n.header),
            "status": {"status": 0, "service": 1},  # STATUS_FIX, SERVICE_GPS
            "latitude": n.latitude_deg, "longitude": n.longitude_deg, "altitude": n.altitude,
            "position_covariance": [0.0] * 9, "position_covariance_type": 0}


def _gps_fix(n: Any) -> dict[str, Any]:
    """gz.msgs.NavSat as ros_gz_bridge writes gps_msgs/GPSFix: speed over ground, track and
    climb from the east-north-up velocity, a ground-based augmented fix, covariance unknown.
    The track is as GPSFix defines it, degrees clockwise from north, where ros_gz_bridge
    writes atan2(north, east) in radians."""
    return {"header": _header(n.header), "status": {"status": 2},  # STATUS_GBAS_FIX
            "latitude": n.latitude_deg, "longitude": n.longitude_deg, "altitude": n.altitude,
            "speed": math.hypot(n.velocity_east, n.velocity_north),
            "track": math.degrees(math.atan2(n.velocity_east, n.velocity_north)) % 360.0,
            "climb": n.velocity_up, "position_covariance": [0.0] * 9,
            "position_covariance_type": 0}


def _nav_sat_of_fix(f: Any) -> dict[str, Any]:
    return {"header": _header(f.header), "latitude_deg": f.latitude,
            "longitude_deg": f.longitude, "altitude": f.altitude}


def _nav_sat_of_gps_fix(g: Any) -> dict[str, Any]:
    track = math.radians(g.track)
    return {"header": _header(g.header), "latitude_deg": g.latitude,
            "longitude_deg": g.longitude, "altitude": g.altitude,
            "velocity_east": math.sin(track) * g.speed,
            "velocity_north": math.cos(track) * g.speed, "velocity_up": g.climb}


def _stamped_pose(p: Any) -> dict[str, Any]:
    return {"header": _header(p.header), "pose": _pose(p.pose)}


# (ROS type, the sim's type's short name) → how one becomes the other: on the bytes (a
# Conversion; _SAME: the layouts are the same, the bytes pass through), or through plain
# objects, (to ROS, to the sim) each building the other's fields (None: one way only)
_SAME = Conversion(_same, _same)
_TABLE: dict[tuple[str, str], Conversion | tuple[Build, Build | None]] = {
    ("rosgraph_msgs/msg/Clock", "Clock"): Conversion(_clock, _clock_to_sim),
    ("geometry_msgs/msg/Twist", "Twist"): _SAME,
    ("geometry_msgs/msg/TwistStamped", "Twist"): (lambda t: {"twist": _twist(t)},
                                                  lambda t: _twist(t.twist)),
    ("nav_msgs/msg/Odometry", "Odometry"): Conversion(_odometry_bytes_to_ros,
                                                      _odometry_bytes_to_sim),
    ("tf2_msgs/msg/TFMessage", "PoseV"): (_tf, None),
    ("sensor_msgs/msg/JointState", "Model"): (_joint_state, None),
    ("geometry_msgs/msg/Pose", "Pose"): (lambda p: _pose(p.pose), lambda p: {"pose": _pose(p)}),
    ("geometry_msgs/msg/PoseStamped", "Pose"): (_stamped_pose, _stamped_pose),
    ("std_msgs/msg/Float64", "Double"): _SAME,
    ("std_msgs/msg/Float32", "Float"): _SAME,
    ("std_msgs/msg/Bool", "Boolean"): _SAME,
    ("std_msgs/msg/Int32", "Int32"): _SAME,
    ("std_msgs/msg/String", "StringMsg"): _SAME,
    ("std_msgs/msg/Empty", "Empty"): _SAME,
    # sensors
    ("sensor_msgs/msg/Imu", "IMU"): _SAME,
    ("sensor_msgs/msg/MagneticField", "Magnetometer"): _SAME,
    ("sensor_msgs/msg/FluidPressure", "FluidPressure"): _SAME,
    ("sensor_msgs/msg/BatteryState", "BatteryState"): _SAME,
    ("trajectory_msgs/msg/JointTrajectory", "JointTrajectory"): _SAME,
    ("sensor_msgs/msg/LaserScan", "LaserScan"): (_scan_to_ros, _scan_to_sim),
    ("sensor_msgs/msg/PointCloud2", "PointCloudPacked"): _SAME,
    ("sensor_msgs/msg/Image", "Image"): _SAME,
    ("sensor_msgs/msg/CameraInfo", "CameraInfo"): _SAME,
    ("ros_gz_interfaces/msg/Altimeter", "Altimeter"): _SAME,
    ("ros_gz_interfaces/msg/Contacts", "Contacts"): _SAME,
    ("ros_gz_interfaces/msg/AirSpeed", "AirSpeedSensor"): _SAME,
    ("geometry_msgs/msg/WrenchStamped", "Wrench"): _SAME,
    ("geometry_msgs/msg/Wrench", "Wrench"): (lambda w: _wrench(w.wrench),
                                             lambda w: {"wrench": _wrench(w)}),
    ("sensor_msgs/msg/NavSatFix", "NavSat"): (_nav_sat_fix, _nav_sat_of_fix),
    ("gps_msgs/msg/GPSFix", "NavSat"): (_gps_fix, _nav_sat_of_gps_fix),
}


def conversions() -> dict[tuple[str, str], Conversion]:
    """(ROS type, the sim's type) → its Conversion, for each pair the bridge converts."""
    found = {}
    for (ros, short), way in _TABLE.items():
        sim = f"{SIM}/msg/{short}"
        if not isinstance(way, Conversion):
            to_ros, to_sim = way
            way = Conversion(_via(sim, ros, to_ros),
                             None if to_sim is None else _via(ros, sim, to_sim))
        found[(ros, sim)] = way
    return found


def known_ros_type(name: str) -> str:
    """A ROS message type the bus knows, by its full name; an unknown one is an error with
    "did you mean"."""
    from launcher.bus.types import normalize

    return registry().ensure(normalize(name))


def find(ros_type: str, sim: str) -> Conversion:
    """The conversion for a pair; an unknown ROS type or an unsupported pair is an error."""
    from launcher.bus.types import normalize

    ros_type = registry().ensure(normalize(ros_type))  # unknown types fail here
    table = conversions()
    found = table.get((ros_type, sim))
    if found is not None:
        return found
    supported = [f"gz.msgs.{s.rsplit('/', 1)[1]}" for r, s in table if r == ros_type]
    if supported:
        raise LaunchError(f"no conversion between {ros_type} and gz.msgs."
                          f"{sim.rsplit('/', 1)[1]}; {ros_type} pairs with: "
                          f"{', '.join(supported)}")
    raise LaunchError(f"the bridge does not convert {ros_type}; it converts: "
                      f"{', '.join(sorted({r for r, _ in table}))}")


@dataclass(frozen=True)
class ServiceConversion:
    """ROS request → the sim's request fields; the sim's response → ROS response fields."""
    request: Callable[[Any], dict[str, Any]]
    response: Callable[[Any], dict[str, Any]]


def _control(r: Any) -> dict[str, Any]:
    c = r.world_control
    return {"pause": c.pause, "step": c.step, "multi_step": c.multi_step,
            "reset_all": c.reset.all, "reset_time_only": c.reset.time_only,
            "reset_model_only": c.reset.model_only}


def _spawn(r: Any) -> dict[str, Any]:
    f = r.entity_factory
    return {"name": f.name, "allow_renaming": f.allow_renaming, "sdf": f.sdf,
            "sdf_filename": f.sdf_filename, "pose": _pose(f.pose), "relative_to": f.relative_to}


def _success(response: Any) -> dict[str, Any]:
    return {"success": response.success}


SERVICES = {
    ("ros_gz_interfaces/srv/ControlWorld", f"{SIM}/srv/Control"):
        ServiceConversion(_control, _success),
    ("ros_gz_interfaces/srv/SpawnEntity", f"{SIM}/srv/Create"):
        ServiceConversion(_spawn, _success),
    ("ros_gz_interfaces/srv/DeleteEntity", f"{SIM}/srv/Remove"):
        ServiceConversion(lambda r: {"name": r.entity.name}, _success),
    ("ros_gz_interfaces/srv/SetEntityPose", f"{SIM}/srv/SetPose"):
        ServiceConversion(lambda r: {"name": r.entity.name, "pose": _pose(r.pose)}, _success),
}


def find_service(ros_type: str, sim_service: str) -> ServiceConversion:
    from launcher.bus.types import normalize

    ros_type = normalize(ros_type)
    registry().service(ros_type)  # an unknown service type fails here, with suggestions
    found = SERVICES.get((ros_type, sim_service))
    if found is None:
        pairs = ", ".join(f"{r} -> {s}" for r, s in SERVICES)
        raise LaunchError(f"no conversion between {ros_type} and {sim_service} (services: "
                          f"{pairs})")
    return found

"""Gazebo's message shapes (gz.msgs.*) over the sim's own types, for the `gz` command.

The sim's types carry the same data in ROS-like layouts (`mujoco_sim/msg/Pose` has a
`pose {position, orientation}` where gz.msgs.Pose has them at the top; times have `nanosec`
where Gazebo has `nsec`). `to_sim` turns what a user typed in Gazebo's text format into the
sim's fields; `to_gz` turns a received message into what Gazebo would print.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.sim.prototext import Enum

Data = dict[str, Any]
# gz.msgs.BatteryState.PowerSupplyStatus, the same numbers as sensor_msgs/BatteryState's
BATTERY_STATUS = {0: "UNKNOWN", 1: "CHARGING", 2: "DISCHARGING", 3: "NOT_CHARGING", 4: "FULL"}


def _rename(data: Any, old: str, new: str) -> Any:
    """`data` with every field called `old`, at any depth, called `new` (times' nanoseconds)."""
    if isinstance(data, dict):
        return {(new if k == old else k): _rename(v, old, new) for k, v in data.items()}
    if isinstance(data, list):
        return [_rename(v, old, new) for v in data]
    return data


def _header_to_gz(header: Data | None, *frames: tuple[str, str]) -> Data:
    header = header or {}
    out: Data = {"stamp": header.get("stamp", {})}
    data = [{"key": key, "value": [value]} for key, value in frames if value]
    if header.get("frame_id"):
        data.insert(0, {"key": "frame_id", "value": [header["frame_id"]]})
    if data:
        out["data"] = data
    return out


def _pose_to_sim(data: Data) -> Data:
    """gz.msgs.Pose fields (position, orientation at the top) → geometry_msgs/Pose."""
    return {k: data[k] for k in ("position", "orientation") if k in data}


def _pose_v_to_gz(data: Data) -> Data:
    poses = [{"name": n, **p} for n, p in zip(data.get("name", []), data.get("pose", []),
                                                strict=False)]
    return {"header": _header_to_gz(data.get("header")), "pose": poses}


def _model_to_gz(data: Data) -> Data:
    joints = [{"name": n, "axis1": {"position": p, "velocity": v, "force": f}}
              for n, p, v, f in zip(data.get("joint_name", []), data.get("position", []),
                                    data.get("velocity", []), data.get("effort", []),
                                    strict=False)]
    return {"header": _header_to_gz(data.get("header")), "name": data.get("name", ""),
            "joint": joints}


def _laser_scan_to_gz(d: Data) -> Data:
    """A scan as gz.msgs.LaserScan: its frame, angle step where ROS has an increment, `count`
    rays a row and the vertical rows' count and angles (a sensor_msgs one: a single row)."""
    header = d.get("header") or {}
    ranges = d.get("ranges") or []
    return {"header": _header_to_gz(header), "frame": header.get("frame_id", ""),
            "angle_min": d.get("angle_min", 0.0), "angle_max": d.get("angle_max", 0.0),
            "angle_step": d.get("angle_increment", 0.0), "range_min": d.get("range_min", 0.0),
            "range_max": d.get("range_max", 0.0), "count": d.get("count") or len(ranges),
            **{k: d.get(k, 0) for k in ("vertical_angle_min", "vertical_angle_max",
                                        "vertical_angle_step", "vertical_count")},
            "ranges": list(ranges), "intensities": list(d.get("intensities") or [])}


def _point_cloud_to_gz(d: Data) -> Data:
    fields = [{"name": f.get("name"), "offset": f.get("offset"),
               "datatype": Enum(_POINT_TYPES.get(f.get("datatype"), str(f.get("datatype")))),
               "count": f.get("count")} for f in d.get("fields") or []]
    return {"header": _header_to_gz(d.get("header")), "field": fields,
            **{k: d.get(k) for k in ("height", "width", "is_bigendian", "point_step",
                                     "row_step", "is_dense")},
            "data": bytes(d.get("data") or b"")}


_PIXEL_FORMATS = {"rgb8": "RGB_INT8", "bgr8": "BGR_INT8", "mono8": "L_INT8",
                  "mono16": "L_INT16", "32FC1": "R_FLOAT32"}


def _image_to_gz(d: Data) -> Data:
    return {"header": _header_to_gz(d.get("header")), "width": d.get("width", 0),
            "height": d.get("height", 0),
            "pixel_format_type": Enum(_PIXEL_FORMATS.get(d.get("encoding", ""),
                                                          "UNKNOWN_PIXEL_FORMAT")),
            "step": d.get("step", 0), "data": bytes(d.get("data") or b"")}


def _camera_info_to_gz(d: Data) -> Data:
    return {"header": _header_to_gz(d.get("header")), "width": d.get("width", 0),
            "height": d.get("height", 0),
            "distortion": {"model": Enum("PLUMB_BOB"), "k": list(d.get("d") or [])},
            "intrinsics": {"k": list(d.get("k") or [])},
            "projection": {"p": list(d.get("p") or [])},
            "rectification_matrix": list(d.get("r") or [])}


def _contact_to_gz(c: Data) -> Data:
    """One touching pair as gz.msgs.Contact: its entities by name and id, and per point the
    position, normal, depth and the wrench on each body."""
    def entity(e: Data | None) -> Data:
        return {"name": (e or {}).get("name", ""), "id": (e or {}).get("id", 0)}

    def wrench(w: Data) -> Data:
        return {"body_1_name": (w.get("body_1_name") or {}).get("data", ""),
                "body_1_id": (w.get("body_1_id") or {}).get("data", 0),
                "body_2_name": (w.get("body_2_name") or {}).get("data", ""),
                "body_2_id": (w.get("body_2_id") or {}).get("data", 0),
                "body_1_wrench": w.get("body_1_wrench", {}),
                "body_2_wrench": w.get("body_2_wrench", {})}

    return {"collision1": entity(c.get("collision1")), "collision2": entity(c.get("collision2")),
            "position": list(c.get("positions") or []), "normal": list(c.get("normals") or []),
            "depth": list(c.get("depths") or []),
            "wrench": [wrench(w) for w in c.get("wrenches") or []]}


_POINT_TYPES = {1: "INT8", 2: "UINT8", 3: "INT16", 4: "UINT16", 5: "INT32", 6: "UINT32",
                7: "FLOAT32", 8: "FLOAT64"}


TO_GZ: dict[str, Callable[[Data], Data]] = {
    "Pose": lambda d: {"header": _header_to_gz(d.get("header")), "name": d.get("name", ""),
                       **(d.get("pose") or {})},
    "PoseV": _pose_v_to_gz,
    "Odometry": lambda d: {"header": _header_to_gz(d.get("header"),
                                                   ("child_frame_id", d.get("child_frame_id"))),
                           "pose": d.get("pose", {}), "twist": d.get("twist", {})},
    "Clock": lambda d: {"real": d.get("real", {}), "sim": d.get("sim", {})},
    "Model": _model_to_gz,
    "IMU": lambda d: {"header": _header_to_gz(d.get("header")),
                      "entity_name": (d.get("header") or {}).get("frame_id", ""),
                      **{k: d.get(k, {}) for k in ("orientation", "angular_velocity",
                                                   "linear_acceleration")}},
    "Magnetometer": lambda d: {"header": _header_to_gz(d.get("header")),
                               "field_tesla": d.get("magnetic_field", {})},
    "FluidPressure": lambda d: {"header": _header_to_gz(d.get("header")),
                                "pressure": d.get("fluid_pressure", 0.0),
                                "variance": d.get("variance", 0.0)},
    "BatteryState": lambda d: {"header": _header_to_gz(d.get("header")),
                               **{k: d.get(k, 0) for k in ("voltage", "current", "charge",
                                                           "capacity", "percentage")},
                               "power_supply_status": Enum(BATTERY_STATUS.get(
                                   d.get("power_supply_status", 0), "UNKNOWN"))},
    "NavSat": lambda d: {"header": _header_to_gz(d.get("header")),
                         **{k: v for k, v in d.items() if k != "header"},
                         "frame_id": (d.get("header") or {}).get("frame_id", "")},
    "LaserScan": _laser_scan_to_gz,
    "PointCloudPacked": _point_cloud_to_gz,
    "Image": _image_to_gz,
    "CameraInfo": _camera_info_to_gz,
    "Wrench": lambda d: {"header": _header_to_gz(d.get("header")),
                         **(d.get("wrench") or {})},
    "Contacts": lambda d: {"header": _header_to_gz(d.get("header")),
                           "contact": [_contact_to_gz(c) for c in d.get("contacts") or []]},
    "AirSpeedSensor": lambda d: {"header": _header_to_gz(d.get("header")),
                                 "diff_pressure": d.get("diff_pressure", 0.0),
                                 "temperature": d.get("temperature", 0.0)},
    "PerformanceSensorMetrics": lambda d: {
        **{k: v for k, v in d.items() if k != "fps"},
        **({"fps_optional": {"data": d["fps"]}} if d.get("fps") else {})},
}

TO_SIM: dict[str, Callable[[Data], Data]] = {
    "Pose": lambda d: {"name": d.get("name", ""), "pose": _pose_to_sim(d)},
    "WorldControl": lambda d: {
        **{k: d[k] for k in ("pause", "step", "multi_step") if k in d},
        **{f"reset_{k}": v for k, v in (d.get("reset") or {}).items()}},
    "EntityFactory": lambda d: {**{k: v for k, v in d.items() if k != "pose"},
                                **({"pose": _pose_to_sim(d["pose"])} if "pose" in d else {})},
    "Entity": lambda d: {k: v for k, v in d.items() if k in ("name", "id")},
}
# fields Gazebo's messages have that the sim's types leave out (ignored, not errors)
IGNORED = {"Pose": {"id", "header"}, "WorldControl": {"seed", "run_to_sim_time"},
           "Entity": {"type"}, "EntityFactory": {"model", "light", "clone_name"},
           "Twist": {"header"}}


def to_gz(short: str, data: Data) -> Data:
    convert = TO_GZ.get(short)
    return _rename(convert(data) if convert else data, "nanosec", "nsec")


def to_sim(short: str, data: Data) -> Data:
    data = {k: v for k, v in data.items() if k not in IGNORED.get(short, ())}
    convert = TO_SIM.get(short)
    return _rename(convert(data) if convert else data, "nsec", "nanosec")


def reply_to_gz(short: str, response: Data) -> Data:
    """A sim service's response as Gazebo's reply type (gz.msgs.Boolean: `data`)."""
    if short == "Boolean":
        return {"data": bool(response.get("success"))}
    return response

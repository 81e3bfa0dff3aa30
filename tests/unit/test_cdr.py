"""launcher's CDR reader and writer (launcher/bus/cdr.py) against rosbags' (the reference):
the same bytes for every type of the pinned distro, and malformed payloads refused."""

from __future__ import annotations

import struct

import pytest
from rosbags.typesys.stores import ros2_jazzy

from launcher.bus.messages import build
from launcher.bus.types import registry


@pytest.mark.parametrize("name", sorted(ros2_jazzy.FIELDDEFS))
def test_every_distro_type_writes_what_rosbags_writes_and_reads_back(name):
    types = registry()
    message = build(name, {})
    reference = bytes(types.store.serialize_cdr(message, name))
    assert types.serialize(message, name) == reference
    back = types.deserialize(reference, name)
    assert bytes(types.store.serialize_cdr(back, name)) == reference


def test_values_strings_and_arrays_round_trip():
    types = registry()
    name = "sensor_msgs/msg/JointState"
    message = build(name, {"header": {"frame_id": "base", "stamp": {"sec": 5, "nanosec": 7}},
                           "name": ["left", "right_wheel"], "position": [1.5, -2.25],
                           "velocity": [3.0], "effort": []})
    data = types.serialize(message, name)
    assert data == bytes(types.store.serialize_cdr(message, name))
    back = types.deserialize(data, name)
    assert back.name == ["left", "right_wheel"] and back.position.tolist() == [1.5, -2.25]
    assert back.header.frame_id == "base" and back.header.stamp.nanosec == 7


def test_malformed_payloads_are_refused_without_allocating():
    types = registry()
    name = "sensor_msgs/msg/JointState"
    data = types.serialize(build(name, {"name": ["a"]}), name)
    with pytest.raises(ValueError, match="malformed sensor_msgs/msg/JointState"):
        types.deserialize(data[:-6], name)
    hostile = bytearray(types.serialize(build("std_msgs/msg/String", {"data": "x"}),
                                        "std_msgs/msg/String"))
    hostile[4:8] = struct.pack("<I", 2**31)  # a string "of 2 GiB"
    with pytest.raises(ValueError, match="malformed std_msgs/msg/String"):
        types.deserialize(bytes(hostile), "std_msgs/msg/String")
    names = bytearray(data)
    names[4 + 16:4 + 20] = struct.pack("<I", 2**30)  # after the header: the name count
    with pytest.raises(ValueError, match="malformed"):
        types.deserialize(bytes(names), name)


def test_a_wstring_field_is_refused_with_the_reason():
    from rosbags.interfaces import Nodetype

    from launcher.bus.cdr import Codec, Unsupported

    codec = Codec(lambda name: [("text", (Nodetype.BASE, ("wstring", 0)))])
    with pytest.raises(Unsupported, match="wstring fields are not supported"):
        codec.serialize(object(), "x/msg/Wide")


@pytest.mark.parametrize("frame", ["", "a", "ab", "abc", "abcd", "abcde", "abcdef", "abcdefg"])
def test_runs_of_fixed_fields_are_padded_from_wherever_a_string_left_them(frame):
    """After a string of each length mod 8, the runs (orientation, covariances, vectors) start
    at every alignment; the bytes and the values read back are rosbags'."""
    types = registry()
    name = "sensor_msgs/msg/Imu"
    message = build(name, {"header": {"frame_id": frame, "stamp": {"sec": -3, "nanosec": 9}},
                           "orientation": {"x": 0.5, "w": -1.25},
                           "angular_velocity": {"y": 2.0}, "linear_acceleration": {"z": 9.81},
                           "orientation_covariance": [float(i) for i in range(9)]})
    data = types.serialize(message, name)
    assert data == bytes(types.store.serialize_cdr(message, name))
    back = types.deserialize(data, name)
    assert back.header.frame_id == frame and back.header.stamp.sec == -3
    assert (back.orientation.x, back.orientation.w) == (0.5, -1.25)
    assert back.linear_acceleration.z == 9.81 and back.orientation_covariance[8] == 8.0


def test_a_value_of_the_wrong_kind_in_a_run_names_its_field():
    types = registry()
    message = build("geometry_msgs/msg/Twist", {})
    message.angular.z = "fast"
    with pytest.raises(Exception, match="z"):
        types.serialize(message, "geometry_msgs/msg/Twist")

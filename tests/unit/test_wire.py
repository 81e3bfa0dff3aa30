"""The hand-packed CDR of bus/wire.py, byte for byte against rosbags' serializer."""

from __future__ import annotations

import numpy as np

from launcher.bus.messages import build
from launcher.bus.types import registry
from launcher.bus.wire import JointStateReader, clock_cdr, pack_tf


def test_the_packed_clock_is_the_cdr_of_the_clock_message():
    payload = clock_cdr(12.345, 3.5, True, 12345)
    message = registry().deserialize(payload, "mujoco_sim/msg/Clock")
    assert (message.sim.sec, message.sim.nanosec) == (12, 345_000_000)
    assert (message.real.sec, message.real.nanosec) == (3, 500_000_000)
    assert message.paused is True and message.iterations == 12345
    assert bytes(registry().serialize(message, "mujoco_sim/msg/Clock")) == payload


def test_packed_tf_is_the_cdr_rosbags_makes():
    payload = pack_tf(5, 7, ["base", "a_longer_name"], ["x", "child2"],
                      np.array([[1.0, 2, 3], [4, 5, 6]]), np.array([[0, 0, 0, 1.0], [0, 0, 1, 0]]))
    message = registry().deserialize(payload, "tf2_msgs/msg/TFMessage")
    second = message.transforms[1]
    assert second.header.frame_id == "a_longer_name" and second.child_frame_id == "child2"
    assert (second.transform.translation.x, second.transform.rotation.z) == (4.0, 1.0)
    assert bytes(registry().serialize(message, "tf2_msgs/msg/TFMessage")) == payload


def test_the_joint_state_reader_reads_what_rosbags_writes_and_caches_names():
    reader = JointStateReader()
    for names, positions in ((["j1", "a_long_joint_name", "x"], [0.5, -1.25, 3.0]),
                             (["j1", "a_long_joint_name", "x"], [1.5, 2.0, -3.0]),
                             (["other"], [7.0])):
        message = build("sensor_msgs/msg/JointState", {
            "header": {"stamp": {"sec": 12, "nanosec": 34}, "frame_id": "odd"},
            "name": names, "position": positions, "velocity": [1.0] * len(names)})
        payload = bytes(registry().serialize(message, "sensor_msgs/msg/JointState"))
        sec, nanosec, read_names, read_positions = reader.read(payload)
        assert (sec, nanosec, read_names) == (12, 34, names)
        assert list(read_positions) == positions


def test_the_packed_image_is_the_cdr_rosbags_makes():
    from launcher.bus.wire import image_cdr

    pixels = np.arange(2 * 3 * 4, dtype=np.float32).reshape(2, 3 * 4 // 4, 4)[..., 0]
    pixels = np.ascontiguousarray(pixels)
    payload = image_cdr(3, 9, "cam_o", 2, 3, "32FC1", 12, pixels)
    message = registry().deserialize(bytes(payload), "sensor_msgs/msg/Image")
    assert (message.height, message.width, message.encoding, message.step) == (2, 3, "32FC1", 12)
    assert message.header.frame_id == "cam_o" and message.header.stamp.nanosec == 9
    assert np.frombuffer(bytes(message.data), np.float32).tolist() == pixels.ravel().tolist()
    assert bytes(registry().serialize(message, "sensor_msgs/msg/Image")) == bytes(payload)

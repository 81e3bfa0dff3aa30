"""Gazebo's message shapes over the sim's types, both ways."""

from __future__ import annotations

from launcher.sim import gz_msgs


def test_times_are_nsec_in_gazebo_and_nanosec_in_the_sim_at_any_depth():
    clock = {"sim": {"sec": 3, "nanosec": 5}, "real": {"sec": 4, "nanosec": 6}}
    shown = gz_msgs.to_gz("Clock", clock)
    assert shown == {"sim": {"sec": 3, "nsec": 5}, "real": {"sec": 4, "nsec": 6}}
    poses = {"header": {"stamp": {"sec": 1, "nanosec": 2}}, "name": ["a"],
             "pose": [{"position": {"x": 1.0}}]}
    assert gz_msgs.to_gz("PoseV", poses) == {
        "header": {"stamp": {"sec": 1, "nsec": 2}},
        "pose": [{"name": "a", "position": {"x": 1.0}}]}
    typed = {"header": {"stamp": {"sec": 1, "nsec": 2}}, "linear": {"x": 0.5}}
    assert gz_msgs.to_sim("Twist", typed) == {"linear": {"x": 0.5}}  # header: not in the sim's
    assert gz_msgs.to_sim("Other", typed) == {"header": {"stamp": {"sec": 1, "nanosec": 2}},
                                               "linear": {"x": 0.5}}


def test_a_pose_moves_its_fields_under_pose_and_a_reply_is_a_boolean():
    typed = {"name": "box", "id": 7, "position": {"z": 1.0}, "orientation": {"w": 1.0}}
    assert gz_msgs.to_sim("Pose", typed) == {
        "name": "box", "pose": {"position": {"z": 1.0}, "orientation": {"w": 1.0}}}
    assert gz_msgs.reply_to_gz("Boolean", {"success": True, "message": ""}) == {"data": True}

"""A wheeled base's planar odometry as ros2_controllers publish it: `nav_msgs/Odometry` (pose,
twist, the diagonal covariances) and the odom → base transform on `/tf`, each only while
someone listens (diff_drive_controller, tricycle_controller, ackermann_steering_controller)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any


def publish(controller: Any, time: float, x: float, y: float, heading: float, linear: float,
            angular: float, pose_diagonal: Sequence[float] = (),
            twist_diagonal: Sequence[float] = ()) -> None:
    """On the controller's `odom_pub` and (when `tf_enabled`) `tf_pub`, in its `odom_frame`
    with child `base_frame`; a diagonal fills the 6×6 covariance's diagonal."""
    odom_wanted = controller.odom_pub.get_subscription_count() > 0
    tf_wanted = controller.tf_enabled and controller.tf_pub.get_subscription_count() > 0
    if not (odom_wanted or tf_wanted):
        return
    make = controller.make
    header = controller.header(time, controller.odom_frame)
    quat = make("geometry_msgs/msg/Quaternion", x=0.0, y=0.0, z=math.sin(heading / 2),
                w=math.cos(heading / 2))
    if odom_wanted:
        controller.odom_pub.publish(make(
            "nav_msgs/msg/Odometry", header=header, child_frame_id=controller.base_frame,
            pose=make("geometry_msgs/msg/PoseWithCovariance", pose=make(
                "geometry_msgs/msg/Pose", position=make(
                    "geometry_msgs/msg/Point", x=x, y=y, z=0.0),
                orientation=quat), covariance=_covariance(pose_diagonal)),
            twist=make("geometry_msgs/msg/TwistWithCovariance", twist=make(
                "geometry_msgs/msg/Twist",
                linear=make("geometry_msgs/msg/Vector3", x=linear, y=0.0, z=0.0),
                angular=make("geometry_msgs/msg/Vector3", x=0.0, y=0.0, z=angular)),
                covariance=_covariance(twist_diagonal))))
    if tf_wanted:
        controller.tf_pub.publish(make("tf2_msgs/msg/TFMessage", transforms=[make(
            "geometry_msgs/msg/TransformStamped", header=header,
            child_frame_id=controller.base_frame, transform=make(
                "geometry_msgs/msg/Transform", translation=make(
                    "geometry_msgs/msg/Vector3", x=x, y=y, z=0.0),
                rotation=quat))]))


def _covariance(diagonal: Sequence[float]) -> list[float]:
    values = [0.0] * 36
    for i, value in enumerate(diagonal[:6]):
        values[i * 7] = float(value)
    return values

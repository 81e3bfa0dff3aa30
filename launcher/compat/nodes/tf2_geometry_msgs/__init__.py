"""tf2_geometry_msgs: geometry_msgs through a TransformStamped (do_transform_point, _vector3,
_pose, _pose_stamped), and the stamped types a Buffer's `transform` takes."""

from __future__ import annotations

from typing import Any

from tf2_ros.buffer import register_transform
from tf2_ros.buffer_core import multiply


def _pose_of(transform: Any) -> Any:
    t, r = transform.transform.translation, transform.transform.rotation
    return (t.x, t.y, t.z), (r.x, r.y, r.z, r.w)


def _header(stamped: Any, transform: Any) -> Any:
    from std_msgs.msg import Header

    return Header(stamp=transform.header.stamp, frame_id=transform.header.frame_id)


def do_transform_point(point: Any, transform: Any) -> Any:
    """A PointStamped moved by a TransformStamped."""
    from geometry_msgs.msg import Point, PointStamped

    (x, y, z), _ = multiply(_pose_of(transform),
                            ((point.point.x, point.point.y, point.point.z), (0, 0, 0, 1)))
    return PointStamped(header=_header(point, transform), point=Point(x=x, y=y, z=z))


def do_transform_vector3(vector3: Any, transform: Any) -> Any:
    """A Vector3Stamped turned by a TransformStamped (no translation)."""
    from geometry_msgs.msg import Vector3, Vector3Stamped

    _, rotation = _pose_of(transform)
    v = vector3.vector
    (x, y, z), _ = multiply(((0.0, 0.0, 0.0), rotation), ((v.x, v.y, v.z), (0, 0, 0, 1)))
    return Vector3Stamped(header=_header(vector3, transform), vector=Vector3(x=x, y=y, z=z))


def do_transform_pose(pose: Any, transform: Any) -> Any:
    """A Pose moved by a TransformStamped."""
    from geometry_msgs.msg import Point, Pose, Quaternion

    p, q = pose.position, pose.orientation
    (x, y, z), (qx, qy, qz, qw) = multiply(_pose_of(transform),
                                           ((p.x, p.y, p.z), (q.x, q.y, q.z, q.w)))
    return Pose(position=Point(x=x, y=y, z=z), orientation=Quaternion(x=qx, y=qy, z=qz, w=qw))


def do_transform_pose_stamped(pose: Any, transform: Any) -> Any:
    """A PoseStamped moved by a TransformStamped."""
    from geometry_msgs.msg import PoseStamped

    return PoseStamped(header=_header(pose, transform),
                       pose=do_transform_pose(pose.pose, transform))


def _register() -> None:
    from geometry_msgs.msg import PointStamped, PoseStamped, Vector3Stamped

    register_transform(PointStamped, do_transform_point)
    register_transform(Vector3Stamped, do_transform_vector3)
    register_transform(PoseStamped, do_transform_pose_stamped)


_register()

__all__ = ["do_transform_point", "do_transform_pose", "do_transform_pose_stamped",
           "do_transform_vector3"]

"""What gz-sim's drive systems (DiffDrive, AckermannSteering) share: their command and odometry
parameters, declared once, and their odometry: gz.msgs.Odometry on `odom_topic` (`odometry`)
and its pose as gz.msgs.Pose_V on `tf_topic` (`tf`), from `frame_id` (`<name>/odom`) to
`child_frame_id` (`<name>/<root link>`), at `odom_publish_frequency` on the grid of
sim/schedule.py (0: never), each only while someone listens."""

from __future__ import annotations

import math
from typing import Any

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim import schedule


@dataclass
class OdometryParameters:
    """A drive system's command topic and odometry (each drive's Parameters extend it)."""

    odom_publish_frequency: float = attr(Kind.FLOAT, 50.0, minimum=0.0)
    topic: str = attr(Kind.TEXT, "")
    odom_topic: str = attr(Kind.TEXT, "")
    tf_topic: str = attr(Kind.TEXT, "")
    frame_id: str = attr(Kind.TEXT, "")
    child_frame_id: str = attr(Kind.TEXT, "")


def open_odometry(plugin: Any, params: OdometryParameters) -> None:
    """The drive's frames and its publishers (`odom_pub`, `tf_pub`), on the sim's side."""
    name, transport = plugin.entity.name, plugin.sim.transport
    plugin.frame_id = params.frame_id or f"{name}/odom"
    plugin.child_frame_id = params.child_frame_id or f"{name}/{plugin.root}"
    plugin.odom_pub = transport.publisher("mujoco_sim/msg/Odometry",
                                          plugin.topic(params.odom_topic, "odometry"))
    plugin.tf_pub = transport.publisher("mujoco_sim/msg/PoseV",
                                        plugin.topic(params.tf_topic, "tf"))


class OdometrySchedule:
    """When a drive publishes its odometry: the grid of its frequency; never at 0."""

    def __init__(self, frequency: float) -> None:
        self.frequency = frequency
        self.next_update = 0.0  # (schedule.tick's)

    def due(self, now: float) -> bool:
        """Whether it is due at `now`; when it is, the next time moves on."""
        return self.frequency > 0 and schedule.tick(self, now, self.frequency)

    @property
    def next(self) -> float:
        return self.next_update if self.frequency > 0 else math.inf


def publish_odometry(plugin: Any, now: float, x: float, y: float, heading: float,
                     linear: float, angular: float) -> None:
    """The odometry on the plugin's `odom_pub` and its pose on `tf_pub`, each only while
    someone listens."""
    odom_wanted = plugin.odom_pub.get_subscription_count() > 0
    tf_wanted = plugin.tf_pub.get_subscription_count() > 0
    if not (odom_wanted or tf_wanted):
        return
    transport = plugin.sim.transport
    header = transport.header(now, plugin.frame_id)
    pose = transport.pose(x, y, 0.0, yaw_quat(heading))
    if odom_wanted:
        plugin.odom_pub.publish(transport.message(
            "mujoco_sim/msg/Odometry", header=header, child_frame_id=plugin.child_frame_id,
            pose=pose, twist=transport.message(
                "geometry_msgs/msg/Twist", linear=transport.vector(linear, 0.0, 0.0),
                angular=transport.vector(0.0, 0.0, angular))))
    if tf_wanted:
        plugin.tf_pub.publish(transport.message(
            "mujoco_sim/msg/PoseV", header=header, name=[plugin.child_frame_id],
            parent=[plugin.frame_id], pose=[pose]))


def yaw_quat(theta: float) -> tuple[float, float, float, float]:
    """(x, y, z, w), ROS order."""
    return 0.0, 0.0, math.sin(theta / 2), math.cos(theta / 2)

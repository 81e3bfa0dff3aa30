"""Gazebo's systems that publish where a model is: OdometryPublisher and PosePublisher.

OdometryPublisher (gz-sim-odometry-publisher-system): the model's pose in the world and its
velocity in its own frame (a rolling mean of 10, as gz-sim's), as gz.msgs.Odometry on
`<odom_topic>` (`/model/<name>/odometry`) and as a Pose_V transform `odom_frame` →
`robot_base_frame` on `<tf_topic>` (`/model/<name>/pose`), at `<odom_publish_frequency>` (50
Hz). `<odom_frame>` (`<name>/odom`), `<robot_base_frame>` (`<name>/base_footprint`),
`<dimensions>` (2: x, y and yaw; 3: all), `<xyz_offset>`, `<rpy_offset>`, `<gaussian_noise>`
(a standard deviation added to the pose and twist).

PosePublisher (gz-sim-pose-publisher-system): the poses of the model's links (and of the model
itself with `<publish_model_pose>`), each relative to its parent (a link's parent is its model),
named as gz-sim names frames (the model's name; its links by their own names), on
`<topic>` (`/model/<name>/pose`): one gz.msgs.Pose each, or one Pose_V with
`<use_pose_vector_msg>`. `<update_frequency>` (negative: every step), and with
`<static_publisher>` the links that cannot move relative to the model (no moving joint up to
its root) go to `<topic>_static` at `<static_update_frequency>`. Visual, collision and sensor
poses are accepted and not published (MuJoCo keeps no frames for them: said once).
"""

from __future__ import annotations

import math
import random
from collections import deque
from typing import Any

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim import schedule
from launcher.sim.plugins import Plugin
from launcher.sim.transform import IDENTITY, Pose, from_rpy


@dataclass
class OdometryParameters:
    odom_frame: str = attr(Kind.TEXT, "")
    robot_base_frame: str = attr(Kind.TEXT, "")
    odom_publish_frequency: float = attr(Kind.FLOAT, 50.0, minimum=0.0)
    odom_topic: str = attr(Kind.TEXT, "")
    odom_covariance_topic: str = attr(Kind.TEXT, "")
    tf_topic: str = attr(Kind.TEXT, "")
    dimensions: int = attr(Kind.INT, 2, minimum=2, maximum=3)
    xyz_offset: str = attr(Kind.TEXT, "0 0 0")
    rpy_offset: str = attr(Kind.TEXT, "0 0 0")
    gaussian_noise: float = attr(Kind.FLOAT, 0.0, minimum=0.0)


def model_pose(sim: Any, entity: Any) -> Pose:
    """The entity's model frame in the world now."""
    body = sim.placement.body_pose(entity.body)
    offset = entity.offset
    return body if offset is IDENTITY or offset.is_identity else body * offset.inverse()


def _yaw(quat: tuple[float, ...]) -> float:
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


class OdometryPublisher(Plugin):
    def prepare(self, spec: Any) -> None:
        p = self.params = self.parameters(OdometryParameters)
        self.offset = from_rpy(*self.three_numbers("xyz_offset", p.xyz_offset),
                               *self.three_numbers("rpy_offset", p.rpy_offset))
        self.rng = random.Random(0)
        self.reset()

    def reset(self) -> None:
        self.last: tuple[float, Pose] | None = None
        self.linear: deque[tuple[float, float, float]] = deque(maxlen=10)
        self.angular: deque[tuple[float, float, float]] = deque(maxlen=10)
        self.next_update = 0.0

    def load(self) -> None:
        name, p, transport = self.entity.name, self.params, self.sim.transport
        self.odom_frame = p.odom_frame or f"{name}/odom"
        self.base_frame = p.robot_base_frame or f"{name}/base_footprint"
        self.odom_pub = transport.publisher("mujoco_sim/msg/Odometry",
                                            p.odom_topic or f"/model/{name}/odometry")
        self.tf_pub = transport.publisher("mujoco_sim/msg/PoseV",
                                          p.tf_topic or f"/model/{name}/pose")

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        rate = self.params.odom_publish_frequency
        self.next_update = schedule.following(self.next_update, now,
                                              schedule.period(rate) or math.inf)
        pose = model_pose(self.sim, self.entity) * self.offset
        if self.params.dimensions == 2:  # on the plane: x, y and yaw only
            yaw = _yaw(pose.quat)
            pose = Pose((pose.pos[0], pose.pos[1], 0.0),
                        (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)))
        if self.last is not None and now > self.last[0]:
            dt = now - self.last[0]
            moved = self.last[1].inverse() * pose  # in the previous body frame
            self.linear.append(tuple(v / dt for v in moved.pos))
            w, x, y, z = moved.quat
            angle = 2 * math.atan2(math.sqrt(x * x + y * y + z * z), w)
            norm = math.sqrt(x * x + y * y + z * z) or 1.0
            self.angular.append(tuple(angle * v / norm / dt for v in (x, y, z)))
        self.last = (now, pose)
        if not (self.odom_pub.get_subscription_count() or self.tf_pub.get_subscription_count()):
            return
        transport = self.sim.transport

        def mean(values: deque[tuple[float, float, float]]) -> list[float]:
            if not values:
                return [0.0, 0.0, 0.0]
            return [sum(v[i] for v in values) / len(values) for i in range(3)]

        noise = self.params.gaussian_noise
        jitter = (lambda: self.rng.gauss(0.0, noise)) if noise else (lambda: 0.0)
        linear, angular = mean(self.linear), mean(self.angular)
        if self.params.dimensions == 2:
            linear[2] = angular[0] = angular[1] = 0.0
        w, x, y, z = pose.quat
        ros_pose = transport.pose(pose.pos[0] + jitter(), pose.pos[1] + jitter(),
                                  pose.pos[2] + (jitter() if self.params.dimensions == 3
                                                 else 0.0), (x, y, z, w))
        header = transport.header(now, self.odom_frame)
        if self.odom_pub.get_subscription_count():
            self.odom_pub.publish(transport.message(
                "mujoco_sim/msg/Odometry", header=header, child_frame_id=self.base_frame,
                pose=ros_pose, twist=transport.message(
                    "geometry_msgs/msg/Twist",
                    linear=transport.vector(*(v + jitter() for v in linear)),
                    angular=transport.vector(*(v + jitter() for v in angular)))))
        if self.tf_pub.get_subscription_count():
            self.tf_pub.publish(transport.message(
                "mujoco_sim/msg/PoseV", header=header, name=[self.base_frame],
                parent=[self.odom_frame], pose=[ros_pose]))

    def close(self) -> None:
        self.odom_pub.destroy()
        self.tf_pub.destroy()


@dataclass
class PoseParameters:
    publish_link_pose: bool = attr(Kind.BOOL, True)
    publish_visual_pose: bool = attr(Kind.BOOL, False)
    publish_collision_pose: bool = attr(Kind.BOOL, False)
    publish_sensor_pose: bool = attr(Kind.BOOL, False)
    publish_model_pose: bool = attr(Kind.BOOL, False)
    publish_nested_model_pose: bool = attr(Kind.BOOL, False)
    use_pose_vector_msg: bool = attr(Kind.BOOL, False)
    update_frequency: float = attr(Kind.FLOAT, -1.0)
    static_publisher: bool = attr(Kind.BOOL, False)
    static_update_frequency: float = attr(Kind.FLOAT, -1.0)
    topic: str = attr(Kind.TEXT, "")


class PosePublisher(Plugin):
    def prepare(self, spec: Any) -> None:
        p = self.params = self.parameters(PoseParameters)
        unsupported = [tag for tag in ("publish_visual_pose", "publish_collision_pose",
                                       "publish_sensor_pose") if getattr(p, tag)]
        if unsupported:
            self.sim.transport.logger.warning(
                f"{self.config.where}: plugin {self.label}: {', '.join(unsupported)} accepted: "
                f"only link and model poses are published (MuJoCo keeps no frames for "
                f"visuals, collisions and sensors)")
        self.next_update = 0.0
        self.next_static = 0.0

    def load(self) -> None:
        name, p, transport = self.entity.name, self.params, self.sim.transport
        topic = p.topic or f"/model/{name}/pose"
        kind = "mujoco_sim/msg/PoseV" if p.use_pose_vector_msg else "mujoco_sim/msg/Pose"
        self.pose_pub = transport.publisher(kind, topic)
        self.static_pub = transport.publisher(kind, f"{topic}_static") \
            if p.static_publisher else None

    def bind(self, model: Any, data: Any) -> None:
        prefix = f"{self.entity.name}/"
        self.links: list[tuple[str, int, bool]] = []  # (frame, body, dynamic)
        for body in range(model.nbody):
            full = model.body(body).name
            if not full.startswith(prefix):
                continue
            moving, walk = False, body
            while walk > 0 and model.body(walk).name.startswith(prefix):
                if model.body_jntnum[walk] and walk != self.entity.body:
                    moving = True
                walk = int(model.body_parentid[walk])
            self.links.append((full[len(prefix):].replace("/", "::"), body, moving))

    def _poses(self, dynamic: bool) -> list[tuple[str, str, Pose]]:
        """(parent frame, frame, pose) of what goes out on the dynamic or the static topic."""
        name = self.entity.name
        model = model_pose(self.sim, self.entity)
        found = []
        if dynamic and self.params.publish_model_pose:
            found.append((self.sim.world_name, name, model))
        if self.params.publish_link_pose:
            to_model = model.inverse()
            placement = self.sim.placement
            for frame, body, moving in self.links:
                free = body == self.entity.body and self.entity.dof >= 0
                if (moving or free or not self.params.static_publisher) == dynamic:
                    found.append((name, frame, to_model * placement.body_pose(body)))
        return found

    def _publish(self, publisher: Any, poses: list[tuple[str, str, Pose]], now: float) -> None:
        transport = self.sim.transport
        ros = [transport.pose(*p.pos, (p.quat[1], p.quat[2], p.quat[3], p.quat[0]))
               for _, _, p in poses]
        if self.params.use_pose_vector_msg:
            publisher.publish(transport.message(
                "mujoco_sim/msg/PoseV", header=transport.header(now, ""),
                name=[c for _, c, _ in poses], parent=[f for f, _, _ in poses], pose=ros))
            return
        for (parent, child, _), pose in zip(poses, ros, strict=True):
            publisher.publish(transport.message("mujoco_sim/msg/Pose",
                                                header=transport.header(now, parent),
                                                name=child, pose=pose))

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        rate = self.params.update_frequency
        if self.pose_pub.get_subscription_count():
            self._publish(self.pose_pub, self._poses(True), now)
            self.next_update = schedule.following(self.next_update, now, schedule.period(rate))
        else:
            self.next_update = now + schedule.LAZY_LOOK
        static = self.static_pub
        if static is not None and now >= self.next_static and static.get_subscription_count():
            self._publish(static, self._poses(False), now)
            rate = self.params.static_update_frequency
            self.next_static = schedule.following(self.next_static, now,
                                                  schedule.period(rate))
        if static is not None:
            self.next_update = min(self.next_update,
                                   max(self.next_static, now + schedule.LAZY_LOOK))

    def close(self) -> None:
        self.pose_pub.destroy()
        if self.static_pub is not None:
            self.static_pub.destroy()

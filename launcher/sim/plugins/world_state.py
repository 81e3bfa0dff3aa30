"""The world's state topics: every entity's pose and velocity, at `update_rate` Hz of sim time.

`/world/<w>/pose/info` (Pose_V: each entity's root pose in the world frame, Gazebo's name),
`/world/<w>/dynamic_pose/info` (the same for the entities that are not static, as Gazebo's
scene broadcaster has it: a model held to the world by a joint is not static, its links may
move) and `/world/<w>/model_states` (ModelStates: name, pose, twist, as ROS 1's
/gazebo/model_states). The sim loads it into every world.
"""

from __future__ import annotations

from typing import Any

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim import schedule
from launcher.sim.plugins import Plugin


@dataclass
class Parameters:
    update_rate: float = attr(Kind.FLOAT, 50.0, minimum=0.0, doc="Hz of sim time.")


class WorldState(Plugin):
    def load(self) -> None:
        self.rate = self.parameters(Parameters).update_rate
        transport, world = self.sim.transport, self.sim.world_name
        self.poses = transport.publisher("mujoco_sim/msg/PoseV", f"/world/{world}/pose/info")
        self.dynamic = transport.publisher("mujoco_sim/msg/PoseV",
                                           f"/world/{world}/dynamic_pose/info")
        self.states = transport.publisher("mujoco_sim/msg/ModelStates",
                                          f"/world/{world}/model_states")
        self.links = transport.publisher("mujoco_sim/msg/ModelStates",
                                         f"/world/{world}/link_states")
        self.reset()

    def reset(self) -> None:
        self.next_update = 0.0

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        if self.rate <= 0 or not schedule.tick(self, now, self.rate):
            return
        want_poses = self.poses.get_subscription_count() > 0
        want_dynamic = self.dynamic.get_subscription_count() > 0
        want_states = self.states.get_subscription_count() > 0
        if self.links.get_subscription_count() > 0:
            self.publish_links(model, data)
        if not (want_poses or want_dynamic or want_states):
            return
        names, positions, quats = self.sim.placement.poses()
        transport = self.sim.transport
        poses = [transport.pose(p[0], p[1], p[2], (q[1], q[2], q[3], q[0]))
                 for p, q in zip(positions, quats, strict=True)]
        header = transport.header(now, "world")
        if want_poses:
            self.publish_poses(self.poses, header, names, poses)
        if want_dynamic:
            entities = self.sim.entities
            moving = [i for i, name in enumerate(names) if not entities[name].static]
            self.publish_poses(self.dynamic, header, [names[i] for i in moving],
                               [poses[i] for i in moving])
        if not want_states:
            return
        twists = [transport.message("geometry_msgs/msg/Twist",
                                    linear=transport.vector(*velocity[:3]),
                                    angular=transport.vector(*velocity[3:6]))
                  for velocity in self.sim.placement.velocities(names)]
        self.states.publish(transport.message("mujoco_sim/msg/ModelStates", header=header,
                                              name=names, pose=poses, twist=twists))

    def publish_poses(self, publisher: Any, header: Any, names: list[str],
                      poses: list[Any]) -> None:
        publisher.publish(self.sim.transport.message(
            "mujoco_sim/msg/PoseV", header=header, name=names, parent=["world"] * len(names),
            pose=poses))

    def publish_links(self, model: Any, data: Any) -> None:
        """Every link of every entity as `entity::link` (gazebo_ros's link_states): the pose
        of the body frame and its velocity in the world frame."""
        import mujoco
        import numpy as np

        entities = set(self.sim.placement.poses()[0])
        transport = self.sim.transport
        names, poses, twists = [], [], []
        velocity = np.zeros(6)
        for body in range(1, model.nbody):
            entity, _, link = model.body(body).name.partition("/")
            if not link or entity not in entities:
                continue
            p, q = data.xpos[body], data.xquat[body]
            mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, body, velocity, 0)
            names.append(f"{entity}::{link}")
            poses.append(transport.pose(p[0], p[1], p[2], (q[1], q[2], q[3], q[0])))
            twists.append(transport.message("geometry_msgs/msg/Twist",
                                            linear=transport.vector(*velocity[3:6]),
                                            angular=transport.vector(*velocity[:3])))
        self.links.publish(transport.message(
            "mujoco_sim/msg/ModelStates", header=transport.header(data.time, "world"),
            name=names, pose=poses, twist=twists))

    def close(self) -> None:
        self.links.destroy()
        self.poses.destroy()
        self.dynamic.destroy()
        self.states.destroy()

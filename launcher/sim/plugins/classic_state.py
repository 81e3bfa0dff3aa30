"""gazebo_ros's ground-truth model plugins: `libgazebo_ros_p3d.so` (a link's pose and
velocity as nav_msgs/Odometry on `odom`) and `libgazebo_ros_ft_sensor.so` (the wrench a joint
carries, or a link's external force, as geometry_msgs/WrenchStamped on `wrench`), in the
plugin's ROS node (plugins/gazebo_ros.py), with their ROS 2 and ROS 1 parameters.

p3d: `body_name` (bodyName), `frame_name` (frameName: world, map, or a link of the model the
pose and velocity are taken against), `xyz_offset(s)`, `rpy_offset(s)`, `gaussian_noise`
(gaussianNoise, on the velocities), `update_rate` (updateRate, Hz of sim time; 0 every step),
ROS 1's `topicName`. ft_sensor: `joint_name` (what the parent exerts on the child across the
joint, in the child's frame at the joint, frame id the child link) or `body_name` (the link's
external force and torque in the world frame, frame id `frame_name`), `gaussian_noise`,
`update_rate`, ROS 1's `topicName`.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from launcher.sim.plugins import PluginError
from launcher.sim.plugins.gazebo_ros import ros_node
from launcher.sim.plugins.periodic import PeriodicPublisher
from launcher.sim.sensors.noise import generator

WORLD_FRAMES = ("world", "/world", "map", "/map")


class _GroundTruth(PeriodicPublisher):
    """A gazebo_ros model plugin that publishes one ROS message at its update rate."""

    unknown_parameters = "ignore"
    type_name = ""
    default_topic = ""

    def setting(self, *names: str, default: str = "") -> str:
        for name in names:
            found = self.text(name)
            if found:
                return found
        return default

    def prepare(self, spec: Any) -> None:
        rate = self.setting("update_rate", "updateRate", default="0")
        try:
            self.rate = float(rate)
            self.noise = float(self.setting("gaussian_noise", "gaussianNoise", default="0"))
        except ValueError:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <update_rate> and "
                              "<gaussian_noise> must be numbers") from None
        if not (math.isfinite(self.rate) and self.rate >= 0 and self.noise >= 0):
            raise PluginError(f"{self.config.where}: plugin {self.label}: <update_rate> and "
                              "<gaussian_noise> must be ≥ 0")
        self.links = {b.name[len(self.spec_prefix):] for b in spec.bodies
                      if b.name.startswith(self.spec_prefix)}

    def link(self, name: str, tag: str) -> str:
        if name not in self.links:
            from launcher.errors import did_you_mean

            raise PluginError(f"{self.config.where}: plugin {self.label}: <{tag}> '{name}' is "
                              f"not a link of '{self.entity.name}'"
                              f"{did_you_mean(name, sorted(self.links))} (its links: "
                              f"{', '.join(sorted(self.links))})")
        return name

    def load(self) -> None:
        node = ros_node(self.config.element, self.config.namespace)
        topic = self.setting("topicName") or self.default_topic
        self.publisher = self.sim.transport.publisher(self.type_name, node.topic(topic),
                                                      ros=True)
        self.rng = generator(getattr(self.sim, "seed", 0), f"{self.entity.name}::{self.label}")
        self.reset()

    def noisy(self, values: Any) -> Any:
        values = np.asarray(values, dtype=float)
        if self.noise > 0:
            values = values + self.rng.normal(0.0, self.noise, values.shape)
        return self.sim.transport.vector(*values)

    def measure(self, model: Any, data: Any) -> Any:
        raise NotImplementedError

    def close(self) -> None:
        self.publisher.destroy()


class P3D(_GroundTruth):
    type_name = "nav_msgs/msg/Odometry"
    default_topic = "odom"

    def prepare(self, spec: Any) -> None:
        super().prepare(spec)
        body = self.setting("body_name", "bodyName")
        if not body:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <body_name> is "
                              "missing: which link to report")
        self.body_name = self.link(body, "body_name")
        self.frame = self.setting("frame_name", "frameName", default="world")
        self.reference = None if self.frame in WORLD_FRAMES else \
            self.link(self.frame, "frame_name")
        self.offset = self._vector("xyz_offset", "xyz_offsets", "xyzOffsets", "xyzOffset")
        rpy = self._vector("rpy_offset", "rpy_offsets", "rpyOffsets", "rpyOffset")
        self.offset_quat = np.zeros(4)
        mujoco.mju_euler2Quat(self.offset_quat, rpy, "XYZ")

    def _vector(self, *names: str) -> Any:
        text = self.setting(*names, default="0 0 0")
        try:
            values = [float(v) for v in text.split()]
        except ValueError:
            values = []
        if len(values) != 3:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <{names[0]}> must be "
                              f"three numbers, got '{text}'")
        return np.array(values)

    def bind(self, model: Any, data: Any) -> None:
        self.body = model.body(f"{self.entity.name}/{self.body_name}").id
        self.reference_body = None if self.reference is None else \
            model.body(f"{self.entity.name}/{self.reference}").id

    def _state(self, model: Any, data: Any, body: int) -> tuple[Any, Any, Any, Any]:
        velocity = np.zeros(6)  # [angular, linear] in the world frame, at the body's frame
        mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_XBODY, body, velocity, 0)
        return data.xpos[body].copy(), data.xquat[body].copy(), velocity[3:], velocity[:3]

    def measure(self, model: Any, data: Any) -> Any:
        position, quat, linear, angular = self._state(model, data, self.body)
        if self.reference_body is not None:
            # against a link, all in that link's frame (gazebo_ros_p3d turns the velocities
            # and the orientation the wrong way round; here they are what the frame sees)
            frame_pos, frame_quat, frame_linear, frame_angular = \
                self._state(model, data, self.reference_body)
            inverse = np.zeros(4)
            mujoco.mju_negQuat(inverse, frame_quat)
            relative = np.zeros(3)
            mujoco.mju_rotVecQuat(relative, position - frame_pos, inverse)
            position = relative
            turned = np.zeros(4)
            mujoco.mju_mulQuat(turned, inverse, quat)
            quat = turned
            for values, frame in ((linear, frame_linear), (angular, frame_angular)):
                rotated = np.zeros(3)
                mujoco.mju_rotVecQuat(rotated, values - frame, inverse)
                values[:] = rotated
        position = position + self.offset
        offset = np.zeros(4)
        mujoco.mju_mulQuat(offset, self.offset_quat, quat)
        mujoco.mju_normalize4(offset)
        t = self.sim.transport
        w, x, y, z = (float(v) for v in offset)
        covariance = [0.0] * 36
        for index in range(0, 36, 7):
            covariance[index] = self.noise ** 2
        return t.message(
            "nav_msgs/msg/Odometry", header=t.header(data.time, self.frame),
            child_frame_id=self.body_name,
            pose=t.message("geometry_msgs/msg/PoseWithCovariance",
                           pose=t.pose(*position, (x, y, z, w)), covariance=covariance),
            twist=t.message("geometry_msgs/msg/TwistWithCovariance", twist=t.message(
                "geometry_msgs/msg/Twist", linear=self.noisy(linear),
                angular=self.noisy(angular)), covariance=covariance))


class FTSensor(_GroundTruth):
    type_name = "geometry_msgs/msg/WrenchStamped"
    default_topic = "wrench"

    def prepare(self, spec: Any) -> None:
        super().prepare(spec)
        joint, body = self.setting("joint_name", "jointName"), \
            self.setting("body_name", "bodyName")
        if not joint and not body:
            raise PluginError(f"{self.config.where}: plugin {self.label}: give <joint_name> "
                              "(the wrench a joint carries) or <body_name> (a link's)")
        self.joint = joint
        if joint:
            joints = {j.name[len(self.spec_prefix):]: j for j in spec.joints
                      if j.name.startswith(self.spec_prefix)}
            if joint not in joints:
                from launcher.errors import did_you_mean

                raise PluginError(
                    f"{self.config.where}: plugin {self.label}: <joint_name> '{joint}' is not "
                    f"a moving joint of '{self.entity.name}'{did_you_mean(joint, list(joints))}"
                    " (MuJoCo keeps no fixed joint: name its child link with <body_name>)")
            found = joints[joint]
            child = found.parent  # the joint's body is the child link
            self.frame_id = child.name[len(self.spec_prefix):]
            site = child.add_site(name=self.in_spec(f"{self.frame_id}/ft/{self.label}"),
                                  pos=list(found.pos), group=5)
            for kind, suffix in ((mujoco.mjtSensor.mjSENS_FORCE, "force"),
                                 (mujoco.mjtSensor.mjSENS_TORQUE, "torque")):
                spec.add_sensor(name=f"{site.name}/{suffix}", type=kind,
                                objtype=mujoco.mjtObj.mjOBJ_SITE, objname=site.name)
            self.site_name = site.name[len(self.spec_prefix):]
        else:
            self.body_name = self.link(body, "body_name")
            self.frame_id = self.setting("frame_name", "frameName", default="world")

    def bind(self, model: Any, data: Any) -> None:
        if self.joint:
            site = f"{self.entity.name}/{self.site_name}"
            self.addresses = [int(model.sensor(f"{site}/{s}").adr[0])
                              for s in ("force", "torque")]
        else:
            self.body = model.body(f"{self.entity.name}/{self.body_name}").id

    def measure(self, model: Any, data: Any) -> Any:
        if self.joint:
            force, torque = (data.sensordata[a:a + 3] for a in self.addresses)
        else:  # the external force and torque on the link (contacts, pushes), world frame
            torque, force = data.cfrc_ext[self.body][:3], data.cfrc_ext[self.body][3:]
        t = self.sim.transport
        return t.message("geometry_msgs/msg/WrenchStamped",
                         header=t.header(data.time, self.frame_id),
                         wrench=t.message("geometry_msgs/msg/Wrench", force=self.noisy(force),
                                          torque=self.noisy(torque)))

"""mujoco_ros2_control_plugins in the sim: the `mujoco_plugins.<name>.type` parameters of the
`mujoco_ros2_control_node`, each made and given its own sub-namespace (`<name>`, as
rclcpp's sub-nodes give it: relative topics are `/<name>/<topic>`), updated every control
cycle before the controllers, as mujoco_ros2_control updates them.

  HeartbeatPublisherPlugin        `mujoco_heartbeat` (std_msgs/String) at `update_rate` Hz
  FreeJointStatePublisherPlugin   `topic` (free_joint_states) at `publish_rate`: every free
                                  body (or `body_names`), in the world or `frame_id`'s frame
  BaseVelocityPlugin              `cmd_vel_topic` drives `body`'s free joint kinematically in
                                  the plane (clamped, zero after `cmd_timeout`)
  RangefinderLidarPlugin          `lidar.*`: the MJCF's `<name>-NN` rangefinders as a LaserScan
  CameraPlugin                    the MJCF's cameras: colour, aligned depth and camera_info
                                  (camera_plugin.py)
  ExternalWrenchPlugin            `apply_wrench` pushes bodies for a while (wrench_plugin.py)
  Mujoco3dLidarPlugin             the MJCF's lidar sensors as LaserScan or PointCloud2
                                  (lidar3d_plugin.py)

Each declares its parameters as data (PARAMETERS, read under `mujoco_plugins.<name>.` when it
is made: a wrong value is refused at its line in the parameter file; a rate must be above 0).
A type launcher does not provide is refused at start, with the ones it does.
"""

from __future__ import annotations

import math
import time
from typing import Any

import mujoco
import numpy as np

from launcher.bus.declarations import REQUIRED, Param
from launcher.bus.wire import fill_stamp
from launcher.errors import LaunchError, did_you_mean
from launcher.sim.mujoco_control.camera_plugin import CameraPlugin
from launcher.sim.mujoco_control.lidar3d_plugin import Mujoco3dLidar
from launcher.sim.mujoco_control.ros_plugin import Context, RosPlugin
from launcher.sim.mujoco_control.wrench_plugin import ExternalWrench

PREFIX = "mujoco_ros2_control_plugins/"


class Heartbeat(RosPlugin):
    PARAMETERS = (Param("update_rate", "double", 1.0, "heartbeats a second of sim time (Hz)",
                        above=0.0),)
    RATE = "update_rate"

    def __init__(self, *args: Any) -> None:
        super().__init__(*args)
        self.publisher = self.node.create_publisher("std_msgs/msg/String",
                                                    self.topic("mujoco_heartbeat"), 10)
        self.count = 0

    def publish(self, model: Any, data: Any, now: float) -> None:
        self.publisher.publish(self.node.message(
            "std_msgs/msg/String", data=f"MuJoCo ROS2 Control Heartbeat #{self.count} | "
                                         f"Simulation time: {data.time:.6f}s"))
        self.count += 1


def _free_bodies(model: Any) -> dict[str, int]:
    """Body name → its free joint."""
    return {model.body(int(model.jnt_bodyid[j])).name: j for j in range(model.njnt)
            if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE}


class FreeJointStates(RosPlugin):
    PARAMETERS = (
        Param("frame_id", "string", "", "the MuJoCo body whose frame poses and twists are in "
              "(empty: the world)"),
        Param("body_names", "string_array", [], "the free-joint bodies published (empty: "
              "every one)"),
        Param("topic", "string", "free_joint_states", "where they are published"),
        Param("publish_rate", "double", 50.0, "messages a second of sim time (Hz)", above=0.0),
    )
    RATE = "publish_rate"

    def __init__(self, *args: Any) -> None:
        super().__init__(*args)
        model = self.world.model
        free = _free_bodies(model)
        wanted = self.values["body_names"]
        for body in wanted:
            if body not in free:
                raise LaunchError(f"{self.place(self.prefix + 'body_names')}: "
                                  f"{self.prefix}body_names: '{body}' is not a body with a "
                                  f"free joint{did_you_mean(body, free)}")
        self.bodies = wanted or list(free)
        self.frame = self.values["frame_id"]
        if self.frame and mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, self.frame) < 0:
            self.log.error(f"{self.prefix}frame_id: no body '{self.frame}'; "
                           f"publishing in the world frame")
            self.frame = ""
        self.publisher = self.node.create_publisher(
            "mujoco_ros2_control_msgs/msg/FreeJointStateArray", self.topic(self.values["topic"]),
            10)

    def wanted(self) -> bool:
        return self.publisher.get_subscription_count() > 0

    def publish(self, model: Any, data: Any, now: float) -> None:
        node, entries = self.node, []
        frame = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, self.frame) \
            if self.frame else -1
        inverse = np.zeros(4)
        if frame >= 0:
            mujoco.mju_negQuat(inverse, data.xquat[frame])
        for name in self.bodies:
            body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name)
            position, quat = data.xpos[body].copy(), data.xquat[body].copy()
            joint = _free_bodies(model)[name]
            dof = int(model.jnt_dofadr[joint])
            linear = data.qvel[dof:dof + 3].copy()
            angular = np.zeros(3)
            mujoco.mju_rotVecQuat(angular, data.qvel[dof + 3:dof + 6], quat)  # to world
            if frame >= 0:
                for vector in (linear, angular):
                    rotated = np.zeros(3)
                    mujoco.mju_rotVecQuat(rotated, vector, inverse)
                    vector[:] = rotated
                relative = np.zeros(3)
                mujoco.mju_rotVecQuat(relative, position - data.xpos[frame], inverse)
                position = relative
                combined = np.zeros(4)
                mujoco.mju_mulQuat(combined, inverse, quat)
                quat = combined
            entry = node.message("mujoco_ros2_control_msgs/msg/FreeJointState", name=name)
            entry.pose.header.frame_id = entry.twist.header.frame_id = self.frame
            p, o = entry.pose.pose.position, entry.pose.pose.orientation
            p.x, p.y, p.z = map(float, position)
            o.w, o.x, o.y, o.z = map(float, quat)
            t = entry.twist.twist
            t.linear.x, t.linear.y, t.linear.z = map(float, linear)
            t.angular.x, t.angular.y, t.angular.z = map(float, angular)
            entries.append(entry)
        message = node.message("mujoco_ros2_control_msgs/msg/FreeJointStateArray",
                               free_joints=entries)
        message.header.frame_id = self.frame
        self.publisher.publish(message)


class BaseVelocity(RosPlugin):
    PARAMETERS = (
        Param("body", "string", REQUIRED, "the MJCF body driven: one with a <freejoint/>"),
        Param("cmd_vel_topic", "string", "cmd_vel", "where the commands come"),
        Param("use_stamped_twist", "bool", False, "the commands are TwistStamped (false: "
              "Twist)"),
        Param("max_linear_velocity", "double", math.inf, "the largest planar speed (m/s)"),
        Param("max_yaw_rate", "double", math.inf, "the largest yaw rate (rad/s)"),
        Param("cmd_timeout", "double", 0.5, "s without a command before it is taken as zero"),
    )

    def __init__(self, *args: Any) -> None:
        super().__init__(*args)
        model = self.world.model
        body = self.values["body"]
        free = _free_bodies(model)
        if body not in free:
            raise LaunchError(f"{self.place(self.prefix + 'body')}: {self.prefix}body: "
                              f"'{body}' is not a body with a <freejoint/>"
                              f"{did_you_mean(body, free)}: the base velocity plugin drives a "
                              f"free joint")
        self.body, self.joint = body, free[body]
        self.max_linear = self.values["max_linear_velocity"]
        self.max_yaw = self.values["max_yaw_rate"]
        self.timeout = self.values["cmd_timeout"]
        stamped = self.values["use_stamped_twist"]
        topic = self.topic(self.values["cmd_vel_topic"])
        self.command = (0.0, 0.0, 0.0)
        self.received = -math.inf
        self.node.create_subscription(
            "geometry_msgs/msg/TwistStamped" if stamped else "geometry_msgs/msg/Twist", topic,
            (lambda m: self._on(m.twist)) if stamped else self._on, 10)

    def _on(self, twist: Any) -> None:
        values = (twist.linear.x, twist.linear.y, twist.angular.z)
        if all(math.isfinite(v) for v in values):
            self.command, self.received = values, time.monotonic()

    def update(self, model: Any, data: Any, now: float) -> None:
        """Each control cycle: the command (clamped; zero once stale) in the world frame."""
        vx, vy, wz = self.command if time.monotonic() - self.received <= self.timeout \
            else (0.0, 0.0, 0.0)
        speed = math.hypot(vx, vy)
        if speed > self.max_linear:
            vx, vy = vx * self.max_linear / speed, vy * self.max_linear / speed
        wz = min(max(wz, -self.max_yaw), self.max_yaw)
        xmat = data.xmat[int(model.jnt_bodyid[self.joint])]
        self.override = (xmat[0] * vx + xmat[1] * vy, xmat[3] * vx + xmat[4] * vy, wz)

    override: tuple[float, float, float] | None = None

    def step(self, model: Any, data: Any) -> None:
        """Before every physics step, as mujoco_ros2_control applies its staged override."""
        if self.override is None:
            return
        dof = int(model.jnt_dofadr[self.joint])
        data.qvel[dof], data.qvel[dof + 1], data.qvel[dof + 5] = self.override


class RangefinderLidar(RosPlugin):
    """The MJCF's rangefinders named `<lidar>-<index>`, one LaserScan per `<lidar>`; a range
    outside the limits is -1, as mujoco_ros2_control reports it."""

    PARAMETERS = (
        Param("lidar_publish_rate", "double", 5.0, "scans a second of sim time (Hz)",
              above=0.0),
        Param("{lidar}.min_angle", "double", REQUIRED, "the first ray's angle (rad)"),
        Param("{lidar}.max_angle", "double", REQUIRED, "the last ray's angle (rad)"),
        Param("{lidar}.angle_increment", "double", REQUIRED, "the angle between rays (rad)"),
        Param("{lidar}.range_min", "double", 0.0, "nearer is out of range (m)"),
        Param("{lidar}.range_max", "double", math.inf, "farther is out of range (m)"),
        Param("{lidar}.laserscan_topic", "string", "/scan", "where its scans are published"),
        Param("{lidar}.frame_name", "string", "{lidar}", "the frame of its scans"),
    )
    RATE = "lidar_publish_rate"

    def __init__(self, context: Context, name: str) -> None:
        groups = _rangefinders(context.world.model)
        super().__init__(context, name, lidar=list(groups))
        self.lidars = [self._lidar(lidar, found) for lidar, found in groups.items()]

    def _lidar(self, name: str, found: dict[int, int]) -> tuple[Any, ...]:
        config = {key: self.values[f"{name}.{key}"] for key in (
            "min_angle", "max_angle", "angle_increment", "range_min", "range_max",
            "laserscan_topic", "frame_name")}
        low, high, step = config["min_angle"], config["max_angle"], config["angle_increment"]
        count = int((high - low) / step) + 1 if step > 0 else 0
        addresses = [found.get(i, 0) for i in range(count)]
        publisher = self.node.create_publisher("sensor_msgs/msg/LaserScan",
                                               config["laserscan_topic"], 10)
        return (publisher, addresses, config["frame_name"], low, high, step,
                (config["range_min"], config["range_max"]))

    def publish(self, model: Any, data: Any, now: float) -> None:
        for publisher, addresses, frame, low, high, step, (near, far) in self.lidars:
            if not publisher.get_subscription_count():
                continue
            ranges = [float(data.sensordata[a]) for a in addresses]
            message = self.node.message(
                "sensor_msgs/msg/LaserScan", angle_min=low, angle_max=high,
                angle_increment=step, range_min=near, range_max=far,
                ranges=[r if near <= r <= far else -1.0 for r in ranges])
            message.header.frame_id = frame
            fill_stamp(message.header.stamp, now)
            publisher.publish(message)


def _rangefinders(model: Any) -> dict[str, dict[int, int]]:
    """The rangefinders named `<lidar>-<index>`: each lidar's sensordata address by index."""
    groups: dict[str, dict[int, int]] = {}
    for i in range(model.nsensor):
        if int(model.sensor_type[i]) != int(mujoco.mjtSensor.mjSENS_RANGEFINDER):
            continue
        name, dash, index = model.sensor(i).name.rpartition("-")
        if dash and index.isdigit():
            groups.setdefault(name, {})[int(index)] = int(model.sensor_adr[i])
    return groups


TYPES: dict[str, type[RosPlugin]] = {
    f"{PREFIX}HeartbeatPublisherPlugin": Heartbeat,
    f"{PREFIX}FreeJointStatePublisherPlugin": FreeJointStates,
    f"{PREFIX}BaseVelocityPlugin": BaseVelocity,
    f"{PREFIX}RangefinderLidarPlugin": RangefinderLidar,
    f"{PREFIX}ExternalWrenchPlugin": ExternalWrench,
    f"{PREFIX}Mujoco3dLidarPlugin": Mujoco3dLidar,
    f"{PREFIX}CameraPlugin": CameraPlugin,
}


def load_plugins(node: Any, world: Any, where: str, files: list[str] | None = None
                 ) -> list[RosPlugin]:
    """Every `mujoco_plugins.<name>.type` of the node's parameters, made (`files`: the
    parameter files, to name where a setting is written)."""
    names = sorted({k.split(".")[1] for k in node.parameters
                    if k.startswith("mujoco_plugins.") and k.endswith(".type")
                    and k.count(".") == 2})
    context = Context(node, world, where, list(files or []))
    plugins: list[RosPlugin] = []
    for name in names:
        kind = str(node.parameters[f"mujoco_plugins.{name}.type"])
        cls = TYPES.get(kind)
        if cls is None:
            raise LaunchError(f"{where}: mujoco_plugins.{name}.type: unknown plugin '{kind}'"
                              f"{did_you_mean(kind, list(TYPES))} (known: {', '.join(TYPES)})")
        plugins.append(cls(context, name))
        node.get_logger().info(f"mujoco plugin '{name}' ({kind.removeprefix(PREFIX)}) loaded")
    return plugins

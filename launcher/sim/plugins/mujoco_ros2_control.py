"""mujoco_ros2_control in the sim: controller_manager over the MJCF's own actuators
(MujocoSystemInterface, launcher/sim/mujoco_control/system.py), run in sim time at its
`update_rate` as mujoco_ros2_control runs it, with the nodes it makes:

  * `controller_manager` (the process's `--ros-args`: its YAML, the controllers' types);
  * `mujoco_ros2_control_node`: `/mujoco_actuators_states` (every MuJoCo joint, actuated or
    not), the floating base's odometry (`odom_free_joint_name`, on `odom_topic`), its services
    (mujoco_control/services.py) and its plugins (`mujoco_plugins.*` parameters,
    mujoco_control/ros_plugins.py). Its parameters are the process's and the
    `pids_config_file`'s.

Made by `ros2_control_node` (launcher/nodes/mujoco_ros2_control_node.py) with the server it
runs, not from a world file: it needs the server for pausing and stepping.
"""

from __future__ import annotations

from typing import Any

from launcher.bus import ros_args
from launcher.bus.node import Node
from launcher.control.description import Hardware
from launcher.control.hardware import make as make_mock
from launcher.control.manager import ControllerManager
from launcher.control.manager_services import ManagerServices
from launcher.control.yaml_places import key_place
from launcher.errors import LaunchError, did_you_mean
from launcher.sim import schedule
from launcher.sim.mjcf import PluginConfig
from launcher.sim.mujoco_control.actuators import pids_from
from launcher.sim.mujoco_control.ros_plugins import load_plugins
from launcher.sim.mujoco_control.services import SimServices
from launcher.sim.mujoco_control.system import MujocoSystem
from launcher.sim.plugins import Plugin

STATE_TOPIC = "/mujoco_actuators_states"


class MujocoRos2Control(Plugin):
    def __init__(self, world: Any, server: Any, blocks: list[Hardware], argv: list[str],
                 config: PluginConfig, started: bool = False) -> None:
        """`started`: the model starts from a keyframe or a saved state, not from the state
        interfaces' initial values."""
        super().__init__(world, None, config)
        self.started = started
        self.server, self.blocks, self.argv = server, blocks, argv
        self.block = next(b for b in blocks if b.is_mujoco)
        self.plugins: list[Any] = []

    def load(self) -> None:
        sim_node = self.server.node
        files = [s for kind, s in ros_args.parse(self.argv).parameter_sources if kind == "file"]
        base = self.argv if "--ros-args" in self.argv else ["--ros-args", *self.argv]
        now = lambda: float(self.data.time)  # noqa: E731  # (the sim's own time)
        self.node = Node("controller_manager", argv=[*base, "-p", "use_sim_time:=true"],
                         session=sim_node.session, sim_time=now)
        self.node.spin_with(sim_node)
        extra = ["-p", "use_sim_time:=true"]
        pid_file = self.block.params.get("pids_config_file", "").strip()
        pid_files = [pid_file] if pid_file else []
        for path in pid_files:
            extra = ["--params-file", path, *extra]
        self.mujoco_node = Node("mujoco_ros2_control_node", argv=[*base, *extra],
                                session=sim_node.session, sim_time=now)
        self.mujoco_node.spin_with(sim_node)
        log = self.mujoco_node.get_logger()
        pids = pids_from(self.mujoco_node.parameters)
        self._check_pids(pids, pid_files, log)
        self.system = MujocoSystem(self.block, self.model, self.data, pids, log,
                                   initial=not self.started)
        components = [self.system if b is self.block else make_mock(b) for b in self.blocks]
        self.manager = ControllerManager(self.node, components, files)
        ManagerServices(self.manager)
        self.update_rate = self.manager.update_rate
        self.states = self.mujoco_node.create_publisher("sensor_msgs/msg/JointState",
                                                        STATE_TOPIC, 100)
        self._odometry(log)
        self.services = SimServices(self.mujoco_node, self.server, self.sim, self._after_reset)
        self.plugins = load_plugins(self.mujoco_node, self.sim, self.config.where,
                                    [*files, *pid_files])
        self.every_step = [p for p in self.plugins if hasattr(p, "step")]
        self.cycle = _Cycle()
        self.next_update = 0.0
        log.info(f"MuJoCo hardware '{self.block.name}': {len(self.system.actuators)} "
                 f"actuator(s) and passive joint(s), controller_manager at "
                 f"{self.update_rate} Hz")

    def _check_pids(self, pids: dict[str, Any], files: list[str], log: Any) -> None:
        """A PID names the MJCF joint its actuator moves; one for a joint the model does not
        have drives nothing, which is said (a file shared by several models may hold
        others')."""
        model = self.model
        names = [model.joint(i).name for i in range(model.njnt)]
        names += [model.actuator(i).name for i in range(model.nu)]
        for mode, gains in pids.items():
            for joint in gains:
                if joint not in names:
                    where = key_place(files, "/**", f"pid_gains.{mode}.{joint}") or \
                        (files[0] if files else "parameters")
                    log.warning(f"{where}: pid_gains.{mode}.{joint}: the MuJoCo model has no "
                                f"joint or actuator '{joint}'"
                                f"{did_you_mean(joint, names)}; this PID drives nothing")

    def _odometry(self, log: Any) -> None:
        import mujoco

        model = self.model
        name = self.block.params.get("odom_free_joint_name", "floating_base_joint")
        self.odometry = None
        joint = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
        if joint < 0:
            return
        if model.jnt_type[joint] != mujoco.mjtJoint.mjJNT_FREE:
            raise LaunchError(f"{self.block.where}: odom_free_joint_name '{name}' is not a "
                              f"free joint: its floating base odometry needs one")
        topic = self.block.params.get("odom_topic", "/simulator/floating_base_state")
        self.odometry = (self.mujoco_node.create_publisher("nav_msgs/msg/Odometry", topic, 100),
                         int(model.jnt_qposadr[joint]), int(model.jnt_dofadr[joint]),
                         model.body(int(model.jnt_bodyid[joint])).name)
        log.info(f"floating base odometry of joint '{name}' on {topic}")

    def _after_reset(self) -> None:
        self.system.sync_commands()

    def bind(self, model: Any, data: Any) -> None:
        self.model, self.data = model, data
        if hasattr(self, "system"):
            self.system.bind(model, data)

    def post_step(self, model: Any, data: Any) -> None:
        now = float(data.time)
        for plugin in self.every_step:  # (velocity overrides: held on every step)
            plugin.step(model, data)
        due = schedule.tick(self.cycle, now, self.update_rate)
        self.next_update = 0.0 if self.every_step else self.cycle.next_update
        if not due:
            return
        for plugin in self.plugins:  # (before the controllers, as mujoco_ros2_control's)
            plugin.update(model, data, now)
        self.manager.update(now)
        if self.states.get_subscription_count():
            self._publish_states(now)
        if self.odometry is not None and self.odometry[0].get_subscription_count():
            self._publish_odometry(now)

    def _publish_states(self, now: float) -> None:
        node, actuators = self.mujoco_node, self.system.actuators
        message = node.message("sensor_msgs/msg/JointState")
        message.header.stamp = node.message("builtin_interfaces/msg/Time",
                                            **_stamp(now))
        message.name = [a.joint for a in actuators]
        message.position = [a.position for a in actuators]
        message.velocity = [a.velocity for a in actuators]
        message.effort = [a.effort for a in actuators]
        self.states.publish(message)

    def _publish_odometry(self, now: float) -> None:
        publisher, qpos, dof, child = self.odometry
        data, node = self.data, self.mujoco_node
        message = node.message("nav_msgs/msg/Odometry")
        message.header.stamp = node.message("builtin_interfaces/msg/Time", **_stamp(now))
        message.header.frame_id, message.child_frame_id = "odom", child
        p, v = data.qpos, data.qvel
        pose, twist = message.pose.pose, message.twist.twist
        pose.position.x, pose.position.y, pose.position.z = map(float, p[qpos:qpos + 3])
        (pose.orientation.w, pose.orientation.x, pose.orientation.y,
         pose.orientation.z) = map(float, p[qpos + 3:qpos + 7])
        twist.linear.x, twist.linear.y, twist.linear.z = map(float, v[dof:dof + 3])
        twist.angular.x, twist.angular.y, twist.angular.z = map(float, v[dof + 3:dof + 6])
        publisher.publish(message)

    def reset(self) -> None:
        self.next_update = 0.0
        if hasattr(self, "cycle"):
            self.cycle.next_update = 0.0
        if hasattr(self, "system"):
            self.system.hold()

    def close(self) -> None:
        for plugin in self.plugins:
            plugin.close()
        if hasattr(self, "manager"):
            self.manager.shutdown()
        for node in (getattr(self, "node", None), getattr(self, "mujoco_node", None)):
            if node is not None:
                node.destroy_node()


class _Cycle:
    """When the next control cycle is due (schedule.tick's owner)."""

    next_update = 0.0


def _stamp(seconds: float) -> dict[str, int]:
    from launcher.bus.wire import split_time

    sec, nanosec = split_time(seconds)
    return {"sec": sec, "nanosec": nanosec}

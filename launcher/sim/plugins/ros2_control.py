"""gz_ros2_control in the sim: the `<ros2_control>` blocks of the robot's URDF as hardware
over MuJoCo's joints, and controller_manager (launcher/control) run in sim time at its
`update_rate`, as gz_ros2_control runs it inside Gazebo.

The plugin is named as users name it: `gz_ros2_control-system` (class
`gz_ros2_control::GazeboSimROS2ControlPlugin`), `ign_ros2_control-system`, or Gazebo
classic's `libgazebo_ros2_control.so`. Its elements: `<parameters>` (one or several YAML
files: the manager's and the controllers' parameters), `<ros><namespace>` and
`<ros><remapping>`, `<controller_manager_name>` (or `<controller_manager_prefix_node_name>`,
which makes `<prefix>_controller_manager`), `<hold_joints>` (true) and
`<position_proportional_gain>` (0.1). `<robot_param>` and `<robot_param_node>` are accepted:
the hardware is read from the robot the plugin came with, which is the same description.

Each commanded joint gets one MuJoCo actuator, switched between a velocity servo and a motor
as the claimed command interface needs, which is what gz_ros2_control asks of Gazebo:
  * velocity: the servo tracks the command (gz: JointVelocityCmd);
  * position: as gz_ros2_control, a velocity of `gain · (command − position) · update_rate`
    (so a user's tuned `position_proportional_gain` behaves the same);
  * effort: the motor applies the command (gz: JointForceCmd);
  * none claimed: the joint holds still (a zero velocity) unless `hold_joints` is false;
  * mimic joints follow their leader with a velocity of `(leader·multiplier − position) ·
    update_rate`.
The servo's gain comes from the joint's own inertia, so it settles in about SERVO_TIME of
sim time whatever the robot's size; the joint's effort limit (URDF `<limit effort>`) bounds
it. Commands are clamped to the interface's `min`/`max`; one that is NaN or infinite is not
applied (the joint keeps the last good one).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from launcher.bus.node import Node
from launcher.control.description import Hardware, parse
from launcher.control.hardware import make as make_mock
from launcher.control.manager import ControllerManager
from launcher.control.manager_services import ManagerServices
from launcher.control.resources import Component
from launcher.errors import LaunchError
from launcher.sim import schedule
from launcher.sim.plugins import Plugin, PluginError
from launcher.sim.plugins.gazebo_ros import under

SERVO_TIME = 0.005  # s: how fast a joint's velocity servo settles
VELOCITY, POSITION, EFFORT = "velocity", "position", "effort"


class SimSystem(Component):
    """GazeboSimSystem over MuJoCo: reads qpos/qvel/actuator forces, writes the actuators."""

    def __init__(self, info: Hardware, plugin: GzRos2Control) -> None:
        super().__init__(info)
        self.plugin = plugin
        self.joints = list(info.joints)
        self.modes: dict[str, set[str]] = {j.name: set() for j in self.joints}
        self.actuated = [j.name for j in self.joints if j.command_interfaces or j.mimic]
        self.initial = {j.name: next((i.initial_value for i in j.state_interfaces
                                      if i.name == POSITION and i.initial_value is not None),
                                     None) for j in self.joints}
        self.gain: dict[str, float] = {}

    def bind(self, model: Any, data: Any, prefix: str) -> None:
        self.data, self.model = data, model
        self.rows = []
        for joint in self.joints:
            index = model.joint(prefix + joint.name).id
            dof = int(model.jnt_dofadr[index])
            actuator = model.actuator(f"{prefix}ros2_control_{joint.name}").id \
                if joint.name in self.actuated else -1
            self.rows.append((joint.name, int(model.jnt_qposadr[index]), dof, actuator,
                              self.states.get(f"{joint.name}/position"),
                              self.states.get(f"{joint.name}/velocity"),
                              self.states.get(f"{joint.name}/effort"),
                              self.commands.get(f"{joint.name}/position"),
                              self.commands.get(f"{joint.name}/velocity"),
                              self.commands.get(f"{joint.name}/effort")))
            if actuator >= 0:
                inertia = float(model.dof_M0[dof]) or 1.0
                self.gain[joint.name] = inertia / SERVO_TIME
        self.by_name = {row[0]: row for row in self.rows}
        self.sensors = [(sensor, None) for sensor in self.info.sensors]
        self.mimics = [(self.by_name[j.name], self.by_name.get(j.mimic[0]), j.mimic[1],
                        j.mimic[2]) for j in self.joints if j.mimic]
        for name in self.actuated:
            self._apply_mode(name)

    def place_initial(self) -> None:
        """initial_value of the position state interfaces (gz: JointPositionReset)."""
        for name, value in self.initial.items():
            if value is not None:
                row = self.by_name[name]
                self.data.qpos[row[1]] = value
                self.data.qvel[row[2]] = 0.0
                if row[7] is not None:
                    row[7].value = value
        self.read(0.0, 0.0)

    def _mode(self, name: str) -> str:
        modes = self.modes[name]
        for mode in (VELOCITY, POSITION, EFFORT):  # gz_ros2_control's order
            if mode in modes:
                return mode
        return ""

    def _apply_mode(self, name: str) -> None:
        row = self.by_name[name]
        actuator = row[3]
        if actuator < 0:
            return
        model = self.model
        if self._mode(name) == EFFORT:
            model.actuator_gainprm[actuator, 0] = 1.0
            model.actuator_biasprm[actuator, 2] = 0.0
        else:
            gain = self.gain[name]
            model.actuator_gainprm[actuator, 0] = gain
            model.actuator_biasprm[actuator, 2] = -gain
        self.data.ctrl[actuator] = 0.0

    def switch_modes(self, start: list[str], stop: list[str]) -> None:
        for names, add in ((stop, False), (start, True)):
            for name in names:
                joint, _, kind = name.rpartition("/")
                if joint in self.modes:
                    (self.modes[joint].add if add else self.modes[joint].discard)(kind)
                    self._apply_mode(joint)

    def _sensor_plugin(self, name: str) -> Any:
        for plugin in self.plugin.entity.plugins:
            config = plugin.config
            if getattr(config, "kind", None) is not None and config.name == name:
                return plugin
        return None

    def _read_sensors(self) -> None:
        """A `<sensor>` block's state interfaces from the robot's sim sensor of that name
        (`orientation.x`, `angular_velocity.z`, `force.y`, …), as gz_ros2_control reads them."""
        for index, (sensor, plugin) in enumerate(self.sensors):
            if plugin is None:
                plugin = self._sensor_plugin(sensor.name)
                if plugin is None:
                    self.plugin.warn_once(
                        f"sensor {sensor.name}",
                        f"{self.info.where}: ros2_control sensor '{sensor.name}' has no sim "
                        f"sensor of that name on the robot (a <gazebo reference=…><sensor "
                        f"name=\"{sensor.name}\">); its state interfaces stay 0")
                    continue
                self.sensors[index] = (sensor, plugin)
            message = plugin.measure(self.model, self.data)
            for interface in sensor.state_interfaces:
                value = _field(message, interface.name)
                if value is not None:
                    self.states[f"{sensor.name}/{interface.name}"].value = value

    def read(self, time: float, period: float) -> None:
        if self.sensors:
            self._read_sensors()
        data = self.data
        qpos, qvel, force = data.qpos, data.qvel, data.qfrc_actuator
        for row in self.rows:
            if row[4] is not None:
                row[4].value = float(qpos[row[1]])
            if row[5] is not None:
                row[5].value = float(qvel[row[2]])
            if row[6] is not None:
                row[6].value = float(force[row[2]])

    def write(self, time: float, period: float) -> None:
        data = self.data
        ctrl, qpos = data.ctrl, data.qpos
        rate = self.plugin.update_rate
        gain = self.plugin.position_gain
        for row in self.rows:
            actuator = row[3]
            if actuator < 0:
                continue
            mode = self._mode(row[0])
            if mode == VELOCITY:
                value = _clamped(row[8])
                if value is not None:
                    ctrl[actuator] = value
            elif mode == POSITION:
                value = _clamped(row[7])
                if value is not None:
                    ctrl[actuator] = -gain * (qpos[row[1]] - value) * rate
            elif mode == EFFORT:
                value = _clamped(row[9])
                if value is not None:
                    ctrl[actuator] = value
            elif self.plugin.hold_joints:
                ctrl[actuator] = 0.0
        for mimic, leader, multiplier, offset in self.mimics:
            if leader is not None and mimic[3] >= 0:
                error = qpos[mimic[1]] - (qpos[leader[1]] * multiplier + offset)
                ctrl[mimic[3]] = -error * rate


def _field(message: Any, name: str) -> float | None:
    """`orientation.x` of an IMU message, `force.y` of a wrench (under `wrench`)."""
    for root in (message, getattr(message, "wrench", None)):
        value = root
        for part in name.split("."):
            value = getattr(value, part, None)
            if value is None:
                break
        if isinstance(value, float | int):
            return float(value)
    return None


def _clamped(handle: Any) -> float | None:
    if handle is None:
        return None
    value = handle.value
    if not math.isfinite(value):
        return None
    return min(max(value, handle.low), handle.high)


class GzRos2Control(Plugin):
    def prepare(self, spec: Any) -> None:
        import mujoco

        text = self.config.robot
        label = self.config.where.rsplit(":", 1)[0]
        if not text:
            raise PluginError(f"{self.config.where}: plugin {self.label}: gz_ros2_control "
                              f"reads <ros2_control> from a URDF robot description; this one "
                              f"came with no URDF")
        try:
            self.blocks = parse(text, label)
        except LaunchError as exc:
            raise PluginError(str(exc)) from None
        if not self.blocks:
            raise PluginError(f"{self.config.where}: plugin {self.label}: the robot has no "
                              f"<ros2_control> block: there is no hardware to control")
        self.files = self.texts("parameters")
        if not self.files:
            raise PluginError(f"{self.config.where}: plugin {self.label}: no <parameters> "
                              f"file: gz_ros2_control needs the controller manager's YAML")
        for path in self.files:
            if not Path(path).is_file():
                raise PluginError(f"{self.config.where}: plugin {self.label}: <parameters> "
                                  f"file '{path}' does not exist")
        joints = self.joint_names(spec)
        for block in self.blocks:
            if not block.is_sim:
                continue
            for joint in block.joints:
                if joint.name not in joints:
                    raise PluginError(f"{block.where}: <ros2_control name=\"{block.name}\">: "
                                      f"joint '{joint.name}' is not a moving joint of the "
                                      f"simulated robot (joints: {', '.join(joints)})")
                if joint.command_interfaces or joint.mimic:
                    actuator = spec.add_actuator(name=self.in_spec(f"ros2_control_{joint.name}"),
                                                 target=self.in_spec(joint.name),
                                                 trntype=mujoco.mjtTrn.mjTRN_JOINT)
                    actuator.set_to_velocity(kv=1.0)  # the gain is set from the joint at bind
        self.hold_joints = (self.text("hold_joints", "true") or "true").lower() \
            not in ("false", "0")
        self.position_gain = self.number("position_proportional_gain", 0.1)
        ros = self.config.element.find("ros")
        self.namespace = ""
        self.remaps: list[str] = []
        if ros is not None:
            self.namespace = (ros.findtext("namespace") or "").strip()
            self.remaps = [(r.text or "").strip() for r in ros.findall("remapping") if r.text]
        name = self.text("controller_manager_name") or "controller_manager"
        prefix = self.text("controller_manager_prefix_node_name")
        self.manager_name = f"{prefix}_controller_manager" if prefix else name
        self.placed = False

    def load(self) -> None:
        sim_node = self.sim.transport.node
        argv = ["--ros-args"]
        for path in self.files:
            argv += ["--params-file", path]
        argv += ["-p", "use_sim_time:=true"]
        for remap in self.remaps:
            argv += ["-r", remap]
        namespace = under(self.config.namespace, self.namespace) \
            if self.namespace or self.config.namespace else ""
        self.node = Node(self.manager_name, namespace=namespace, argv=argv,
                         session=sim_node.session, sim_time=lambda: float(self.data.time))
        self.node.spin_with(sim_node)
        self.components = [SimSystem(b, self) if b.is_sim else make_mock(b) for b in self.blocks]
        try:
            self.manager = ControllerManager(self.node, self.components, self.files, self.remaps)
            ManagerServices(self.manager)
        except LaunchError:
            self.node.destroy_node()
            raise
        self.update_rate = self.manager.update_rate
        self.node.get_logger().info(
            f"controller_manager of entity '{self.entity.name}': {len(self.components)} "
            f"hardware component(s), update rate {self.update_rate} Hz")
        for component in self.components:
            if isinstance(component, SimSystem):
                component.bind(self.model, self.data, f"{self.entity.name}/")
                if not self.placed:
                    component.place_initial()
        self.placed = True
        self.next_update = 0.0

    def bind(self, model: Any, data: Any) -> None:
        self.model, self.data = model, data
        for component in getattr(self, "components", []):
            if isinstance(component, SimSystem):
                component.bind(model, data, f"{self.entity.name}/")

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        if schedule.tick(self, now, self.update_rate):
            self.manager.update(now)

    def reset(self) -> None:
        self.next_update = 0.0
        for component in getattr(self, "components", []):
            if isinstance(component, SimSystem):
                component.place_initial()

    def close(self) -> None:
        if hasattr(self, "manager"):
            self.manager.shutdown()
        if hasattr(self, "node"):
            self.node.destroy_node()


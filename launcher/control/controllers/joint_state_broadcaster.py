"""joint_state_broadcaster/JointStateBroadcaster: every joint's position, velocity and effort
on `joint_states` (sensor_msgs/JointState) and every interface on `dynamic_joint_states`
(control_msgs/DynamicJointState), in the manager's namespace.

Parameters (ros2_controllers'): `joints` and `interfaces` (both given: only those; else every
state interface), `use_local_topics` (publish under `~/`), `map_interface_to_joint_state`
(`position`/`velocity`/`effort` → another interface's name), `extra_joints` (published at 0).
A joint lacking one of position, velocity and effort has NaN there in JointState, as
ros2_controllers fills it; extra joints are at 0. Nothing is built while no one subscribes.
"""

from __future__ import annotations

from typing import Any

from launcher.bus.declarations import Param
from launcher.bus.wire import JointStateLayout, split_time
from launcher.control.controller import Controller, ControllerError

KINDS = ("position", "velocity", "effort")
NAN = float("nan")


class JointStateBroadcaster(Controller):
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("joints", "string_array", [], "only these joints (with interfaces)"),
        Param("interfaces", "string_array", [], "only these interfaces (with joints)"),
        Param("use_local_topics", "bool", False, "publish under ~/ (the controller's name)"),
        *(Param(f"map_interface_to_joint_state.{kind}", "string", kind,
                f"the interface published as the JointState's {kind}") for kind in KINDS),
        Param("extra_joints", "string_array", [], "joints published at 0 besides"),
    )

    def on_init(self) -> None:
        p = self.read_parameters("joints", "interfaces")
        self.joints, self.interfaces = p["joints"], p["interfaces"]
        if bool(self.joints) != bool(self.interfaces):
            raise ControllerError(self._at(
                f"controller '{self.name}': 'joints' and 'interfaces' must be given together "
                f"(one alone is ignored by ros2_controllers and is surely a mistake)"))

    def state_interfaces(self) -> list[str] | None:
        if self.joints:
            return [f"{j}/{i}" for j in self.joints for i in self.interfaces]
        return None

    def on_configure(self) -> None:
        p = self.read_parameters()
        prefix = "~/" if p["use_local_topics"] else ""
        self.mapping = {k: p[f"map_interface_to_joint_state.{k}"] for k in KINDS}
        self.extra = p["extra_joints"]
        self.joint_pub = self.node.create_publisher("sensor_msgs/msg/JointState",
                                                    f"{prefix}joint_states", 10)
        self.dynamic_pub = self.node.create_publisher("control_msgs/msg/DynamicJointState",
                                                      f"{prefix}dynamic_joint_states", 10)

    def on_activate(self) -> None:
        order: list[str] = []
        for handle in self.states.values():
            if handle.prefix not in order:
                order.append(handle.prefix)
        self.order = order
        by_joint: dict[str, dict[str, Any]] = {j: {} for j in order}
        for handle in self.states.values():
            by_joint[handle.prefix][handle.interface] = handle
        self.by_joint = by_joint
        # the joints of JointState: those with a position, velocity or effort
        self.joint_names = [j for j in order
                            if any(self.mapping[k] in by_joint[j] for k in KINDS)]
        self.columns = [[by_joint[j].get(self.mapping[k]) for j in self.joint_names]
                        for k in KINDS]
        self.layout = JointStateLayout(self.joint_names + self.extra)

    def on_cleanup(self) -> None:
        self.joint_pub.destroy()
        self.dynamic_pub.destroy()

    def update(self, time: float, period: float) -> None:
        make = self.make
        if self.joint_pub.get_subscription_count():
            extra = [0.0] * len(self.extra)
            values = [[h.value if h is not None else NAN for h in column] + extra
                      for column in self.columns]
            self.joint_pub.publish_raw(self.layout.pack(*split_time(time), *values))
        if self.dynamic_pub.get_subscription_count():
            self.dynamic_pub.publish(make(
                "control_msgs/msg/DynamicJointState", header=self.header(time),
                joint_names=self.order, interface_values=[make(
                    "control_msgs/msg/InterfaceValue", interface_names=list(self.by_joint[j]),
                    values=[h.value for h in self.by_joint[j].values()]) for j in self.order]))

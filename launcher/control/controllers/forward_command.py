"""forward_command_controller/ForwardCommandController and the JointGroup controllers of
position_controllers, velocity_controllers and effort_controllers: the numbers of a
std_msgs/Float64MultiArray on `~/commands`, one per joint, written to the joints' command
interface (`interface_name`; fixed by the JointGroup types). A message of the wrong size, or
holding NaN or an infinity, is refused with an error and the joints keep their command; until
the first message the hardware keeps what it had (a position holds).
"""

from __future__ import annotations

from typing import Any

from launcher.bus.declarations import REQUIRED, Param
from launcher.control.controller import Controller


class ForwardCommandController(Controller):
    interface = ""  # fixed by the JointGroup types
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("joints", "string_array", REQUIRED, "the commanded joints, in the commands' order",
              non_empty=True),
        Param("interface_name", "string", REQUIRED,
              "their command interface (the JointGroup types fix it)"),
    )

    def on_init(self) -> None:
        p = self.read_parameters("joints", *(() if self.interface else ("interface_name",)))
        self.joints = p["joints"]
        self.interface_name = self.interface or p["interface_name"]

    def command_interfaces(self) -> list[str]:
        return [f"{j}/{self.interface_name}" for j in self.joints]

    def on_configure(self) -> None:
        self.pending: list[float] | None = None
        self.subscription = self.node.create_subscription(
            "std_msgs/msg/Float64MultiArray", "~/commands", self.on_commands, 10)

    def on_cleanup(self) -> None:
        self.subscription.destroy()

    def on_activate(self) -> None:
        self.pending = None

    def on_commands(self, message: Any) -> None:
        values = list(message.data)
        if len(values) != len(self.joints):
            self.node.get_logger().error(
                f"command size ({len(values)}) does not match number of interfaces "
                f"({len(self.joints)}): refused")
            return
        if self.refuse_non_finite(values, "a command on ~/commands"):
            return
        self.pending = values

    def update(self, time: float, period: float) -> None:
        values = self.pending
        if values is None:
            return
        for handle, value in zip(self.commands, values, strict=True):
            handle.value = value


class JointGroupPositionController(ForwardCommandController):
    interface = "position"


class JointGroupVelocityController(ForwardCommandController):
    interface = "velocity"


class JointGroupEffortController(ForwardCommandController):
    interface = "effort"

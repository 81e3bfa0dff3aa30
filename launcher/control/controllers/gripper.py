"""Gripper controllers with an action, as ros2_controllers': `position_controllers/` and
`effort_controllers/GripperActionController` (gripper_action_controllers: `~/gripper_cmd`,
control_msgs/GripperCommand: a position and a max effort) and
`parallel_gripper_action_controller/GripperActionController` (`~/gripper_cmd`,
control_msgs/ParallelGripperCommand: a JointState command).

Parameters: `joint` (the one commanded joint), `action_monitor_rate` (20 Hz), `goal_tolerance`
(0.01), `allow_stalling` (false), `stall_velocity_threshold` (0.001), `stall_timeout` (1 s),
and for the effort type the PID `gains.<joint>.p|i|d`. A goal succeeds when the joint is within
`goal_tolerance` of the command; a gripper that stops short (an object in it) for
`stall_timeout` is stalled: the goal succeeds if stalling is allowed, else aborts. A new goal
preempts the running one; a cancel holds the joint where it is. A command that is NaN or
infinite is refused.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.bus.action_server import ActionServer, Goal
from launcher.bus.declarations import REQUIRED, Param
from launcher.control.controller import Controller


class GripperActionController(Controller):
    action_type = "control_msgs/action/GripperCommand"
    command_kind = "position"
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("joint", "string", REQUIRED, "the commanded joint"),
        Param("action_monitor_rate", "double", 20.0, "goal checks a second", minimum=0.1),
        Param("goal_tolerance", "double", 0.01, "how near the command a goal succeeds",
              minimum=0.0),
        Param("allow_stalling", "bool", False, "a stalled gripper succeeds (false: aborts)"),
        Param("stall_velocity_threshold", "double", 0.001,
              "below this speed the gripper is stopped"),
        Param("stall_timeout", "double", 1.0, "s stopped short before it is stalled"),
        Param("gains.{joint}.p", "double", 0.0, "the effort type's PID: proportional"),
        Param("gains.{joint}.i", "double", 0.0, "integral"),
        Param("gains.{joint}.d", "double", 0.0, "derivative"),
    )

    def on_init(self) -> None:
        self.joint = self.read_parameters("joint")["joint"]

    def command_interfaces(self) -> list[str]:
        return [f"{self.joint}/{self.command_kind}"]

    def state_interfaces(self) -> list[str]:
        return [f"{self.joint}/position", f"{self.joint}/velocity"]

    def on_configure(self) -> None:
        p = self.read_parameters()
        self.monitor_period = 1.0 / p["action_monitor_rate"]
        self.tolerance, self.allow_stalling = p["goal_tolerance"], p["allow_stalling"]
        self.stall_speed = p["stall_velocity_threshold"]
        self.stall_timeout = p["stall_timeout"]
        self.gains = tuple(p[f"gains.{self.joint}.{k}"] for k in "pid")
        self.now = 0.0
        self.action = ActionServer(self.node, self.action_type, "~/gripper_cmd", self.accept,
                                   self.on_goal, self.on_cancel, lambda: self.stamp(self.now))

    def on_cleanup(self) -> None:
        self.action.destroy()

    def on_activate(self) -> None:
        self.position = self.states[f"{self.joint}/position"]
        self.velocity = self.states[f"{self.joint}/velocity"]
        self.target = self.position.value
        self.max_effort = math.inf
        self.goal: Goal | None = None
        self.moving_since = 0.0
        self.integral, self.next_feedback = 0.0, 0.0

    def on_deactivate(self) -> None:
        if self.goal is not None and self.goal.active:
            self.goal.abort(self._result(False, False))
        self.goal = None

    def _command(self, goal: Any) -> tuple[float, float]:
        command = goal.command
        if self.action_type.endswith("GripperCommand") and hasattr(command, "max_effort"):
            return float(command.position), float(command.max_effort)
        if list(command.name) and self.joint not in list(command.name):
            return math.nan, math.nan
        position = list(command.position)
        effort = list(command.effort)
        return (float(position[0]) if position else math.nan,
                float(effort[0]) if effort else 0.0)

    def accept(self, goal: Any) -> bool:
        if not self.is_active:
            return False
        position, effort = self._command(goal)
        if not (math.isfinite(position) and math.isfinite(effort)):
            self.node.get_logger().error(f"gripper goal refused: the command must name "
                                         f"'{self.joint}' with a finite position and effort")
            return False
        return True

    def on_goal(self, goal: Goal) -> None:
        if self.goal is not None and self.goal.active:
            self.goal.abort(self._result(False, False))
        position, effort = self._command(goal.request)
        self.target = position
        self.max_effort = effort if effort > 0 else math.inf
        self.goal, self.moving_since = goal, self.now

    def on_cancel(self, goal: Goal) -> None:
        if goal is self.goal:
            self.target = self.position.value
            goal.canceled(self._result(False, False))
            self.goal = None

    def _result(self, stalled: bool, reached: bool) -> Any:
        if self.action_type.endswith("ParallelGripperCommand"):
            return self.make(f"{self.action_type}_Result", state=self._state(),
                             stalled=stalled, reached_goal=reached)
        return self.make(f"{self.action_type}_Result", position=self.position.value,
                         effort=self.commands[0].value if self.command_kind == "effort"
                         else 0.0, stalled=stalled, reached_goal=reached)

    def _state(self) -> Any:
        return self.make("sensor_msgs/msg/JointState", name=[self.joint],
                         position=[self.position.value], velocity=[self.velocity.value],
                         effort=[])

    def update(self, time: float, period: float) -> None:
        self.now = time
        error = self.target - self.position.value
        handle = self.commands[0]
        if self.command_kind == "position":
            handle.value = self.target
        else:
            p, i, d = self.gains
            self.integral += error * period
            force = p * error + i * self.integral - d * self.velocity.value
            handle.value = max(-self.max_effort, min(self.max_effort, force))
        goal = self.goal
        if goal is None or not goal.active:
            return
        if abs(error) < self.tolerance:
            goal.succeed(self._result(False, True))
            self.goal = None
            return
        if abs(self.velocity.value) > self.stall_speed:
            self.moving_since = time
        elif time - self.moving_since > self.stall_timeout:
            self.target = self.position.value  # hold where it stopped
            if self.allow_stalling:
                goal.succeed(self._result(True, False))
            else:
                goal.abort(self._result(True, False))
            self.goal = None
            return
        if time >= self.next_feedback:
            self.next_feedback = time + self.monitor_period
            if self.action_type.endswith("ParallelGripperCommand"):
                goal.feedback(self.make(f"{self.action_type}_Feedback", state=self._state()))
            else:
                goal.feedback(self.make(f"{self.action_type}_Feedback",
                                        position=self.position.value, effort=handle.value,
                                        stalled=False, reached_goal=False))


class EffortGripperActionController(GripperActionController):
    command_kind = "effort"


class ParallelGripperActionController(GripperActionController):
    action_type = "control_msgs/action/ParallelGripperCommand"

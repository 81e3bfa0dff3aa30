"""joint_trajectory_controller/JointTrajectoryController: trajectories from `~/joint_trajectory`
(trajectory_msgs/JointTrajectory) and goals of `~/follow_joint_trajectory`
(control_msgs/FollowJointTrajectory), sampled each update (trajectory.py) and written to the
joints' command interfaces; `~/controller_state` (control_msgs/JointTrajectoryControllerState)
says the reference, feedback, error and output.

Parameters (ros2_controllers'): `joints`, `command_joints`, `command_interfaces` (position,
velocity, effort; position may come with velocity and acceleration), `state_interfaces`,
`allow_partial_joints_goal`, `interpolation_method` (splines / none), `action_monitor_rate`,
`open_loop_control`, `gains.<joint>.p|i|d|ff_velocity_scale` (for velocity or effort command
interfaces), `constraints.stopped_velocity_tolerance`, `constraints.goal_time`,
`constraints.<joint>.trajectory` (path) and `.goal` tolerances. A goal's own tolerances
override the configured ones. A new trajectory replaces the one running; an empty one stops
the joints where they are. A trajectory naming other joints, with times that do not increase,
or with NaN, is refused (a goal with INVALID_GOAL / INVALID_JOINTS) and the joints hold.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.bus.action_server import ActionServer, Goal
from launcher.bus.declarations import REQUIRED, Param
from launcher.bus.wire import stamp_seconds
from launcher.control.controller import Controller, ControllerError
from launcher.control.controllers.trajectory import Point, Trajectory, validate

ACTION = "control_msgs/action/FollowJointTrajectory"
SUCCESSFUL, INVALID_GOAL, INVALID_JOINTS, OLD_HEADER_TIMESTAMP = 0, -1, -2, -3
PATH_TOLERANCE_VIOLATED, GOAL_TOLERANCE_VIOLATED = -4, -5
ALLOWED = {"position", "velocity", "acceleration", "effort"}


class JointTrajectoryController(Controller):
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("joints", "string_array", REQUIRED, "the joints the trajectories name",
              non_empty=True, read_only=True),
        Param("command_joints", "string_array", [],
              "the joints commanded, in the order of 'joints' (empty: the same)",
              read_only=True),
        Param("command_interfaces", "string_array", REQUIRED,
              "what is commanded: position, velocity, acceleration, effort", non_empty=True,
              read_only=True),
        Param("state_interfaces", "string_array", REQUIRED,
              "what is read: position, and velocity, acceleration", non_empty=True,
              read_only=True),
        Param("allow_partial_joints_goal", "bool", False, "a goal may name some joints"),
        Param("interpolation_method", "string", "splines", "splines, or none", read_only=True,
              choices=("splines", "none")),
        Param("open_loop_control", "bool", False, "follow the plan, not the state"),
        Param("action_monitor_rate", "double", 20.0, "goal checks a second", minimum=0.1,
              read_only=True),
        Param("constraints.stopped_velocity_tolerance", "double", 0.01,
              "below this speed the goal's joints have stopped"),
        Param("constraints.goal_time", "double", 0.0,
              "s after the end a goal may take to be reached (0: any)", minimum=0.0),
        Param("constraints.{joints}.trajectory", "double", 0.0,
              "the largest error on the way (0: any)"),
        Param("constraints.{joints}.goal", "double", 0.0,
              "the largest error at the end (0: any)"),
        Param("gains.{joints}.p", "double", 0.0, "velocity or effort commands' PID: "
                                                 "proportional"),
        Param("gains.{joints}.i", "double", 0.0, "integral"),
        Param("gains.{joints}.d", "double", 0.0, "derivative"),
        Param("gains.{joints}.ff_velocity_scale", "double", 0.0,
              "the planned velocity's share of the command"),
    )

    def on_init(self) -> None:
        p = self.read_parameters("joints", "command_joints", "command_interfaces",
                                 "state_interfaces")
        self.joints = p["joints"]
        self.command_joints = p["command_joints"] or self.joints
        self.command_kinds, self.state_kinds = p["command_interfaces"], p["state_interfaces"]
        for kinds, what in ((self.command_kinds, "command_interfaces"),
                            (self.state_kinds, "state_interfaces")):
            wrong = [k for k in kinds if k not in ALLOWED]
            if wrong:
                raise ControllerError(self._at(
                    f"controller '{self.name}': '{what}' has {wrong}; expected some of "
                    f"position, velocity, acceleration, effort"))
        if "position" not in self.state_kinds:
            raise ControllerError(self._at(f"controller '{self.name}': 'state_interfaces' "
                                           f"must hold 'position'"))
        if len(self.command_joints) != len(self.joints):
            raise ControllerError(self._at(f"controller '{self.name}': 'command_joints' must "
                                           f"name as many joints as 'joints'"))

    def command_interfaces(self) -> list[str]:
        return [f"{j}/{k}" for k in self.command_kinds for j in self.command_joints]

    def state_interfaces(self) -> list[str]:
        return [f"{j}/{k}" for k in self.state_kinds for j in self.joints]

    def on_configure(self) -> None:
        p = self.read_parameters()
        self.partial = p["allow_partial_joints_goal"]
        self.interpolate = p["interpolation_method"] != "none"
        self.open_loop = p["open_loop_control"]
        self.monitor_period = 1.0 / p["action_monitor_rate"]
        self.stopped_tolerance = p["constraints.stopped_velocity_tolerance"]
        self.goal_time = p["constraints.goal_time"]
        self.path_tol = [p[f"constraints.{j}.trajectory"] for j in self.joints]
        self.goal_tol = [p[f"constraints.{j}.goal"] for j in self.joints]
        self.gains = [tuple(p[f"gains.{j}.{k}"] for k in ("p", "i", "d", "ff_velocity_scale"))
                      for j in self.joints]
        node = self.node
        self.subscription = node.create_subscription("trajectory_msgs/msg/JointTrajectory",
                                                     "~/joint_trajectory", self.on_trajectory, 10)
        self.state_pub = node.create_publisher("control_msgs/msg/JointTrajectoryControllerState",
                                               "~/controller_state", 10)
        self.action = ActionServer(node, ACTION, "~/follow_joint_trajectory", self.accept,
                                   self.on_goal, self.on_cancel, lambda: self.stamp(self.now))
        self.now = 0.0
        self.trajectory: Trajectory | None = None
        self.goal: Goal | None = None

    def on_cleanup(self) -> None:
        self.subscription.destroy()
        self.state_pub.destroy()
        self.action.destroy()

    def on_activate(self) -> None:
        n = len(self.joints)
        self.position = [self.states[f"{j}/position"] for j in self.joints]
        self.velocity = [self.states.get(f"{j}/velocity") for j in self.joints]
        self.outputs = {k: self.commands[i * n:(i + 1) * n]
                        for i, k in enumerate(self.command_kinds)}
        self.integral = [0.0] * n
        self.trajectory = None  # hold where the joints are
        self.hold = [h.value for h in self.position]
        self.reference = (list(self.hold), [0.0] * n, [0.0] * n)
        self.next_feedback = 0.0

    def on_deactivate(self) -> None:
        if self.goal is not None and self.goal.active:
            self.goal.abort(self._result(INVALID_GOAL, "the controller was deactivated"))
        self.goal = None
        self.trajectory = None

    # --- trajectories in -------------------------------------------------------------------
    def _points(self, message: Any) -> tuple[list[str], list[Point]]:
        names = list(message.joint_names)
        points = []
        for point in message.points:
            duration = point.time_from_start
            points.append(Point(stamp_seconds(duration), list(point.positions),
                                list(point.velocities) or None,
                                list(point.accelerations) or None))
        return names, points

    def _check(self, message: Any) -> tuple[str, list[str], list[Point]]:
        names, points = self._points(message)
        problem = validate(names, self.joints, points, self.partial)
        return problem, names, points

    def on_trajectory(self, message: Any) -> None:
        if not self.is_active:
            self.node.get_logger().warning("a trajectory arrived while the controller is not "
                                           "active: ignored")
            return
        problem, names, points = self._check(message)
        if problem:
            self.node.get_logger().error(f"trajectory refused: {problem}; the joints hold")
            return
        if self.goal is not None and self.goal.active:
            self.goal.abort(self._result(INVALID_GOAL, "replaced by a trajectory on the topic"))
        self.goal = None
        self._start(message, names, points)

    def _start(self, message: Any, names: list[str], points: list[Point]) -> None:
        stamp = message.header.stamp
        start = stamp_seconds(stamp) if (stamp.sec or stamp.nanosec) else self.now
        if not points:  # an empty trajectory: stop where the joints are
            self.trajectory = None
            self.hold = list(self.reference[0])
            return
        order = [names.index(j) if j in names else -1 for j in self.joints]
        current = list(self.reference[0])

        def full(values: list[float] | None, fallback: list[float]) -> list[float] | None:
            if values is None:
                return None
            return [values[i] if i >= 0 else fallback[k] for k, i in enumerate(order)]

        absolute = [Point(start + pt.time, full(pt.positions, current),
                          full(pt.velocities, [0.0] * len(current)),
                          full(pt.accelerations, [0.0] * len(current))) for pt in points]
        first = Point(self.now, current, list(self.reference[1]), list(self.reference[2]))
        if absolute[0].velocities is None:
            first.velocities = first.accelerations = None
        elif absolute[0].accelerations is None:
            first.accelerations = None
        self.trajectory = Trajectory(first, absolute, self.interpolate)

    # --- the action --------------------------------------------------------------------------
    def accept(self, goal: Any) -> bool:
        if not self.is_active:
            self.node.get_logger().error("Can't accept new action goals. Controller is not "
                                         "running.")
            return False
        problem, _, _ = self._check(goal.trajectory)
        if problem:
            self.node.get_logger().error(f"goal refused: {problem}")
            return False
        return True

    def on_goal(self, goal: Goal) -> None:
        if self.goal is not None and self.goal.active:
            self.goal.abort(self._result(INVALID_GOAL, "replaced by a new goal"))
        self.goal = goal
        request = goal.request
        names, points = self._points(request.trajectory)
        self.goal_overrides = self._tolerances(request)
        self._start(request.trajectory, names, points)

    def on_cancel(self, goal: Goal) -> None:
        if goal is self.goal:
            self.trajectory = None
            self.hold = [h.value for h in self.position]
            goal.canceled(self._result(SUCCESSFUL, "canceled"))
            self.goal = None

    def _tolerances(self, request: Any) -> tuple[list[float], list[float], float]:
        path, goal = list(self.path_tol), list(self.goal_tol)
        for source, into in ((request.path_tolerance, path), (request.goal_tolerance, goal)):
            for tolerance in source:
                if tolerance.name in self.joints and tolerance.position != 0.0:
                    into[self.joints.index(tolerance.name)] = max(tolerance.position, 0.0) \
                        if tolerance.position > 0 else 0.0
        duration = request.goal_time_tolerance
        goal_time = stamp_seconds(duration) or self.goal_time
        return path, goal, goal_time

    def _result(self, code: int, text: str) -> Any:
        return self.make(f"{ACTION}_Result", error_code=code, error_string=text)

    # --- the cycle ---------------------------------------------------------------------------
    def update(self, time: float, period: float) -> None:
        self.now = time
        actual = [h.value for h in self.position]
        if self.trajectory is not None:
            desired = self.trajectory.sample(time)
        else:
            n = len(actual)
            desired = (list(self.hold), [0.0] * n, [0.0] * n)
        self.reference = desired
        self._write(desired, actual, period)
        if self.goal is not None and self.goal.active and self.trajectory is not None:
            self._monitor(time, desired, actual)
        if self.state_pub.get_subscription_count():
            self._publish_state(time, desired, actual)

    def _write(self, desired: tuple[list[float], list[float], list[float]],
               actual: list[float], period: float) -> None:
        positions, velocities, accelerations = desired
        outputs = self.outputs
        if "position" in outputs:
            for handle, value in zip(outputs["position"], positions, strict=True):
                handle.value = value
        feedback_kind = "velocity" if "velocity" in outputs else \
            "effort" if "effort" in outputs else ""
        if "position" in outputs:
            for kind, values in (("velocity", velocities), ("acceleration", accelerations)):
                for handle, value in zip(outputs.get(kind, []), values, strict=False):
                    handle.value = value
            return
        if feedback_kind:  # a PID on the position error, plus the velocity feed-forward
            for j, handle in enumerate(outputs[feedback_kind]):
                p, i, d, ff = self.gains[j]
                error = positions[j] - actual[j]
                self.integral[j] += error * period
                speed = self.velocity[j].value if self.velocity[j] is not None else 0.0
                value = p * error + i * self.integral[j] + d * (velocities[j] - speed)
                if feedback_kind == "velocity":
                    value += ff * velocities[j]
                handle.value = value

    def _monitor(self, time: float, desired: Any, actual: list[float]) -> None:
        goal = self.goal
        assert goal is not None and self.trajectory is not None
        path, goal_tol, goal_time = self.goal_overrides
        errors = [d - a for d, a in zip(desired[0], actual, strict=True)]
        if time >= self.next_feedback:
            self.next_feedback = time + self.monitor_period
            goal.feedback(self._feedback(time, desired, actual, errors))
        end = self.trajectory.end_time
        if time < end:
            for j, tolerance in enumerate(path):
                if tolerance > 0 and abs(errors[j]) > tolerance:
                    self.trajectory = None
                    self.hold = list(actual)
                    goal.abort(self._result(PATH_TOLERANCE_VIOLATED, (
                        f"Aborted due to path tolerance violation: joint {self.joints[j]} "
                        f"error {errors[j]:.6g} exceeds {tolerance:g}")))
                    self.goal = None
                    return
            return
        inside = all(tol <= 0 or abs(errors[j]) <= tol for j, tol in enumerate(goal_tol))
        if inside and self.stopped_tolerance > 0:
            inside = all(v is None or abs(v.value) <= self.stopped_tolerance
                         for v in self.velocity)
        if inside:
            goal.succeed(self._result(SUCCESSFUL, ""))
            self.goal = None
        elif goal_time > 0 and time > end + goal_time:
            goal.abort(self._result(GOAL_TOLERANCE_VIOLATED, (
                f"Aborted due goal_time_tolerance exceeding by {time - end - goal_time:.3f} s")))
            self.goal = None

    def _point(self, positions: list[float], velocities: list[float] | None = None) -> Any:
        return self.make("trajectory_msgs/msg/JointTrajectoryPoint",
                         positions=positions, velocities=velocities or [])

    def _feedback(self, time: float, desired: Any, actual: list[float], errors: list[float]) \
            -> Any:
        speeds = [v.value if v is not None else 0.0 for v in self.velocity]
        return self.make(
            f"{ACTION}_Feedback", header=self.header(time), joint_names=self.joints,
            desired=self._point(desired[0], desired[1]), actual=self._point(actual, speeds),
            error=self._point(errors, [d - s for d, s in zip(desired[1], speeds, strict=True)]))

    def _publish_state(self, time: float, desired: Any, actual: list[float]) -> None:
        speeds = [v.value if v is not None else 0.0 for v in self.velocity]
        output = [h.value for h in self.commands[:len(self.joints)]]
        self.state_pub.publish(self.make(
            "control_msgs/msg/JointTrajectoryControllerState", header=self.header(time),
            joint_names=self.joints, reference=self._point(desired[0], desired[1]),
            feedback=self._point(actual, speeds),
            error=self._point([d - a for d, a in zip(desired[0], actual, strict=True)]),
            output=self._point(output), speed_scaling_factor=1.0))


def finite(values: list[float]) -> bool:
    return all(math.isfinite(v) for v in values)

"""The simulation's state, stepping and resets: GetSimulationState, SetSimulationState,
StepSimulation (answered once its steps are done), the SimulateSteps action (feedback after
each batch of steps, cancel ends them) and ResetSimulation with each of its scopes.

States as ros_gz reads them: playing, or paused; a paused world that has not stepped since it
was loaded or reset is stopped. Setting STOPPED pauses and resets time and state (ros_gz's
world reset: spawned entities stay); ResetSimulation's default scope is every scope, spawned
entities removed, as the package defines it.
"""

from __future__ import annotations

from typing import Any

from launcher.bus.action_server import ActionServer
from launcher.bus.actions import CANCELING
from launcher.bus.wire import fill_stamp
from launcher.sim.simulation_interfaces.common import (
    FEATURE_UNSUPPORTED,
    NO_WORLD_TEXT,
    OK,
    OPERATION_FAILED,
    TYPES,
    Api,
    result,
)

STOPPED, PLAYING, PAUSED, QUITTING, NO_WORLD, LOADING_WORLD = range(6)
STATE_NAMES = ("STATE_STOPPED", "STATE_PLAYING", "STATE_PAUSED", "STATE_QUITTING",
               "STATE_NO_WORLD", "STATE_LOADING_WORLD")
ALREADY_IN_TARGET_STATE, INCORRECT_TRANSITION = 101, 103
SCOPE_TIME, SCOPE_STATE, SCOPE_SPAWNED, SCOPE_ALL = 1, 2, 4, 255
MAX_STEPS = 100_000_000  # in one request (the sim's control service has the same limit)


class Simulation:
    def __init__(self, api: Api) -> None:
        self.api, self.server = api, api.server
        self.paused_from_stop = False  # STOPPED → PAUSED: paused, not stepped yet
        self.goal: Any = None  # the SimulateSteps goal now stepping
        node = api.node
        node.create_service(f"{TYPES}/srv/GetSimulationState", "~/get_simulation_state",
                            self.on_get_state)
        node.create_service(f"{TYPES}/srv/SetSimulationState", "~/set_simulation_state",
                            self.on_set_state)
        step = node.create_service(f"{TYPES}/srv/StepSimulation", "~/step_simulation",
                                   self.on_step)
        step.deferred = True
        node.create_service(f"{TYPES}/srv/ResetSimulation", "~/reset_simulation",
                            self.on_reset)
        self.action = ActionServer(node, f"{TYPES}/action/SimulateSteps", "~/simulate_steps",
                                   lambda goal: True, self.on_goal, self.on_cancel,
                                   self._stamp)

    # --- state -------------------------------------------------------------------------------
    def state(self) -> int:
        server = self.server
        if server.no_world:
            return NO_WORLD
        if not server.paused:
            return PLAYING
        if server.world.physics.iterations == 0 and not server.steps_to_go and \
                not self.paused_from_stop:
            return STOPPED
        return PAUSED

    def on_get_state(self, request: Any, response: Any) -> Any:
        response.state.state = self.state()
        return result(response, OK)

    def on_set_state(self, request: Any, response: Any) -> Any:
        target, now = request.state.state, self.state()
        if target not in (STOPPED, PLAYING, PAUSED, QUITTING):
            name = STATE_NAMES[target] if target < len(STATE_NAMES) else str(target)
            return result(response, INCORRECT_TRANSITION,
                          f"{name} is not a state to set: set STATE_STOPPED, STATE_PLAYING, "
                          "STATE_PAUSED or STATE_QUITTING")
        server = self.server
        if server.no_world and target != QUITTING:
            return result(response, INCORRECT_TRANSITION, NO_WORLD_TEXT)
        if target == now:
            return result(response, ALREADY_IN_TARGET_STATE,
                          f"the simulation is already {STATE_NAMES[now]}")
        if target == STOPPED:
            server.set_paused(True)
            server.reset(time=True, poses=True)
            self.paused_from_stop = False
        elif target == PLAYING:
            self.paused_from_stop = False
            server.set_paused(False)
        elif target == PAUSED:
            self.paused_from_stop = now == STOPPED
            server.set_paused(True)
        else:  # QUITTING: answered, then the sim ends as on Ctrl-C
            self.api.node.get_logger().info("SetSimulationState STATE_QUITTING: the sim "
                                            "stops")
            server.stop()
        return result(response, OK)

    # --- stepping ----------------------------------------------------------------------------
    def _refusal(self, steps: int) -> str:
        if self.server.no_world:
            return NO_WORLD_TEXT
        if not self.server.paused:
            return ("the simulation is playing: stepping needs it paused (SetSimulationState "
                    "STATE_PAUSED first)")
        if steps > MAX_STEPS:
            return f"{steps} steps is past the limit of {MAX_STEPS:,} steps in one request"
        return ""

    def on_step(self, request: Any, reply: Any) -> None:
        response = reply.new_response()
        steps = max(int(request.steps), 1)  # 0: one step, as Gazebo's step
        refused = self._refusal(steps)
        if refused:
            reply.send(result(response, OPERATION_FAILED, refused))
            return
        self.paused_from_stop = False

        def done(finished: bool) -> None:
            reply.send(result(response, OK) if finished else result(
                response, OPERATION_FAILED, "interrupted: the simulation was played, reset or "
                "given other steps before these were done"))

        self.server.step_then(steps, done)

    def on_goal(self, goal: Any) -> None:
        steps = int(goal.request.steps)
        refused = "the goal asks for 0 steps" if steps < 1 else self._refusal(steps)
        outcome = self.api.node.message(f"{TYPES}/action/SimulateSteps_Result")
        if refused:
            result(outcome, OPERATION_FAILED, refused)
            goal.abort(outcome)
            return
        self.paused_from_stop = False
        feedback_type = f"{TYPES}/action/SimulateSteps_Feedback"

        def progress(completed: int, remaining: int) -> None:
            goal.feedback(self.api.node.message(feedback_type, completed_steps=completed,
                                                remaining_steps=remaining))

        def done(finished: bool) -> None:
            if self.goal is goal:
                self.goal = None
            if finished:
                goal.succeed(result(outcome, OK))
            elif goal.record.state == CANCELING:  # the client asked
                goal.canceled(result(outcome, OK, "canceled"))
            else:
                goal.abort(result(outcome, OPERATION_FAILED, "interrupted: the simulation "
                                  "was played, reset or given other steps"))

        self.goal = goal
        self.server.step_then(steps, done, progress)

    def on_cancel(self, goal: Any) -> None:
        if self.goal is goal:
            self.server.stop_stepping()

    def _stamp(self) -> Any:
        time = self.api.node.message("builtin_interfaces/msg/Time")
        fill_stamp(time, float(self.server.world.data.time))
        return time

    # --- resets ------------------------------------------------------------------------------
    def on_reset(self, request: Any, response: Any) -> Any:
        scope = int(request.scope) or SCOPE_ALL
        if not scope & (SCOPE_TIME | SCOPE_STATE | SCOPE_SPAWNED):
            return result(response, FEATURE_UNSUPPORTED,
                          f"scope {scope} names no scope this sim resets: use SCOPE_TIME (1), "
                          "SCOPE_STATE (2), SCOPE_SPAWNED (4) or a sum of them, or SCOPE_ALL")
        world = self.server.world
        if scope & SCOPE_SPAWNED:
            world.remove_all([name for name, e in world.entities.items() if e.spawned])
        if scope & (SCOPE_TIME | SCOPE_STATE):
            self.server.reset(time=bool(scope & SCOPE_TIME), poses=bool(scope & SCOPE_STATE))
        else:
            self.server.publish_clock()
        self.paused_from_stop = False
        return result(response, OK)


def serve(api: Api) -> Simulation:
    return Simulation(api)

"""The world server: the sim's loop (runner.py) and the world's services (world_services.py)
over one world, with its plugins and ROS's standard simulator API (sim/simulation_interfaces/),
served on the bus.

Topics (sim-native types from the mujoco_sim package, Gazebo's names):
  /clock and /world/<w>/clock                Clock, after every batch of steps (paused: 20 Hz)
  /world/<w>/pose/info, /world/<w>/model_states   every entity (world_state plugin)
  /world/<w>/dynamic_pose/info               every entity that is not static (world_state)
  /model/<m>/odometry, /model/<m>/tf, /model/<m>/cmd_vel   diff drive plugins
  /world/<w>/model/<m>/joint_state           joint state plugins (paused too, as Gazebo's)
Services: /world/<w>/control, /world/<w>/create, /world/<w>/remove, /world/<w>/set_pose,
/world/<w>/state (every entity's pose and twist now, paused or not), /world/<w>/snapshot.
On the ROS graph: simulation_interfaces' services and action, on /gzserver/*
(sim/simulation_interfaces/), which act on the runner as the world's services do.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from typing import Any

import mujoco

from launcher.bus.node import Node
from launcher.sim import simulation_interfaces
from launcher.sim.plugins import config_from
from launcher.sim.runner import SimulationRunner
from launcher.sim.world import World
from launcher.sim.world_services import WorldServices


def route_mujoco_warnings(logger: Any) -> None:
    """MuJoCo's own warnings to the log, not to a MUJOCO_LOG.TXT in the working folder."""
    mujoco.set_mju_user_warning(lambda text: logger.warning(f"MuJoCo: {text}"))


class SimServer:
    """One sim: its loop (`runner`), the world's services (`services`), the world's plugins
    and the standard API, kept together across the worlds loaded in the first one's place."""

    def __init__(self, world: World, node: Node, rtf: float, running: bool,
                 state_rate: float = 50.0, lockstep: float | None = None) -> None:
        """`lockstep`: the tick, in s of sim time, of a lockstep with the nodes on sim time
        (bus/lockstep.py); None: paced by `rtf`."""
        route_mujoco_warnings(node.get_logger())
        self.state_rate = state_rate
        self.runner = SimulationRunner(world, node, rtf, running, lockstep)
        self.runner.on_load = self._follow
        self.services = WorldServices(self.runner)
        self._load_plugins(world)
        # ROS's standard simulator API (simulation_interfaces) on the ROS graph, as ros_gz's
        self.standard_api = simulation_interfaces.serve(self.runner)

    def _load_plugins(self, world: World) -> None:
        world.load_world_plugins(before=[config_from(
            f'<plugin filename="world_state" name="WorldState">'
            f"<update_rate>{self.state_rate}</update_rate></plugin>", "the sim")])

    def _follow(self, world: World, renamed: bool) -> None:
        """A world loaded in the runner's place of the last (runner.load): its services and
        plugins follow it."""
        self.services.follow(world, renamed)
        self._load_plugins(world)

    def run(self, iterations: int | None = None) -> None:
        """Run the loop until it stops (or `iterations` steps), then close what serves the
        world."""
        try:
            self.runner.run(iterations)
        finally:
            self.services.close()
            if self.runner.view is not None:
                self.runner.view.close()


EXIT_GRACE = 3.0  # s from SIGINT/SIGTERM to a forced exit, should shutting down ever stall


def install_signal_handlers(runner: SimulationRunner) -> None:
    """SIGINT and SIGTERM end the loop; the sim then closes its session and exits. Should that
    stall (a bus call that never returns), it exits anyway after EXIT_GRACE: a stop request
    always stops the sim, well before the launcher's own SIGTERM/SIGKILL escalation."""
    armed: list[threading.Timer] = []

    def stop(signum: int, _frame: Any) -> None:
        runner.stop()
        if not armed:
            timer = threading.Timer(EXIT_GRACE, _force_exit, (128 + signum,))
            timer.daemon = True
            timer.start()
            armed.append(timer)

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)


def _force_exit(code: int) -> None:
    sys.stderr.write(f"[sim] did not stop within {EXIT_GRACE:g} s of the stop request; "
                     f"exiting\n")
    sys.stderr.flush()
    os._exit(code)

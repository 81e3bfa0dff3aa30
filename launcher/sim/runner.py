"""The sim's loop (gz-sim's SimulationRunner): steps the world, paced, and says the time.

One thread does everything: bus callbacks (services, cmd_vel) run between batches of steps,
so the world is never touched from two threads. While paused or ahead of schedule the loop
waits on the node's queue, so services and spawning stay responsive. Between two batches,
callbacks get at most CALLBACK_BUDGET of wall time, so that no flood of messages or requests
can hold physics back (each subscription keeps only its last `depth` samples: a `/cmd_vel`
flood is the latest command, not a backlog). A request for steps (`step_then`, `control`) is
stepped by the loop in batches, the bus served between them: a later request (pause, run,
reset, another step) replaces the steps still to go. With `--lockstep` the loop steps one tick
at a time, unpaced, each once the nodes on sim time and the bridges have handled the one
before (bus/lockstep.py). With a stop time (`stop_at`), the loop ends at the first step (in
lockstep: the first tick) whose sim time is on or past it; `tally` counts the steps and the wall
time they took, for the sim's `report` (report.py), written as the loop ends however it ends.

What runs on the bus acts on the world through this object, from the loop's own thread (the
callbacks run inside `node.spin_once`): pausing and stepping (`set_paused`, `step_then`,
`stop_stepping`, `control`), resets, spawns (queued, then added together between steps),
a world loaded in place of this one. After every batch the clocks are published and the web
viewer, if one is shown, follows the world.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable
from typing import Any

from launcher.bus.lockstep import Leader
from launcher.errors import LaunchError
from launcher.sim.clocks import Clocks
from launcher.sim.pacing import Pacer
from launcher.sim.report import SimReport, Tally
from launcher.sim.schedule import SLACK
from launcher.sim.world import Spawn, SpawnError, World

MAX_BATCH = 100  # steps between two looks at the bus when running unpaced
CALLBACK_BUDGET = 0.002  # s of callbacks between two batches of steps
LOCKSTEP_REPEAT = 0.05  # s of wall time between two clocks of the same time in a lockstep
LOCKSTEP_DRAIN = 10_000  # callbacks at most between two lockstep ticks (a flood ends no tick)


class SimulationRunner:
    def __init__(self, world: World, node: Any, rtf: float, running: bool,
                 lockstep: float | None = None) -> None:
        """`lockstep`: the tick, in s of sim time, of a lockstep with the nodes on sim time
        (bus/lockstep.py); None: paced by `rtf`."""
        self.world, self.node, self.transport = world, node, world.transport
        self.log = node.get_logger()
        self.view: Any = None  # the web viewer (viewer.py), following the world when shown
        self.paused = not running
        self.stopped = False
        self.stop_at: float | None = None  # s of sim time at which the loop ends
        self.stop_reached = False  # it ended so (not on a signal)
        self.tally = Tally()
        self.report: SimReport | None = None  # written as the loop ends
        self.no_world = False  # the world unloaded (simulation_interfaces' UnloadWorld)
        self.steps_to_go = 0  # of a request for steps
        self._when_stepped: Any = None  # told (True) when steps_to_go is done, or (False) not
        self._step_progress: Any = None  # told the steps done after each batch of them
        self._steps_asked = 0
        self.pacer = Pacer(world.model.opt.timestep, rtf)
        self._spawns: list[tuple[Spawn, Any]] = []  # spawn_soon's, not yet spawned
        self.clocks = Clocks(node, world.world_name)
        # what else follows a loaded world (its services and plugins), told (world, renamed)
        self.on_load: Callable[[World, bool], None] = lambda world, renamed: None
        self.leader: Leader | None = None
        self.tick_steps = 0
        self.lockstep = lockstep
        if lockstep is not None:
            self.leader = Leader(node.host, world.world_name, self.log)
            self.tick_steps = max(1, round(lockstep / world.model.opt.timestep))

    def load(self, world: World, no_world: bool = False) -> None:
        """Put `world` in the place of the running one (simulation_interfaces' LoadWorld):
        the old one's entities and plugins go, `on_load` makes the rest follow, and it is
        stopped (paused, at time 0). Its clock follows its name. `no_world`: an empty stand-in
        after UnloadWorld, until a world is loaded."""
        for _, done in self._spawns:
            done(SpawnError("the world was replaced before the entity could be added"))
        self._spawns = []
        old = self.world
        old.close()
        self.world, self.no_world = world, no_world
        self.pacer = Pacer(world.model.opt.timestep, self.pacer.rtf)
        renamed = world.world_name != old.world_name
        if renamed:
            self.clocks.name(world.world_name)
            if self.leader is not None and self.lockstep is not None:
                self.leader.close()
                self.leader = Leader(self.node.host, world.world_name, self.log)
        if self.lockstep is not None:
            self.tick_steps = max(1, round(self.lockstep / world.model.opt.timestep))
        self.on_load(world, renamed)
        self.paused = True
        self.stop_stepping()
        self.publish_clock()

    # --- the loop --------------------------------------------------------------------------
    def run(self, iterations: int | None = None) -> None:
        try:
            self._loop(iterations)
        finally:
            for _, done in self._spawns:  # (their callers are not left waiting)
                done(SpawnError("the sim stopped before it could add the entity"))
            self._spawns = []
            if self.report is not None:  # (on a stop, a signal or an error alike)
                self.report.write(self.world, self.tally, self.stop_reached)
            if self.leader is not None:
                self.leader.close()

    def _loop(self, iterations: int | None) -> None:
        node = self.node
        self.publish_clock()
        while not self.stopped:
            world, pacer = self.world, self.pacer  # (a loaded world takes their place)
            if self._spawns:
                self._spawn_pending()
            if iterations is not None and world.physics.iterations >= iterations:
                break
            if self.paused and self.steps_to_go:  # steps asked for, batch by batch
                self._step_asked(world, iterations)
                continue
            if self.paused:  # serve the bus; the clock says "paused" 20 times a second
                if not node.spin_once(0.05):
                    self.publish_clock()
                    self.world.physics.idle()  # (a loaded world may have replaced it)
                elif self.view is not None:  # (a busy bus: the page is still served)
                    self.view.follow(self.world, self.paused)
                continue
            if self.leader is not None:
                self._lockstep_tick(iterations)
                continue
            due = pacer.due()
            if due == 0:  # ahead of schedule: serve the bus until the next step is due
                if node.spin_once(pacer.wait_time()) or self.paused or self.stopped:
                    continue  # a callback ran: look again (more may be queued)
                due = pacer.due()
                if due == 0:
                    continue
            else:
                self.serve()  # callbacks first: commands apply to this batch
                if self.paused or self.stopped:
                    continue
            pacer.stepped(self._step(world, min(due, MAX_BATCH), iterations))
            self.publish_clock()

    def _step(self, world: World, batch: int, iterations: int | None) -> int:
        """Step at most `batch` steps, no further than `iterations`, the stop time, nor past
        the next step a plugin has work at; the steps stepped."""
        if iterations is not None:
            batch = min(batch, iterations - world.physics.iterations)
        if self.stop_at is not None:
            batch = min(batch, max(1, math.ceil((self.stop_at - world.data.time - SLACK) /
                                                world.model.opt.timestep)))
        batch = world.physics.steps_until_update(batch)
        self._advance(world, batch)
        self._stop_if_due(world)
        return batch

    def _advance(self, world: World, count: int) -> None:
        began = time.monotonic()
        world.physics.step(count)
        self.tally.stepped(count, began, time.monotonic())

    def _stop_if_due(self, world: World) -> None:
        """End the loop once the sim time is on or past the stop time (within SLACK: the
        float sums of the timestep)."""
        if self.stop_at is not None and world.data.time + SLACK >= self.stop_at:
            self.stopped = self.stop_reached = True

    def _step_asked(self, world: World, iterations: int | None) -> None:
        """The next batch of the steps asked for while paused (the bus served first)."""
        self.serve()
        if not (self.paused and self.steps_to_go and not self.stopped):
            return
        self.steps_to_go -= self._step(world, min(self.steps_to_go, MAX_BATCH), iterations)
        self.publish_clock()
        if self._step_progress is not None:
            self._step_progress(self._steps_asked - self.steps_to_go, self.steps_to_go)
        if not self.steps_to_go:
            self._stepped(True)

    def _lockstep_tick(self, iterations: int | None) -> None:
        """Wait until the members of the lockstep have handled the last clock (serving the
        bus, and saying the time again now and then for those that join), apply all that
        they sent, then step one tick."""
        world, node, leader = self.world, self.node, self.leader
        assert leader is not None
        now = round(world.data.time * 1e9)
        while not leader.ready(now):
            if self.paused or self.stopped:
                return
            if leader.joined or not node.spin_once(LOCKSTEP_REPEAT):
                leader.joined = False
                self.publish_clock()  # (a member that came since hears the time)
            if self._spawns:  # (a spawn asked for meanwhile is not held up by the tick)
                self._spawn_pending()
        for _ in range(LOCKSTEP_DRAIN):  # what they sent, before the step
            if self.stopped or not node.spin_once(0):
                break
        left = self.tick_steps
        if iterations is not None:
            left = min(left, iterations - world.physics.iterations)
        while left > 0 and not self.stopped:
            batch = world.physics.steps_until_update(left)
            self._advance(world, batch)
            left -= batch
        self.publish_clock()
        self._stop_if_due(world)  # (a whole tick: the nodes heard each one)

    def serve(self) -> None:
        """Run the callbacks that are ready, for up to CALLBACK_BUDGET."""
        end = time.monotonic() + CALLBACK_BUDGET
        while not self.stopped and self.node.spin_once(0) and time.monotonic() < end:
            pass

    def stop(self, *_: Any) -> None:
        self.stopped = True

    # --- pausing and stepping ----------------------------------------------------------------
    def set_paused(self, paused: bool) -> None:
        """Pause or run; running ends steps still to go (their caller is told so). With no
        world loaded (UnloadWorld) it stays paused."""
        paused = paused or self.no_world
        if self.paused and not paused:
            self.pacer.restart()  # no catching up on the time spent paused
        self.paused = paused
        if not paused and self.steps_to_go:
            self.steps_to_go = 0
            self._stepped(False)
        self.publish_clock()

    def step_then(self, steps: int, done: Any, progress: Any = None) -> None:
        """Step a paused world `steps` steps, then call `done(True)`; `done(False)` if a
        later request ends them first (a run, another step, a reset, `stop_stepping`).
        `progress(completed, remaining)` is told after each batch of steps."""
        if self.steps_to_go:
            self._stepped(False)
        self.steps_to_go, self._when_stepped = steps, done
        self._steps_asked, self._step_progress = steps, progress

    def control(self, pause: bool | None, steps: int, restart: bool) -> None:
        """A control request (`/world/<w>/control`, the web page's buttons): pause (True), run
        (False) or stay as it is (None); then `steps` to step if paused, in place of those
        still to go (their caller is told they did not finish). The pacing starts again on
        running after a pause, or on `restart` (a reset of the time)."""
        was_paused = self.paused
        if pause is not None:
            self.paused = pause or self.no_world
        if self.steps_to_go:
            self._stepped(False)  # replaced by this request
        self.steps_to_go = steps if self.paused else 0
        if (was_paused and not self.paused) or restart:
            self.pacer.restart()
        self.publish_clock()

    def stop_stepping(self) -> None:
        """End the steps still to go (their caller is told they did not finish)."""
        if self.steps_to_go:
            self.steps_to_go = 0
            self._stepped(False)

    def _stepped(self, finished: bool) -> None:
        done, self._when_stepped, self._step_progress = self._when_stepped, None, None
        if done is not None:
            done(finished)

    def reset(self, time: bool, poses: bool) -> None:
        """Reset the world's time, poses or both (the standard API's resets); steps still
        to go end."""
        self.world.reset(time=time, poses=poses)
        self.stop_stepping()
        if time:
            self.pacer.restart()
        self.publish_clock()

    def publish_clock(self) -> None:
        if self.view is not None:  # (after every batch, and while paused: rate-limited)
            self.view.follow(self.world, self.paused)
        self.clocks.publish(self.world, self.paused)

    # --- spawning in batches -----------------------------------------------------------------
    def spawn_soon(self, request: Spawn, done: Any) -> None:
        """Spawn `request` with the others that arrive with it (one recompile for them all,
        world.spawn_all), between two batches of steps, then call `done(entity or
        SpawnError)`."""
        self._spawns.append((request, done))

    def _spawn_pending(self) -> None:
        self.serve()  # the requests that came with these join them
        pending, self._spawns = self._spawns, []
        results = self.world.spawn_all([request for request, _ in pending])
        for (_, done), entity in zip(pending, results, strict=True):
            if not isinstance(entity, LaunchError):  # (a string's label is its first spawn's)
                source = f" from {entity.label}" if os.path.isfile(entity.label) else ""
                self.log.info(f"spawned '{entity.name}'{source}")
            done(entity)
        added = sum(not isinstance(entity, LaunchError) for entity in results)
        if added > 1:
            self.log.info(f"{added} entities spawned with one recompile")
        self.publish_clock()

"""The world server: steps the world, paced, and serves it on the bus.

One thread does everything: bus callbacks (services, cmd_vel) run between batches of steps,
so the world is never touched from two threads. While paused or ahead of schedule the loop
waits on the node's queue, so services and spawning stay responsive. Between two batches,
callbacks get at most CALLBACK_BUDGET of wall time, so that no flood of messages or requests
can hold physics back (each subscription keeps only its last `depth` samples: a `/cmd_vel`
flood is the latest command, not a backlog). A control request's `multi_step` is stepped by
the loop in batches, the bus served between them: the request is answered at once, a later
request (pause, run, reset, another step) replaces the steps still to go, and more than
MAX_MULTI_STEP is refused. With `--lockstep` the loop steps one tick at a time, unpaced, each
once the nodes on sim time and the bridges have handled the one before (bus/lockstep.py).

Topics (sim-native types from the mujoco_sim package, Gazebo's names):
  /clock and /world/<w>/clock                Clock, after every batch of steps (paused: 20 Hz)
  /world/<w>/pose/info, /world/<w>/model_states   every entity (world_state plugin)
  /world/<w>/dynamic_pose/info               every entity that is not static (world_state)
  /model/<m>/odometry, /model/<m>/tf, /model/<m>/cmd_vel   diff drive plugins
  /world/<w>/model/<m>/joint_state           joint state plugins (paused too, as Gazebo's)
Services: /world/<w>/control, /world/<w>/create, /world/<w>/remove, /world/<w>/set_pose,
/world/<w>/state (every entity's pose and twist now, paused or not), /world/<w>/snapshot.
Spawns that arrive together (creates, the standard API's) are added with one recompile.
On the ROS graph: simulation_interfaces' services and action, on /gzserver/*
(sim/simulation_interfaces/).
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time
from typing import Any

import mujoco

from launcher.bus.lockstep import Leader
from launcher.bus.node import Node
from launcher.bus.wire import clock_cdr, ros_clock_cdr
from launcher.errors import LaunchError
from launcher.sim import simulation_interfaces
from launcher.sim.pacing import Pacer
from launcher.sim.plugins import config_from
from launcher.sim.snapshot import Camera
from launcher.sim.world import Spawn, SpawnError, World

MAX_BATCH = 100  # steps between two looks at the bus when running unpaced
CALLBACK_BUDGET = 0.002  # s of callbacks between two batches of steps
MAX_MULTI_STEP = 100_000_000
LOCKSTEP_REPEAT = 0.05  # s of wall time between two clocks of the same time in a lockstep
LOCKSTEP_DRAIN = 10_000  # callbacks at most between two lockstep ticks (a flood ends no tick)


def route_mujoco_warnings(logger: Any) -> None:
    """MuJoCo's own warnings to the log, not to a MUJOCO_LOG.TXT in the working folder."""
    mujoco.set_mju_user_warning(lambda text: logger.warning(f"MuJoCo: {text}"))


class SimServer:
    def __init__(self, world: World, node: Node, rtf: float, running: bool,
                 state_rate: float = 50.0, lockstep: float | None = None) -> None:
        """`lockstep`: the tick, in s of sim time, of a lockstep with the nodes on sim time
        (bus/lockstep.py); None: paced by `rtf`."""
        self.world, self.node, self.transport = world, node, world.transport
        self.view: Any = None  # the web viewer (viewer.py), once show() is given one
        self.log = node.get_logger()
        route_mujoco_warnings(self.log)
        self.paused = not running
        self.stopped = False
        self.steps_to_go = 0  # of a multi_step request
        self._when_stepped: Any = None  # told (True) when steps_to_go is done, or (False) not
        self._step_progress: Any = None  # told the steps done after each batch of them
        self._steps_asked = 0
        self._ros_clocks: list[Any] = []  # rosgraph_msgs/Clock on the ROS graph (add_ros_clock)
        self.pacer = Pacer(world.model.opt.timestep, rtf)
        self.state_rate = state_rate
        self.no_world = False  # the world unloaded (simulation_interfaces' UnloadWorld)
        self._spawns: list[tuple[Spawn, Any]] = []  # spawn_soon's, not yet spawned
        self._clocks = [node.create_publisher("mujoco_sim/msg/Clock", "/clock")]
        self._named: list[Any] = []  # the endpoints named by the world (_serve_world)
        self._serve_world(world.world_name)
        self.camera = Camera(world)  # its GL context is made at the first snapshot
        # the web viewer on request (`gz sim -g`), made by start_view(port) if one is given
        self.start_view: Any = None
        self._load_plugins(world)
        # ROS's standard simulator API (simulation_interfaces) on the ROS graph, as ros_gz's
        self.standard_api = simulation_interfaces.serve(self)
        self._started = time.monotonic()
        self.leader: Leader | None = None
        self.tick_steps = 0
        self.lockstep = lockstep
        if lockstep is not None:
            self.leader = Leader(node.host, world.world_name, self.log)
            self.tick_steps = max(1, round(lockstep / world.model.opt.timestep))

    def _serve_world(self, name: str) -> None:
        """The sim's services and clock under `/world/<name>/`, as gz sim names them."""
        node = self.node
        for endpoint in self._named:
            endpoint.destroy()
        clock = node.create_publisher("mujoco_sim/msg/Clock", f"/world/{name}/clock")
        self._clocks[1:] = [clock]
        create = node.create_service("mujoco_sim/srv/Create", f"/world/{name}/create",
                                     self.on_create)
        create.deferred = True
        self._named = [clock, create] + [node.create_service(
            f"mujoco_sim/srv/{kind}", f"/world/{name}/{service}", callback)
            for kind, service, callback in (
                ("Control", "control", self.on_control),
                ("Remove", "remove", self.on_remove),
                ("SetPose", "set_pose", self.on_set_pose),
                ("State", "state", self.on_state),
                ("Snapshot", "snapshot", self.on_snapshot),
                ("Gui", "gui", self.on_gui))]

    def _load_plugins(self, world: World) -> None:
        world.load_world_plugins(before=[config_from(
            f'<plugin filename="world_state" name="WorldState">'
            f"<update_rate>{self.state_rate}</update_rate></plugin>", "the sim")])

    def load(self, world: World, no_world: bool = False) -> None:
        """Put `world` in the place of the running one (simulation_interfaces' LoadWorld):
        the old one's entities and plugins go, the new one's plugins load, and it is stopped
        (paused, at time 0). Its services and clock follow its name. `no_world`: an empty
        stand-in after UnloadWorld, until a world is loaded."""
        for _, done in self._spawns:
            done(SpawnError("the world was replaced before the entity could be added"))
        self._spawns = []
        old = self.world
        old.close()
        self.world, self.no_world = world, no_world
        self.pacer = Pacer(world.model.opt.timestep, self.pacer.rtf)
        if world.world_name != old.world_name:
            self._serve_world(world.world_name)
            if self.leader is not None and self.lockstep is not None:
                self.leader.close()
                self.leader = Leader(self.node.host, world.world_name, self.log)
        if self.lockstep is not None:
            self.tick_steps = max(1, round(self.lockstep / world.model.opt.timestep))
        self.camera.close()
        self.camera = Camera(world)
        self._load_plugins(world)
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
            if self.leader is not None:
                self.leader.close()
            self.camera.close()
            if self.view is not None:
                self.view.close()

    def _loop(self, iterations: int | None) -> None:
        node = self.node
        self.publish_clock()
        while not self.stopped:
            world, pacer = self.world, self.pacer  # (a loaded world takes their place)
            if self._spawns:
                self._spawn_pending()
            if iterations is not None and world.physics.iterations >= iterations:
                break
            if self.paused and self.steps_to_go:  # a multi_step, batch by batch
                self.serve()
                if self.paused and self.steps_to_go and not self.stopped:
                    batch = min(self.steps_to_go, MAX_BATCH)
                    if iterations is not None:
                        batch = min(batch, iterations - world.physics.iterations)
                    batch = world.physics.steps_until_update(batch)
                    world.physics.step(batch)
                    self.steps_to_go -= batch
                    self.publish_clock()
                    if self._step_progress is not None:
                        self._step_progress(self._steps_asked - self.steps_to_go,
                                            self.steps_to_go)
                    if not self.steps_to_go:
                        self._stepped(True)
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
            batch = min(due, MAX_BATCH)
            if iterations is not None:
                batch = min(batch, iterations - world.physics.iterations)
            batch = world.physics.steps_until_update(batch)
            world.physics.step(batch)
            pacer.stepped(batch)
            self.publish_clock()

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
            world.physics.step(batch)
            left -= batch
        self.publish_clock()

    # --- pausing and stepping, for the services of a plugin (mujoco_ros2_control's) ---------
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

    def add_ros_clock(self) -> None:
        """/clock as rosgraph_msgs/Clock on the ROS graph too (for a sim started without a
        bridge, as mujoco_ros2_control's node publishes it)."""
        from launcher.bus import keys

        self._ros_clocks.append(self.node.create_publisher("rosgraph_msgs/msg/Clock", "/clock",
                                                           space=keys.ROS))

    def serve(self) -> None:
        """Run the callbacks that are ready, for up to CALLBACK_BUDGET."""
        end = time.monotonic() + CALLBACK_BUDGET
        while not self.stopped and self.node.spin_once(0) and time.monotonic() < end:
            pass

    def publish_clock(self) -> None:
        if self.view is not None:  # (after every batch, and while paused: rate-limited)
            self.view.follow(self.world, self.paused)
        for publisher in self._ros_clocks:
            if publisher.get_subscription_count():
                publisher.publish_raw(ros_clock_cdr(self.world.data.time))
        wanted = [p for p in self._clocks if p.get_subscription_count()]
        if not wanted:
            return
        payload = clock_cdr(self.world.data.time, time.monotonic() - self._started,
                            self.paused, self.world.physics.iterations)
        for publisher in wanted:
            publisher.publish_raw(payload)

    def stop(self, *_: Any) -> None:
        self.stopped = True

    def show(self, view: Any) -> None:
        """Serve the world to `view` (viewer.py's WebView), whose page's buttons act as the
        control service's requests do."""
        self.view = view
        view.on_action = self.on_page_action

    def on_gui(self, request: Any, response: Any) -> Any:
        if self.view is None and self.start_view is not None:
            view = self.start_view(request.port or None)
            if view is not None:
                self.show(view)
        if self.view is None:
            response.success = False
            response.message = "the sim could not serve its web viewer (its log says why)"
            return response
        response.success, response.url = True, self.view.url
        return response

    def on_page_action(self, action: str) -> None:
        """The page's Pause, Run, Step or Reset, as a `/world/<w>/control` request."""
        pause = action in ("pause", "step") or (action == "reset" and self.paused)
        request = self.node.message("mujoco_sim/srv/Control_Request", pause=pause,
                                    step=action == "step", reset_all=action == "reset")
        self.on_control(request, self.node.message("mujoco_sim/srv/Control_Response"))
        self.log.info(f"the web viewer's page: {action}")

    # --- services --------------------------------------------------------------------------
    def on_control(self, request: Any, response: Any) -> Any:
        if request.reset_all or request.reset_time_only or request.reset_model_only:
            self.world.reset(time=request.reset_all or request.reset_time_only,
                             poses=request.reset_all or request.reset_model_only)
        steps = request.multi_step or (1 if request.step else 0)
        if steps > MAX_MULTI_STEP:
            response.success = False
            response.message = (f"multi_step {steps} is past the limit of {MAX_MULTI_STEP:,} "
                                f"steps in one request")
            return response
        resetting = request.reset_all or request.reset_time_only or request.reset_model_only
        # A reset alone keeps a paused world paused, as Gazebo does; pause/step say otherwise
        was_paused = self.paused
        if not (resetting and not request.pause and not steps):
            self.paused = request.pause or self.no_world
        if self.steps_to_go:
            self._stepped(False)  # replaced by this request
        self.steps_to_go = steps if self.paused else 0  # replaces what was still to go
        if (was_paused and not self.paused) or request.reset_all or request.reset_time_only:
            self.pacer.restart()
        self.publish_clock()
        response.success = True
        response.message = (f"paused; stepping {steps}" if steps and self.paused else
                            "paused" if self.paused else "running")
        return response

    def on_create(self, request: Any, reply: Any) -> None:
        response = reply.new_response()
        try:
            if self.no_world:
                raise LaunchError("no world is loaded (UnloadWorld removed it): load one first")
            templates = self.world.templates
            if request.sdf.strip():
                template = templates.from_string(request.sdf, f"entity '{request.name}'")
            elif request.sdf_filename.strip():
                template = templates.from_file(request.sdf_filename.strip())
            else:
                raise LaunchError("nothing to spawn: give the description (sdf) or a file "
                                  "(sdf_filename)")
            position, quat = spawn_pose(request.pose, template)
            names, values = list(request.joint_names), list(request.joint_positions)
            if len(names) != len(values):
                raise LaunchError(f"{len(names)} joint names but {len(values)} joint "
                                  "positions: give one position per joint")
        except LaunchError as exc:
            self.log.warning(f"create failed: {exc}")
            response.success, response.message = False, str(exc)
            reply.send(response)
            return

        def spawned(entity: Any) -> None:
            if isinstance(entity, LaunchError):
                self.log.warning(f"create failed: {entity}")
                response.success, response.message = False, str(entity)
            else:
                response.success, response.name = True, entity.name
                response.message = f"spawned '{entity.name}'"
            reply.send(response)

        self.spawn_soon(Spawn(template, request.name, position, quat, request.allow_renaming,
                              dict(zip(names, map(float, values), strict=True)),
                              request.keyframe), spawned)

    # --- spawning in batches -----------------------------------------------------------------
    def spawn_soon(self, request: Spawn, done: Any) -> None:
        """Spawn `request` with the others that arrive with it (one recompile for them all,
        world.spawn_all), then call `done(entity or SpawnError)`."""
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

    def on_remove(self, request: Any, response: Any) -> Any:
        try:
            self.world.remove(request.name)
        except LaunchError as exc:
            response.success, response.message = False, str(exc)
            return response
        self.log.info(f"removed '{request.name}'")
        response.success, response.message = True, f"removed '{request.name}'"
        return response

    def on_set_pose(self, request: Any, response: Any) -> Any:
        pose = request.pose
        quat = [pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z]
        if all(q == 0 for q in quat):
            quat = [1.0, 0.0, 0.0, 0.0]
        try:
            placement = self.world.placement
            placement.set_pose(request.name, [pose.position.x, pose.position.y,
                                              pose.position.z], quat)
            if request.set_twist:
                linear, angular = request.twist.linear, request.twist.angular
                placement.set_twist(request.name, [linear.x, linear.y, linear.z],
                                    [angular.x, angular.y, angular.z])
        except LaunchError as exc:
            response.success, response.message = False, str(exc)
            return response
        response.success, response.message = True, f"moved '{request.name}'"
        return response

    def on_state(self, request: Any, response: Any) -> Any:
        world, transport = self.world, self.transport
        names, positions, quats = world.placement.poses()
        response.world = world.world_name
        response.name = names
        response.pose = [transport.pose(p[0], p[1], p[2], (q[1], q[2], q[3], q[0]))
                         for p, q in zip(positions, quats, strict=True)]
        response.twist = [transport.message("geometry_msgs/msg/Twist",
                                            linear=transport.vector(*v[:3]),
                                            angular=transport.vector(*v[3:6]))
                          for v in world.placement.velocities(names)]
        response.sim_time = float(world.data.time)
        response.time_step = float(world.model.opt.timestep)
        response.paused = self.paused
        response.real_time_factor = float(self.pacer.rtf)
        response.gravity = transport.vector(*world.model.opt.gravity.tolist())
        return response

    def on_snapshot(self, request: Any, response: Any) -> Any:
        import numpy as np

        try:
            png = self.camera.png(request.width, request.height, request.camera.strip(),
                                  request.track.strip())
        except LaunchError as exc:
            self.log.warning(f"snapshot failed: {exc}")
            response.success, response.message = False, str(exc)
            return response
        response.success, response.message = True, f"{len(png)} bytes of PNG"
        response.png = np.frombuffer(png, dtype=np.uint8)
        return response


def spawn_pose(pose: Any, template: Any) -> tuple[list[float], list[float]]:
    """Where a create request puts the model: its pose, or, when it gives none (all zero),
    the pose the description itself has (an SDF model's `<pose>`)."""
    position = [pose.position.x, pose.position.y, pose.position.z]
    quat = [pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z]
    if all(q == 0 for q in quat):
        quat = [1.0, 0.0, 0.0, 0.0]
    if not any(position) and quat == [1.0, 0.0, 0.0, 0.0]:
        return list(template.pose.pos), list(template.pose.quat)
    return position, quat


EXIT_GRACE = 3.0  # s from SIGINT/SIGTERM to a forced exit, should shutting down ever stall


def install_signal_handlers(server: SimServer) -> None:
    """SIGINT and SIGTERM end the loop; the sim then closes its session and exits. Should that
    stall (a bus call that never returns), it exits anyway after EXIT_GRACE: a stop request
    always stops the sim, well before the launcher's own SIGTERM/SIGKILL escalation."""
    armed: list[threading.Timer] = []

    def stop(signum: int, _frame: Any) -> None:
        server.stop()
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

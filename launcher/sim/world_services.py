"""The world's services under `/world/<w>/`, as gz sim names them (gz-sim's UserCommands and
its world control): control, create, remove, set_pose, state, snapshot and gui, and the web
page's buttons (as control requests).

They run on the loop's thread, between its steps (the runner serves the bus there), and act on
the world through the runner (runner.py) alone: its `world`, `paused` and `no_world`, its
pacing's rate, `control` for pausing and stepping, `spawn_soon` for spawns (added together
between steps), and its `view`. A control request's `multi_step` is stepped by the loop in
batches, the bus served between them: the request is answered at once, and more than
MAX_MULTI_STEP is refused. Spawns that arrive together are added with one recompile.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus.service_table import create_services
from launcher.errors import LaunchError
from launcher.sim.runner import SimulationRunner
from launcher.sim.snapshot import Camera
from launcher.sim.world import Spawn, World

MAX_MULTI_STEP = 100_000_000


class WorldServices:
    def __init__(self, runner: SimulationRunner) -> None:
        self.runner, self.node = runner, runner.node
        self.log = self.node.get_logger()
        self._named: list[Any] = []  # the services named by the world (_serve)
        self._serve(runner.world.world_name)
        self.camera = Camera(runner.world)  # its GL context is made at the first snapshot
        # the web viewer on request (`gz sim -g`), made by start_view(port) if one is given
        self.start_view: Callable[[int | None], Any] | None = None

    def _serve(self, name: str) -> None:
        node = self.node
        for endpoint in self._named:
            endpoint.destroy()
        create = node.create_service("mujoco_sim/srv/Create", f"/world/{name}/create",
                                     self.on_create)
        create.deferred = True
        self._named = [create, *create_services(node, "mujoco_sim", (
            ("control", "Control", self.on_control),
            ("remove", "Remove", self.on_remove),
            ("set_pose", "SetPose", self.on_set_pose),
            ("state", "State", self.on_state),
            ("snapshot", "Snapshot", self.on_snapshot),
            ("gui", "Gui", self.on_gui)), f"/world/{name}")]

    def follow(self, world: World, renamed: bool) -> None:
        """A world loaded in place of the last: the services follow its name, the snapshots
        its model."""
        if renamed:
            self._serve(world.world_name)
        self.camera.close()
        self.camera = Camera(world)

    def close(self) -> None:
        self.camera.close()

    # --- the web viewer ----------------------------------------------------------------------
    def show(self, view: Any) -> None:
        """Serve the world to `view` (viewer.py's WebView), whose page's buttons act as the
        control service's requests do."""
        self.runner.view = view
        view.on_action = self.on_page_action

    def on_gui(self, request: Any, response: Any) -> Any:
        if self.runner.view is None and self.start_view is not None:
            view = self.start_view(request.port or None)
            if view is not None:
                self.show(view)
        if self.runner.view is None:
            response.success = False
            response.message = "the sim could not serve its web viewer (its log says why)"
            return response
        response.success, response.url = True, self.runner.view.url
        return response

    def on_page_action(self, action: str) -> None:
        """The page's Pause, Run, Step or Reset, as a `/world/<w>/control` request."""
        pause = action in ("pause", "step") or (action == "reset" and self.runner.paused)
        request = self.node.message("mujoco_sim/srv/Control_Request", pause=pause,
                                    step=action == "step", reset_all=action == "reset")
        self.on_control(request, self.node.message("mujoco_sim/srv/Control_Response"))
        self.log.info(f"the web viewer's page: {action}")

    # --- the services ------------------------------------------------------------------------
    def on_control(self, request: Any, response: Any) -> Any:
        runner = self.runner
        resetting = request.reset_all or request.reset_time_only or request.reset_model_only
        if resetting:
            runner.world.reset(time=request.reset_all or request.reset_time_only,
                               poses=request.reset_all or request.reset_model_only)
        steps = request.multi_step or (1 if request.step else 0)
        if steps > MAX_MULTI_STEP:
            response.success = False
            response.message = (f"multi_step {steps} is past the limit of {MAX_MULTI_STEP:,} "
                                f"steps in one request")
            return response
        # A reset alone keeps a paused world paused, as Gazebo does; pause/step say otherwise
        keep = resetting and not request.pause and not steps
        runner.control(None if keep else bool(request.pause), steps,
                       restart=bool(request.reset_all or request.reset_time_only))
        response.success = True
        response.message = (f"paused; stepping {steps}" if steps and runner.paused else
                            "paused" if runner.paused else "running")
        return response

    def on_create(self, request: Any, reply: Any) -> None:
        response = reply.new_response()
        try:
            spawn = self._spawn_from(request)
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

        self.runner.spawn_soon(spawn, spawned)

    def _spawn_from(self, request: Any) -> Spawn:
        """What a create request asks to spawn; LaunchError if it cannot be."""
        if self.runner.no_world:
            raise LaunchError("no world is loaded (UnloadWorld removed it): load one first")
        templates = self.runner.world.templates
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
        return Spawn(template, request.name, position, quat, request.allow_renaming,
                     dict(zip(names, map(float, values), strict=True)), request.keyframe)

    def on_remove(self, request: Any, response: Any) -> Any:
        try:
            self.runner.world.remove(request.name)
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
            placement = self.runner.world.placement
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
        world, transport = self.runner.world, self.runner.transport
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
        response.paused = self.runner.paused
        response.real_time_factor = float(self.runner.pacer.rtf)
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

"""gazebo_ros's ROS interface (ROS 1's `/gazebo/*`) over launcher's sim, so the course's
commands work with their own text:

    launcher topic pub /gazebo/set_model_state gazebo_msgs/ModelState '{model_name: …}'
    launcher service call /gazebo/reset_world std_srvs/srv/Empty

Node `gazebo` (so its names are `/gazebo/…`), a client of the sim's own services:
  topics    /gazebo/model_states, /gazebo/link_states (gazebo_msgs/ModelStates, LinkStates;
            from the sim's /world/<w>/model_states and link_states, only while someone
            listens), /gazebo/set_model_state (gazebo_msgs/ModelState, in)
  services  pause_physics, unpause_physics, reset_simulation (time and poses), reset_world
            (poses) (std_srvs/Empty); get_model_state, set_model_state, spawn_urdf_model,
            spawn_sdf_model, delete_model, get_physics_properties, get_world_properties
            (gazebo_msgs)
A reset keeps a paused world paused, as Gazebo does. `reference_frame` may name another
entity (poses are then relative to its model frame); empty, `world` and `map` mean the world.

    gazebo_ros_api [-world NAME] [-timeout S]
"""

from __future__ import annotations

import sys
import time
from typing import Any

from launcher.bus import keys
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.bus.service_table import create_services
from launcher.bus.wire import fill_stamp
from launcher.errors import LaunchError, UsageError
from launcher.nodes.create import SimNotFound, find_world
from launcher.nodes.running import run_node
from launcher.sim.transform import Pose

SIM = "mujoco_sim"
WORLD_FRAMES = ("", "world", "map", "/world")
EMPTY = "std_srvs/srv/Empty"


class GazeboApi:
    def __init__(self, node: Node, world: str) -> None:
        self.node, self.world = node, world

        def sim_client(service: str, type_name: str) -> Any:
            return node.create_client(f"{SIM}/srv/{type_name}", f"/world/{world}/{service}",
                                      space=keys.SIM)
        self.control = sim_client("control", "Control")
        self.create = sim_client("create", "Create")
        self.remove = sim_client("remove", "Remove")
        self.set_pose = sim_client("set_pose", "SetPose")
        self.state = sim_client("state", "State")
        for name, control in (("pause_physics", {"pause": True}),
                              ("unpause_physics", {"pause": False}),
                              ("reset_simulation", {"reset_all": True}),
                              ("reset_world", {"reset_model_only": True})):
            node.create_service(EMPTY, f"~/{name}", self.controlling(control))
        create_services(node, "gazebo_msgs", (
            ("get_model_state", "GetModelState", self.on_get_model_state),
            ("set_model_state", "SetModelState", self.on_set_model_state),
            ("spawn_urdf_model", "SpawnModel", self.on_spawn),
            ("spawn_sdf_model", "SpawnModel", self.on_spawn),
            ("delete_model", "DeleteModel", self.on_delete),
            ("get_physics_properties", "GetPhysicsProperties", self.on_physics),
            ("get_world_properties", "GetWorldProperties", self.on_world)))
        # transient local: a latched publisher's message (ROS 1's `rostopic pub`, which the
        # course uses) reaches it whenever that publisher appears, as ROS 1 latching does
        node.create_subscription("gazebo_msgs/msg/ModelState", "~/set_model_state",
                                 self.on_model_state_topic, QoS(transient_local=True))
        self._relay("model_states", "gazebo_msgs/msg/ModelStates")
        self._relay("link_states", "gazebo_msgs/msg/LinkStates")

    # --- topics -----------------------------------------------------------------------------
    def _relay(self, name: str, type_name: str) -> None:
        """The sim's /world/<w>/<name> as /gazebo/<name>, subscribed only while listened to."""
        publisher = self.node.create_publisher(type_name, f"~/{name}")
        source: list[Any] = []

        def forward(message: Any) -> None:
            out = self.node.message(type_name)
            out.name, out.pose, out.twist = message.name, message.pose, message.twist
            publisher.publish(out)

        def watch(matching: bool) -> None:
            if matching and not source:
                source.append(self.node.create_subscription(
                    f"{SIM}/msg/ModelStates", f"/world/{self.world}/{name}", forward,
                    space=keys.SIM))
            elif not matching and source:
                source.pop().destroy()
        self.node.watch_subscribers(publisher, watch)

    def on_model_state_topic(self, message: Any) -> None:
        ok, text = self._set_state(message)
        if not ok:
            self.node.get_logger().warning(f"/gazebo/set_model_state: {text}")

    # --- services ---------------------------------------------------------------------------
    def _control(self, **fields: Any) -> Any:
        return self.control.call(self.node.message(f"{SIM}/srv/Control_Request", **fields))

    def controlling(self, fields: dict[str, bool]) -> Any:
        """An Empty service's callback that sends the sim's Control with `fields`."""
        def callback(request: Any, response: Any) -> Any:
            self._control(**fields)
            return response
        return callback

    def _state(self) -> Any:
        return self.state.call(self.node.message(f"{SIM}/srv/State_Request"))

    def _poses(self) -> tuple[Any, dict[str, tuple[Pose, Any]]]:
        state = self._state()
        return state, {name: (_pose(p), t) for name, p, t in
                       zip(state.name, state.pose, state.twist, strict=True)}

    def _frame(self, name: str, poses: dict[str, tuple[Pose, Any]]) -> Pose | None:
        """The pose of a reference frame (an entity, or `entity::link` read as the entity)."""
        if name.strip() in WORLD_FRAMES:
            return Pose((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
        entity = name.split("::", 1)[0]
        found = poses.get(entity)
        return None if found is None else found[0]

    def on_get_model_state(self, request: Any, response: Any) -> Any:
        state, poses = self._poses()
        response.header.frame_id = request.relative_entity_name or "world"
        fill_stamp(response.header.stamp, state.sim_time)
        found = poses.get(request.model_name)
        if found is None:
            response.success = False
            response.status_message = (f"GetModelState: model [{request.model_name}] does not "
                                       f"exist; the world has: {', '.join(sorted(poses))}")
            return response
        frame = self._frame(request.relative_entity_name, poses)
        if frame is None:
            response.success = False
            response.status_message = (f"GetModelState: reference relative_entity_name "
                                       f"[{request.relative_entity_name}] not found")
            return response
        _fill_pose(response.pose, frame.inverse() * found[0])
        response.twist = found[1]
        response.success, response.status_message = True, "GetModelState: got properties"
        return response

    def _set_state(self, state: Any) -> tuple[bool, str]:
        _, poses = self._poses()
        if state.model_name not in poses:
            return False, (f"SetModelState: model [{state.model_name}] does not exist; the "
                           f"world has: {', '.join(sorted(poses))}")
        frame = self._frame(state.reference_frame, poses)
        if frame is None:
            return False, (f"SetModelState: reference frame [{state.reference_frame}] not "
                           "found")
        pose = frame * _pose(state.pose)
        request = self.node.message(f"{SIM}/srv/SetPose_Request", name=state.model_name,
                                    set_twist=True)
        _fill_pose(request.pose, pose)
        request.twist = state.twist
        answer = self.set_pose.call(request)
        return bool(answer.success), answer.message

    def on_set_model_state(self, request: Any, response: Any) -> Any:
        response.success, response.status_message = self._set_state(request.model_state)
        if response.success:
            response.status_message = "SetModelState: set model state done"
        return response

    def on_spawn(self, request: Any, response: Any) -> Any:
        _, poses = self._poses()
        frame = self._frame(request.reference_frame, poses)
        if frame is None:
            response.success = False
            response.status_message = (f"SpawnModel: reference frame [{request.reference_frame}]"
                                       " not found")
            return response
        create = self.node.message(f"{SIM}/srv/Create_Request", name=request.model_name,
                                   sdf=request.model_xml)
        _fill_pose(create.pose, frame * _pose(request.initial_pose))
        answer = self.create.call(create, timeout=60.0)
        response.success = bool(answer.success)
        response.status_message = "SpawnModel: Successfully spawned entity" if \
            answer.success else f"SpawnModel: Failure - {answer.message}"
        return response

    def on_delete(self, request: Any, response: Any) -> Any:
        answer = self.remove.call(self.node.message(f"{SIM}/srv/Remove_Request",
                                                    name=request.model_name))
        response.success = bool(answer.success)
        response.status_message = "DeleteModel: successfully deleted model" if \
            answer.success else f"DeleteModel: {answer.message}"
        return response

    def on_physics(self, request: Any, response: Any) -> Any:
        state = self._state()
        response.time_step = state.time_step
        response.pause = bool(state.paused)
        response.max_update_rate = state.real_time_factor / state.time_step if \
            state.time_step > 0 else 0.0
        response.gravity = state.gravity
        response.success, response.status_message = True, "GetPhysicsProperties: got properties"
        return response

    def on_world(self, request: Any, response: Any) -> Any:
        state = self._state()
        response.sim_time = state.sim_time
        response.model_names = list(state.name)
        response.rendering_enabled = False
        response.success, response.status_message = True, "GetWorldProperties: got properties"
        return response


def _pose(message: Any) -> Pose:
    p, q = message.position, message.orientation
    quat = (q.w, q.x, q.y, q.z)
    norm = sum(v * v for v in quat) ** 0.5
    return Pose((p.x, p.y, p.z), tuple(v / norm for v in quat) if norm > 0 else
                (1.0, 0.0, 0.0, 0.0))


def _fill_pose(message: Any, pose: Pose) -> None:
    message.position.x, message.position.y, message.position.z = pose.pos
    o = message.orientation
    o.w, o.x, o.y, o.z = pose.quat


def _options(argv: list[str]) -> dict[str, Any]:
    options: dict[str, Any] = {"timeout": 30.0}
    words = list(argv)
    while words:
        word = words.pop(0)
        if word in ("-world", "-timeout") and words:
            value = words.pop(0)
            if word == "-timeout":
                try:
                    options["timeout"] = float(value)
                except ValueError:
                    raise UsageError(f"-timeout: expected seconds, got '{value}'") from None
            else:
                options["world"] = value
        else:
            raise UsageError(f"unknown argument '{word}' (expected -world NAME, -timeout S)")
    return options


def main() -> int:
    def setup(node: Node) -> None:
        options = _options(node.args)
        timeout = options["timeout"]
        try:
            world = options.get("world") or find_world(
                node, time.monotonic() + timeout, timeout, "control", f"{SIM}/srv/Control")
        except SimNotFound as exc:
            raise LaunchError(f"{exc.message}; is the sim running?") from None
        GazeboApi(node, world)
        node.get_logger().info(f"serving /gazebo/* for world '{world}'")
    return run_node("gazebo", setup)


if __name__ == "__main__":
    sys.exit(main())

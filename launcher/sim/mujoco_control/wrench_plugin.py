"""mujoco_ros2_control's ExternalWrenchPlugin: `apply_wrench`
(mujoco_ros2_control_msgs/srv/ApplyExternalWrench) pushes bodies for a while.

Each wrench names its MJCF body in `wrench.header.frame_id`; its force and torque are given
in that body's frame (the plugin's code rotates them by the body's orientation, whatever its
message's comment says) at `application_point` (body frame), for `duration` of sim time (zero:
one physics step), scaled down to nothing over its last `ramp_down_duration`. They are
applied as MuJoCo's `xfrc_applied` before every physics step, at the body's centre of mass
with the torque the offset adds. A request naming a body the model lacks is refused whole,
with the nearest names; a ramp longer than its duration too. The answer comes once the
longest wrench has ended, in sim time (the plugin sleeps that long in wall time; a paused or
slower sim would answer before its wrench was done). While someone subscribes,
`~/wrench_markers` (the node's, as a sub-node's private name resolves) shows each live wrench
as arrows from its application point in the body's frame: force red (`force_arrow_scale`,
0.01 m/N), torque cyan (`torque_arrow_scale`, 0.1 m/(N m)), both shrinking with the ramp.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from launcher.bus.declarations import Param
from launcher.bus.wire import stamp_seconds
from launcher.errors import did_you_mean
from launcher.sim.mujoco_control.ros_plugin import RosPlugin

SERVICE = "mujoco_ros2_control_msgs/srv/ApplyExternalWrench"
MARKERS = "visualization_msgs/msg/MarkerArray"
SHAFT, HEAD = 0.02, 0.04  # m: the arrows' diameters
ARROW, ADD = 0, 0  # visualization_msgs/Marker


class ExternalWrench(RosPlugin):
    PARAMETERS = (
        Param("force_arrow_scale", "double", 0.01, "a force's arrow: metres per newton"),
        Param("torque_arrow_scale", "double", 0.1, "a torque's arrow: metres per newton metre"),
    )

    def __init__(self, *args: Any) -> None:
        super().__init__(*args)
        self.active: list[tuple[int, np.ndarray, np.ndarray, np.ndarray, float, float]] = []
        self.written: list[int] = []
        self.waiting: list[tuple[float, Any, Any]] = []  # (sim time, reply, response)
        service = self.node.create_service(SERVICE, self.topic("apply_wrench"), self.on_apply)
        service.deferred = True
        self.log.info(f"ExternalWrenchPlugin: {service.name}")
        self.scales = (self.values["force_arrow_scale"], self.values["torque_arrow_scale"])
        self.markers = self.node.create_publisher(
            MARKERS, "~/wrench_markers", 10)

    def on_apply(self, request: Any, reply: Any) -> None:
        response = reply.new_response()
        wrenches = list(request.wrenches.external_wrenches)
        if not wrenches:
            response.success, response.message = True, "No wrenches provided; nothing applied."
            reply.send(response)
            return
        model, now = self.world.model, float(self.world.data.time)
        bodies = [model.body(i).name for i in range(model.nbody)]
        made = []
        for wrench in wrenches:
            name = wrench.wrench.header.frame_id
            body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name)
            duration = stamp_seconds(wrench.duration)
            ramp = stamp_seconds(wrench.ramp_down_duration)
            refused = (f"Body '{name}' not found in MuJoCo model{did_you_mean(name, bodies)}"
                       if body < 0 else f"body '{name}': ramp_down_duration {ramp:g} s is "
                       f"longer than duration {duration:g} s" if ramp > duration else "")
            if refused:
                self.log.warning(refused)
                response.success, response.message = False, refused
                reply.send(response)  # (nothing of this request is applied)
                return
            force = wrench.wrench.wrench.force
            torque = wrench.wrench.wrench.torque
            point = wrench.application_point
            made.append((body, np.array([force.x, force.y, force.z]),
                         np.array([torque.x, torque.y, torque.z]),
                         np.array([point.x, point.y, point.z]), now + duration, ramp))
        self.active += made
        response.success = True
        response.message = f"Applied {len(made)} wrench(es) successfully."
        self.waiting.append((max(end for *_, end, _ in made), reply, response))

    def step(self, model: Any, data: Any) -> None:
        """Before every physics step: last step's wrenches off, the live ones on."""
        for body in self.written:
            data.xfrc_applied[body] = 0.0
        self.written = []
        now = float(data.time)
        for body, force, torque, point, end, ramp in self.active:
            scale = 1.0 if ramp <= 0 or end - now >= ramp else max(0.0, (end - now) / ramp)
            turn = data.xmat[body].reshape(3, 3)
            f, t = turn @ (force * scale), turn @ (torque * scale)
            at = data.xpos[body] + turn @ point
            data.xfrc_applied[body, :3] += f
            data.xfrc_applied[body, 3:] += t + np.cross(at - data.xipos[body], f)
            self.written.append(body)
        self.active = [w for w in self.active if now < w[4]]

    def update(self, model: Any, data: Any, now: float) -> None:
        """Each control cycle: requests whose wrenches have all ended are answered; the
        live wrenches' markers published."""
        done = [w for w in self.waiting if w[0] <= now]
        self.waiting = [w for w in self.waiting if w[0] > now]
        for _, reply, response in done:
            reply.send(response)
        if self.markers.get_subscription_count():
            self.markers.publish(self._markers(model, now))

    def _markers(self, model: Any, now: float) -> Any:
        node, markers = self.node, []
        for body, force, torque, point, end, ramp in self.active:
            scale = 1.0 if ramp <= 0 or end - now >= ramp else max(0.0, (end - now) / ramp)
            for vector, arrow_scale, part, colour in (
                    (force, self.scales[0], "force", (1.0, 0.0, 0.0)),
                    (torque, self.scales[1], "torque", (0.0, 0.7, 0.9))):
                if float(vector @ vector) <= 1e-18:
                    continue
                tip = point + vector * arrow_scale * scale
                markers.append(node.message(
                    "visualization_msgs/msg/Marker",
                    header={"frame_id": model.body(body).name},  # (stamp 0: the latest tf)
                    ns=f"external_wrench/{part}", id=len(markers), type=ARROW, action=ADD,
                    points=[dict(zip("xyz", map(float, p), strict=True)) for p in (point, tip)],
                    scale={"x": SHAFT, "y": HEAD, "z": 0.0},
                    color=dict(zip("rgba", (*colour, 0.8), strict=True))))
        return node.message(MARKERS, markers=markers)

"""A world's cameras and the renderer that draws them.

The renderer is a process of its own (launcher/nodes/renderer.py), a node on the bus like any
other: the sim publishes its compiled model (MJB) with each camera's settings, latched, on
`/world/<w>/render/model` whenever the model changes, and on `/world/<w>/render/state` the
state to draw (qpos, mocap, sim time) and which cameras are due; the renderer publishes the
images on the cameras' topics and says which cameras anyone watches, and which model version
it holds, on `/world/<w>/render/wanted`. So the stepping thread never renders, a frame the
renderer is late with is dropped, and the renderer can run on another host (a GPU machine)
through the same router mesh: start it there with `launcher run mujoco_sim renderer --world W`
and set LAUNCHER_RENDERER=none for the sim, which otherwise starts one itself.

The model is published once per change, and a renderer whose route to the sim formed late
(under load) can miss that one publication: it would then drop every state, for want of the
model. Its wanted message, said again every half second, closes the loop: when the version it
holds is not the sim's, the sim publishes the same model again (its arrival proves the route).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np

from launcher.bus.qos import LATCHED, QoS

RENDERER_VARIABLE = "LAUNCHER_RENDERER"  # "none": the sim starts no renderer of its own
RESEND_AFTER = 2.0  # s: the model is sent again to a renderer that lacks it, at most this often


def rendering_of(sim: Any) -> Rendering:
    """The world's rendering link, made when its first camera loads."""
    found = getattr(sim, "rendering", None)
    if found is None:
        found = sim.rendering = Rendering(sim)
    return found


class Rendering:
    def __init__(self, sim: Any, clock: Callable[[], float] = time.monotonic) -> None:
        self.sim, self.clock = sim, clock
        transport, world = sim.transport, sim.world_name
        self.cameras: dict[str, Any] = {}
        self.version = 0
        self.sequence = 0
        self._published: tuple[Any, int] | None = None  # (model, cameras) last sent
        self._model_message: Any = None  # the last model sent (again to a renderer lacking it)
        self._model_sent_at = 0.0  # (clock) when it was last sent
        self.wanted: set[str] = set()
        self.model_publisher = transport.publisher(
            "mujoco_sim/msg/RenderModel", f"/world/{world}/render/model", LATCHED)
        self.state_publisher = transport.publisher(
            "mujoco_sim/msg/RenderState", f"/world/{world}/render/state", QoS(depth=1))
        self.subscription = transport.subscribe(
            "mujoco_sim/msg/StringMsg", f"/world/{world}/render/wanted", self._on_wanted)
        self.process: subprocess.Popen[bytes] | None = None

    def add(self, camera: Any) -> None:
        self.cameras[camera.camera_name] = camera
        self._published = None  # the settings changed: send the model again
        if self.process is None and os.environ.get(RENDERER_VARIABLE, "") != "none":
            self.process = subprocess.Popen(
                [sys.executable, "-m", "launcher.nodes.renderer", "--world",
                 self.sim.world_name, "--parent", str(os.getpid())])

    def remove(self, camera: Any) -> None:
        self.cameras.pop(camera.camera_name, None)
        self._published = None
        if not self.cameras:
            self.close()

    def wants(self, camera: str) -> bool:
        return camera in self.wanted

    def _on_wanted(self, message: Any) -> None:
        self.wanted, held = _wanted_of(message.data)
        if held is not None and held != self.version:
            self._send_model_again(held)

    def _send_model_again(self, held: int) -> None:
        """The renderer holds model version `held`, not the sim's: the model is published
        again, the same message (its version unchanged), unless it was sent less than
        RESEND_AFTER ago (a model takes a while to cross and load, and what the renderer
        said may predate the model on its way to it)."""
        now = self.clock()
        if self._model_message is None or now - self._model_sent_at < RESEND_AFTER:
            return
        self._model_sent_at = now
        self.sim.transport.logger.debug(
            f"the renderer holds model version {held}, not {self.version}: sending it again")
        self.model_publisher.publish(self._model_message)

    def sync(self, model: Any) -> None:
        """Send the model and the cameras' settings when either changed."""
        if self._published == (model, len(self.cameras)) or not self.cameras:
            return
        self._published = (model, len(self.cameras))
        self.version += 1
        size = mujoco.mj_sizeModel(model)
        buffer = np.empty(size, dtype=np.uint8)
        mujoco.mj_saveModel(model, None, buffer)
        from launcher.sim.plugins.label import labels_of  # (its import loads sim/sdf/: here,
        # not at the top, so that a camera plugin may be imported before the SDF loader)

        settings = [camera.settings() for camera in self.cameras.values()]
        self._model_message = self.sim.transport.message(
            "mujoco_sim/msg/RenderModel", version=self.version, cameras=json.dumps(settings),
            model=buffer.tobytes(), labels=json.dumps(labels_of(self.sim)))
        self._model_sent_at = self.clock()
        self.model_publisher.publish(self._model_message)

    def request(self, cameras: list[str], data: Any) -> None:
        """Ask the renderer to draw `cameras` from the state `data` holds now."""
        self.sync(self.sim.model)
        self.sequence += 1
        self.state_publisher.publish(self.sim.transport.message(
            "mujoco_sim/msg/RenderState", version=self.version, sequence=self.sequence,
            time=float(data.time),
            cameras=cameras, qpos=data.qpos.copy(), mocap_pos=data.mocap_pos.reshape(-1).copy(),
            mocap_quat=data.mocap_quat.reshape(-1).copy()))

    def close(self) -> None:
        if self.process is not None:
            self.process.terminate()
            try:
                self.process.wait(5)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
            self.process = None

    def retire(self) -> None:
        """Its world is gone (another was loaded): the renderer stopped, the topics given up
        (the latched model with them)."""
        self.close()
        for endpoint in (self.model_publisher, self.state_publisher, self.subscription):
            endpoint.destroy()


def _wanted_of(data: str) -> tuple[set[str], int | None]:
    """The cameras a renderer's wanted message names, and the model version it holds (-1:
    none; None from a renderer that says only the cameras, as a plain list)."""
    try:
        said = json.loads(data)
        if isinstance(said, dict):
            version = said.get("version")
            return set(said.get("cameras", ())), version if isinstance(version, int) else None
        return set(said), None
    except (ValueError, TypeError):
        return set(), None

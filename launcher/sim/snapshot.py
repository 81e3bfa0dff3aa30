"""Offscreen pictures of the world: MuJoCo's renderer (EGL, or OSMesa with MUJOCO_GL=osmesa),
encoded as PNG without an imaging library."""

from __future__ import annotations

import os
import struct
import zlib
from typing import Any

import mujoco
import numpy as np

from launcher.errors import LaunchError, did_you_mean
from launcher.sim.world import World

DEFAULT_SIZE = (640, 480)
MAX_SIDE = 4096
SHADOW_CLIP = 0.2  # of the model's extent: sharp shadows near the robots, none far out
GL_HELP = ("offscreen rendering needs EGL (Debian: apt-get install libegl1 libegl-mesa0 "
           "libgl1-mesa-dri) or OSMesa (apt-get install libosmesa6, then MUJOCO_GL=osmesa)")


def encode_png(pixels: np.ndarray) -> bytes:
    """An RGB uint8 image (height × width × 3) as a PNG file's bytes."""
    height, width, _ = pixels.shape
    rows = np.zeros((height, width * 3 + 1), dtype=np.uint8)  # filter byte 0 on each row
    rows[:, 1:] = pixels.reshape(height, width * 3)

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data)))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(rows.tobytes(), 6)) + chunk(b"IEND", b""))


class Camera:
    """Renders one world; keeps its renderer until the model is recompiled or resized."""

    def __init__(self, world: World) -> None:
        self.world = world
        self._renderer: Any = None
        self._key: tuple = ()

    def png(self, width: int = 0, height: int = 0, camera: str = "", track: str = "") -> bytes:
        width, height = width or DEFAULT_SIZE[0], height or DEFAULT_SIZE[1]
        if not (0 < width <= MAX_SIDE and 0 < height <= MAX_SIDE):
            raise LaunchError(f"snapshot size {width}x{height}: each side must be 1 to "
                              f"{MAX_SIDE} pixels")
        renderer = self._renderer_for(width, height)
        renderer.update_scene(self.world.data, camera=self._view(camera, track))
        return encode_png(renderer.render())

    def close(self) -> None:
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None

    # --- the view --------------------------------------------------------------------------
    def _view(self, camera: str, track: str) -> Any:
        model = self.world.model
        if camera:
            names = [model.camera(i).name for i in range(model.ncam)]
            if camera not in names:
                known = ", ".join(n for n in names if n) or "none"
                raise LaunchError(f"no camera '{camera}' in world '{self.world.world_name}'"
                                  f"{did_you_mean(camera, names)} (cameras: {known})")
            return camera
        entities = self.world.entities
        if track and track not in entities:
            raise LaunchError(f"no entity '{track}' in world '{self.world.world_name}'"
                              f"{did_you_mean(track, list(entities))}")
        view = mujoco.MjvCamera()
        mujoco.mjv_defaultFreeCamera(model, view)
        framed = framing(self.world, [track] if track else None)
        if framed is not None:  # the entities rather than the whole (often huge) ground
            view.lookat[:], view.distance = framed
        view.azimuth, view.elevation = AZIMUTH, ELEVATION
        return view


    def _renderer_for(self, width: int, height: int) -> Any:
        model = self.world.model
        key = (id(model), width, height)
        if self._renderer is not None and key == self._key:
            return self._renderer
        self.close()
        visual = model.vis.global_
        visual.offwidth, visual.offheight = max(visual.offwidth, width), \
            max(visual.offheight, height)
        if model.vis.map.shadowclip == 1.0:  # MuJoCo's default: one shadow map over the whole
            model.vis.map.shadowclip = SHADOW_CLIP  # extent speckles a large ground
        try:
            self._renderer = mujoco.Renderer(model, height, width)
        except Exception as exc:  # the GL libraries raise many kinds; all mean the same
            backend = os.environ.get("MUJOCO_GL", "")
            raise LaunchError(f"cannot render (MUJOCO_GL={backend}): {exc}; "
                              f"{GL_HELP}") from None
        self._key = key
        return self._renderer


AZIMUTH, ELEVATION = 135.0, -30.0  # the free view's direction: from the side, above


def framing(world: World, names: list[str] | None = None) -> tuple[Any, float] | None:
    """(look-at point, distance) of a free view that frames the named entities, or every one
    but the ground (a plane is everywhere); None when there is nothing to frame."""
    model, data, entities = world.model, world.data, world.entities
    chosen = [entities[n] for n in names] if names is not None else \
        [e for e in entities.values() if not _is_ground(model, e.body)]
    if not chosen:
        return None
    points = np.array([data.xpos[e.body] for e in chosen])
    center = points.mean(axis=0)
    if names is not None and len(chosen) == 1:  # one entity (--track): framed whole
        return center, max(2.0, 3.0 * _radius(model, data, chosen[0].body))
    spread = float(np.max(np.linalg.norm(points - center, axis=1)))
    return center, max(2.0, 2.5 * spread + 1.5)


def _radius(model: Any, data: Any, body: int) -> float:
    """How far the entity's geometry reaches from its body's origin."""
    geoms = [g for g in range(model.ngeom)
             if model.body_rootid[model.geom_bodyid[g]] == model.body_rootid[body]]
    if not geoms or model.body_rootid[body] == 0:
        return 0.0
    reach = [float(np.linalg.norm(data.geom_xpos[g] - data.xpos[body])) + model.geom_rbound[g]
             for g in geoms]
    return max(reach)


def _is_ground(model: Any, body: int) -> bool:
    """A ground plane (Gazebo's `ground_plane` model) is framed by nothing: it is
    everywhere."""
    start, count = int(model.body_geomadr[body]), int(model.body_geomnum[body])
    return any(model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE
               for g in range(start, start + count))

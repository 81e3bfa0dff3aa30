"""MuJoCo's own renderer on an offscreen GL context (the public API mujoco.Renderer is made
of: GLContext, MjrContext, MjvScene, mjr_render, mjr_readPixels), for the cameras' colour and
depth: each buffer read into arrays made once, depth made metric in float32 in place.

mujoco.Renderer turns a depth buffer into metres through float64 copies of the whole picture;
with reversed Z (MuJoCo's depth map ZEROFAR) float32 holds the same metres to its own
precision, and at 640 × 480 doing it in place is most of the difference between the depth
frames a camera delivers and those the renderer draws (bench/sensors.py). Depth is drawn as
mujoco.Renderer draws it: segmented (no lighting), which also keeps far depths accurate.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np


class Offscreen:
    def __init__(self, model: Any, width: int, height: int) -> None:
        self.model, self.width, self.height = model, width, height
        self.gl = mujoco.GLContext(width, height)
        self.gl.make_current()
        self.context = mujoco.MjrContext(model, mujoco.mjtFontScale.mjFONTSCALE_150.value)
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN.value, self.context)
        self.context.readDepthMap = mujoco.mjtDepthMap.mjDEPTH_ZEROFAR
        self.scene = mujoco.MjvScene(model, maxgeom=10000)
        self.option = mujoco.MjvOption()
        self.camera = mujoco.MjvCamera()
        self.camera.type = mujoco.mjtCamera.mjCAMERA_FIXED
        self.rect = mujoco.MjrRect(0, 0, width, height)
        self._rgb = np.empty((height, width, 3), dtype=np.uint8)
        self._depth = np.empty((height, width), dtype=np.float32)

    def _draw(self, data: Any, camera: int, segmented: bool) -> None:
        self.gl.make_current()
        self.camera.fixedcamid = camera
        mujoco.mjv_updateScene(self.model, data, self.option, None, self.camera,
                               mujoco.mjtCatBit.mjCAT_ALL.value, self.scene)
        flags = self.scene.flags
        flags[mujoco.mjtRndFlag.mjRND_SEGMENT] = flags[mujoco.mjtRndFlag.mjRND_IDCOLOR] = \
            segmented
        mujoco.mjr_render(self.rect, self.scene, self.context)

    def colour(self, data: Any, camera: int) -> np.ndarray:
        """The camera's RGB picture (H × W × 3 uint8, top row first): a new array."""
        self._draw(data, camera, False)
        mujoco.mjr_readPixels(self._rgb, None, self.rect, self.context)
        return self._rgb[::-1].copy()

    def depth(self, data: Any, camera: int) -> np.ndarray:
        """The camera's depth in metres (H × W float32, top row first): a new array."""
        self._draw(data, camera, True)
        mujoco.mjr_readPixels(None, self._depth, self.rect, self.context)
        extent = self.model.stat.extent
        near = np.float32(self.model.vis.map.znear * extent)
        far = np.float32(self.model.vis.map.zfar * extent)
        if self.scene.camera[0].orthographic:  # the buffer is linear in depth
            out = np.multiply(self._depth[::-1], near - far)
            out += far
            return out
        # reversed Z's perspective: metres = d / (buffer + c) (mujoco.Renderer's, in float32)
        c = np.float32(-0.5) * (-(far + near) / (far - near)) - np.float32(0.5)
        d = np.float32(-0.5) * (-(np.float32(2) * far * near) / (far - near))
        out = np.add(self._depth[::-1], c)
        np.divide(d, out, out=out)
        return out

    def close(self) -> None:
        self.gl.make_current()
        self.context.free()
        self.gl.free()

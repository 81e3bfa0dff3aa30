"""What a camera's picture goes through after MuJoCo draws it, as gz-sensors and gz-rendering
do it: image noise, lens distortion, and a segmentation camera's label maps. Plain numpy on
whole pictures, so the renderer (nodes/renderer.py) pays a few array passes a frame."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

GEOM = 5  # mujoco.mjtObj.mjOBJ_GEOM: a segmentation pixel's object type for a geom


# --- noise ---------------------------------------------------------------------------------
def add_noise(picture: Any, rng: np.random.Generator, mean: float, stddev: float,
              unit: float) -> Any:
    """gz-sensors' image noise: each value plus a gaussian draw, in `unit`s (255 a colour
    channel, 1 a metre of depth); colours rounded and clamped."""
    draws = rng.standard_normal(picture.shape, dtype=np.float32)
    draws *= stddev * unit
    draws += mean * unit
    if picture.dtype == np.uint8:
        draws += picture
        return np.clip(np.rint(draws, out=draws), 0, 255).astype(np.uint8)
    return picture + draws


# --- distortion ----------------------------------------------------------------------------
@dataclass
class Lens:
    """How a distorted camera is drawn: MuJoCo draws an undistorted picture wide enough for
    all the lens sees (`width` × `height` pixels, `fovy` degrees, at the camera's focal
    length), and `index` gives, for each pixel of the distorted picture, the pixel of that
    one it shows (-1: none)."""
    index: Any
    width: int
    height: int
    fovy: float


MAX_SPREAD = 3.0  # a lens may widen the drawn picture to three times the camera's, no more


def lens(width: int, height: int, k: list[float], coefficients: list[float],
         iterations: int = 20) -> Lens:
    """The Brown model camera_info gives (plumb_bob: k1, k2, p1, p2, k3, about the principal
    point), so that image_proc's rectification undoes it exactly. Each distorted pixel's
    undistorted direction comes from inverting the model by fixed-point iteration, as
    OpenCV's undistortPoints does; a barrel lens sees past the camera's field of view, so
    the picture drawn is widened to hold it."""
    k1, k2, p1, p2, k3 = coefficients
    fx, cx, fy, cy = k[0], k[2], k[4], k[5]
    u, v = np.meshgrid(np.arange(width, dtype=np.float64) + 0.5,
                       np.arange(height, dtype=np.float64) + 0.5)
    xd, yd = (u - cx) / fx, (v - cy) / fy
    x, y = xd.copy(), yd.copy()
    with np.errstate(all="ignore"):  # (a strong lens's rim may diverge: it shows nothing)
        for _ in range(iterations):
            r2 = x * x + y * y
            radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3))
            x, y = ((xd - (2 * p1 * x * y + p2 * (r2 + 2 * x * x))) / radial,
                    (yd - (p1 * (r2 + 2 * y * y) + 2 * p2 * x * y)) / radial)
        r2 = x * x + y * y  # where the answer lands when distorted again: converged?
        radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3))
        again_x = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
        again_y = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
        good = (np.abs(again_x - xd) * fx < 0.5) & (np.abs(again_y - yd) * fy < 0.5) & \
            (radial > 0)
    half_x = min(float(np.abs(x[good]).max(initial=0.0)), MAX_SPREAD * width / (2 * fx))
    half_y = min(float(np.abs(y[good]).max(initial=0.0)), MAX_SPREAD * height / (2 * fy))
    half_x = max(half_x, width / (2 * fx))
    half_y = max(half_y, height / (2 * fy))
    drawn_w, drawn_h = 2 * math.ceil(half_x * fx) + 2, 2 * math.ceil(half_y * fy) + 2
    with np.errstate(all="ignore"):
        su, sv = np.floor(x * fx + drawn_w / 2), np.floor(y * fy + drawn_h / 2)
        inside = good & (su >= 0) & (su < drawn_w) & (sv >= 0) & (sv < drawn_h)
    index = np.where(inside, np.nan_to_num(sv) * drawn_w + np.nan_to_num(su), -1)
    return Lens(index.astype(np.int64).reshape(-1), drawn_w, drawn_h,
                math.degrees(2 * math.atan(drawn_h / (2 * fy))))


def distort(drawn: Any, found: Lens, shape: tuple[int, ...], fill: Any) -> Any:
    """The picture seen through the lens, from the wider one drawn for it; `fill` where the
    lens shows nothing."""
    flat = drawn.reshape(found.width * found.height, -1)
    out = flat[np.maximum(found.index, 0)]
    out[found.index < 0] = fill
    return out.reshape(shape)


# --- segmentation --------------------------------------------------------------------------
def segmentation_tables(model: Any, labels: dict[str, int]) -> tuple[Any, Any]:
    """Each geom's label (0: none) and its instance among its label's: its top-level model's
    rank, from 1, among the models with visuals of that label (gz-rendering counts them so)."""
    label = np.zeros(model.ngeom, dtype=np.int64)
    for name, value in labels.items():
        try:
            label[model.geom(name).id] = int(value)
        except KeyError:
            continue
    roots = model.body_rootid[model.geom_bodyid]
    instance = np.zeros(model.ngeom, dtype=np.int64)
    for value in set(label[label > 0].tolist()):
        carrying = sorted(set(roots[label == value].tolist()))
        rank = {root: n for n, root in enumerate(carrying, 1)}
        for geom in np.flatnonzero(label == value):
            instance[geom] = rank[int(roots[geom])]
    return label, instance


def segment(segmentation: Any, geom_label: Any, geom_instance: Any,
            panoptic: bool) -> tuple[Any, Any]:
    """The labels map and the coloured map of MuJoCo's segmentation picture (each pixel's
    object id and type), as gz-rendering lays them out: semantic, each pixel's label in all
    three channels; panoptic, the instance count (low byte, high byte) then the label. A pixel
    of no labelled visual is the background's (0, black)."""
    ids, types = segmentation[..., 0], segmentation[..., 1]
    geoms = (types == GEOM) & (ids >= 0) & (ids < len(geom_label))
    label = np.zeros(ids.shape, dtype=np.int64)
    label[geoms] = geom_label[ids[geoms]]
    label8 = label.astype(np.uint8)
    if panoptic:
        instance = np.zeros(ids.shape, dtype=np.int64)
        instance[geoms] = geom_instance[ids[geoms]]
        labels = np.stack([(instance % 256).astype(np.uint8),
                           (instance // 256 % 256).astype(np.uint8), label8], axis=-1)
        return labels, colours(np.where(label > 0, label * 65536 + instance, 0))
    return np.stack([label8, label8, label8], axis=-1), colours(label)


def colours(keys: Any) -> Any:
    """A colour per key (a fixed pseudo-random one; the background, 0, black), to look at."""
    index = keys.astype(np.uint64)
    colour = np.stack([(index * 97 + 31) % 256, (index * 57 + 101) % 256,
                       (index * 151 + 7) % 256], axis=-1).astype(np.uint8)
    colour[keys == 0] = 0
    return colour

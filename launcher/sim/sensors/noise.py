"""SDF's `<noise>`: Gaussian noise with a bias, as gz-sensors applies it, drawn from one
seeded generator per sensor (the same seed gives the same readings)."""

from __future__ import annotations

import zlib
from dataclasses import dataclass
from typing import Any

import numpy as np

from launcher.sim.sdf.pose import child_number
from launcher.sim.sdf.xmltree import SdfError

TYPES = ("none", "gaussian", "gaussian_quantized")


def generator(seed: int, name: str) -> np.random.Generator:
    """The generator of the sensor `name` in a world run with `seed`."""
    return np.random.default_rng([seed, zlib.crc32(name.encode())])


@dataclass
class Noise:
    mean: float = 0.0
    stddev: float = 0.0
    bias: float = 0.0  # drawn once, from bias_mean and bias_stddev, its sign at random
    precision: float = 0.0  # gaussian_quantized: values are rounded to this step

    def apply(self, value: float, rng: np.random.Generator) -> float:
        if self.stddev > 0:
            value += rng.normal(self.mean, self.stddev)
        else:
            value += self.mean
        value += self.bias
        if self.precision > 0:
            value = round(value / self.precision) * self.precision
        return value


NONE = Noise()


def noise_of(element: Any, rng: np.random.Generator) -> Noise:
    """The `<noise>` child of `element` (no noise when there is none); a type or value that
    is not one is an error at its line."""
    found = element.find("noise") if element is not None else None
    if found is None:
        return NONE
    kind = found.get("type", "gaussian") or found.value("type") or "gaussian"
    if kind not in TYPES:
        raise SdfError(f"<noise type='{kind}'>: expected one of {', '.join(TYPES)}",
                       found.location)
    if kind == "none":
        return NONE
    values = {tag: child_number(found, tag)
              for tag in ("mean", "stddev", "bias_mean", "bias_stddev", "precision")}
    for tag in ("stddev", "bias_stddev", "precision"):
        if values[tag] < 0:
            raise SdfError(f"<noise><{tag}> must be ≥ 0, got {values[tag]:g}", found.location)
    bias = 0.0
    if values["bias_mean"] or values["bias_stddev"]:
        bias = rng.normal(values["bias_mean"], values["bias_stddev"]) \
            if values["bias_stddev"] > 0 else values["bias_mean"]
        bias *= 1.0 if rng.random() < 0.5 else -1.0
    return Noise(values["mean"], values["stddev"], bias,
                 values["precision"] if kind == "gaussian_quantized" else 0.0)

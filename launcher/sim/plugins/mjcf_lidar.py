"""mujoco_ros2_control's lidar sensor extension (`mujoco.plugin.lidar`), which MuJoCo's Python
does not have: the rays of an MJCF lidar sensor cast from its site with `mj_multiRay`.

Its settings are the extension's `<config>` keys: `resolution` (horizontal and vertical
rays), `azimuth_range`, `elevation_range` (one angle when there is one row), `max_range`,
`min_range` (0), `update_rate` (1 Hz; 0 is every step). Ray (e, a) points at azimuth a and
elevation e of the site's frame, rows of azimuths one elevation after another; a distance
past `max_range`, under `min_range` or with nothing hit is -1, as the extension writes it.
Like the extension, a scan is taken when `1 / update_rate` of sim time has passed since the
last (from the first step on), whoever reads it; `ranges` and `stamp` (the sim time it was
taken) are what mujoco_ros2_control's 3D lidar plugin publishes (lidar3d_plugin.py). A wrong
setting is an error at the sensor's line (the extension's words), and the sim goes on without
that lidar. `async` is accepted: the scan is taken in the step.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from launcher.errors import did_you_mean
from launcher.sim import schedule
from launcher.sim.plugins import Plugin, PluginError

KEYS = ("resolution", "azimuth_range", "elevation_range", "max_range", "min_range",
        "update_rate", "async")


class MjcfLidar(Plugin):
    def __init__(self, sim: Any, entity: Any, config: Any) -> None:
        super().__init__(sim, entity, config)
        self.configs = {c.get("key", ""): c.get("value", "")
                        for c in config.element.findall("config")}
        for key in self.configs:
            if key not in KEYS:
                self.fail(f"unknown config key '{key}'{did_you_mean(key, KEYS)} (keys: "
                          f"{', '.join(KEYS)})")
        if config.element.get("objtype") != "site":
            self.fail("Lidar must be attached to a site (objtype=\"site\" objname=…)")
        self.site_name = config.element.get("objname", "")
        resolution = self._numbers("resolution")
        if len(resolution) != 2:
            self.fail("Both horizontal and vertical resolutions must be specified")
        if resolution[0] <= 0 or resolution[1] <= 0 or \
                any(r != int(r) for r in resolution):
            self.fail("Horizontal and vertical resolutions must be positive whole numbers")
        self.resolution = (int(resolution[0]), int(resolution[1]))
        self.azimuth_range = self._range("azimuth_range", "azimuth")
        self.elevation_range = self._elevation()
        self.max_range = self._number("max_range", None)
        if self.max_range is None:
            self.fail("Lidar max range must be specified")
        if self.max_range <= 0.0:
            self.fail("Lidar max range must be greater than 0.0")
        self.min_range = self._number("min_range", 0.0)
        if self.min_range < 0.0:
            self.fail("Lidar min range must be greater than 0.0")
        rate = self._number("update_rate", 1.0)
        if rate < 0.0:
            self.fail("Lidar update rate must be greater than 0.0")
        self.period = schedule.period(rate)
        azimuths = np.linspace(*self.azimuth_range, self.resolution[0]) \
            if self.resolution[0] > 1 else np.zeros(1)
        elevations = np.linspace(*self.elevation_range, self.resolution[1]) \
            if self.resolution[1] > 1 else np.array([self.elevation_range[0]])
        e, a = np.meshgrid(elevations, azimuths, indexing="ij")
        self.directions = np.stack([np.cos(a) * np.cos(e), np.sin(a) * np.cos(e), np.sin(e)],
                                   axis=-1).reshape(-1, 3)
        self.ranges = np.full(len(self.directions), -1.0)
        self.geoms = np.zeros(len(self.directions), dtype=np.int32)
        self.stamp = 0.0  # the sim time of the last scan (0: none yet)
        self.last = -1.0  # the extension's first "last compute time"
        self.site = -1

    def fail(self, message: str) -> None:
        raise PluginError(f"{self.config.where}: lidar sensor '{self.label}': {message}")

    def _numbers(self, key: str) -> list[float]:
        text = self.configs.get(key, "")
        try:
            return [float(v) for v in text.replace(",", " ").split()]
        except ValueError:
            self.fail(f"{key}=\"{text}\" is not numbers")
            return []

    def _number(self, key: str, default: float | None) -> Any:
        values = self._numbers(key)
        return values[0] if values else default

    def _range(self, key: str, what: str) -> tuple[float, float]:
        values = self._numbers(key)
        if len(values) != 2:
            self.fail(f"Both minimum and maximum {what} angles must be specified")
        if values[0] < -math.pi or values[1] > math.pi:
            self.fail(f"`{key}` must lie within -pi and pi")
        if values[0] >= values[1]:
            self.fail(f"`{key} minimum` must less than `{key} maximum`")
        return values[0], values[1]

    def _elevation(self) -> tuple[float, float]:
        values = self._numbers("elevation_range")
        if not values:
            self.fail("Minimum elevation angle must be specified")
        if len(values) == 1:
            if self.resolution[1] > 1:
                self.fail("When elevation resolution is greater than 1, maximum elevation "
                          "must be specified")
            values.append(values[0])
        if values[0] < -math.pi or values[1] > math.pi:
            self.fail("`elevation_range` must lie within -pi and pi")
        if self.resolution[1] > 1 and values[0] >= values[1]:
            self.fail("`elevation_range minimum` must less than `elevation_range maximum`")
        return values[0], values[1]

    def bind(self, model: Any, data: Any) -> None:
        prefix = f"{self.entity.name}/" if self.entity is not None else ""  # (a spawned one's)
        names = [model.site(i).name for i in range(model.nsite)]
        if prefix + self.site_name not in names:
            self.fail(f"site '{self.site_name}' is not in the model"
                      f"{did_you_mean(prefix + self.site_name, names)}")
        self.site = names.index(prefix + self.site_name)

    def reset(self) -> None:
        self.last, self.stamp, self.next_update = -1.0, 0.0, 0.0
        self.ranges[:] = -1.0

    def post_step(self, model: Any, data: Any) -> None:
        if self.period > 0.0 and data.time - self.last < self.period:
            self.next_update = self.last + self.period
            return
        self.last = data.time
        self.next_update = data.time + self.period
        rotation = data.site_xmat[self.site].reshape(3, 3)
        vectors = np.ascontiguousarray(self.directions @ rotation.T).reshape(-1)
        mujoco.mj_multiRay(model, data, data.site_xpos[self.site], vectors, None, 1, -1,
                           self.geoms, self.ranges, None, len(self.ranges), self.max_range)
        self.ranges[(self.ranges >= self.max_range) | (self.ranges < self.min_range)] = -1.0
        self.stamp = data.time

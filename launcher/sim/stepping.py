"""Stepping the physics in batches: the plugins' pre_step hooks, `mj_step` N times, the
post_step hooks that are due, and MuJoCo's instability warnings turned into one logged event
each (MuJoCo resets the state; the sim goes on). While the world is paused, `idle` runs the
plugins' paused hooks instead."""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.sim.plugin_host import PluginHost
from launcher.sim.schedule import SLACK

UNSTABLE = (mujoco.mjtWarning.mjWARN_BADQPOS, mujoco.mjtWarning.mjWARN_BADQVEL,
            mujoco.mjtWarning.mjWARN_BADQACC)
_QPOS, _QVEL, _QACC = (int(kind) for kind in UNSTABLE)  # indices into data.warning


class Physics:
    def __init__(self, plugins: PluginHost, logger: Any) -> None:
        self.plugins, self.logger = plugins, logger
        self.iterations = 0
        self.model: Any = None
        self.data: Any = None
        self._unstable = dict.fromkeys(UNSTABLE, 0)
        self._unstable_total = 0

    def bind(self, model: Any, data: Any) -> None:
        """New model and data (after a recompile): their warning counts are the new zero."""
        self.model, self.data = model, data
        self._unstable = {kind: data.warning[kind].number for kind in UNSTABLE}
        self._unstable_total = sum(self._unstable.values())

    def steps_until_update(self, limit: int) -> int:
        """How many steps may run before a plugin needs its post_step (at least 1)."""
        if not self.plugins.post:
            return max(1, limit)
        due = min(p.next_update for p in self.plugins.post) - self.data.time
        if due == math.inf:  # (a sensor whose system the world lacks: never)
            return max(1, limit)
        # the steps until a step's time is on the due time (within schedule.SLACK)
        return max(1, min(limit, math.ceil((due - SLACK) / self.model.opt.timestep)))

    def step(self, count: int = 1) -> None:
        """Step `count` times; pre_step hooks run before, post_step hooks that are due after."""
        model, data = self.model, self.data
        for plugin in self.plugins.pre:
            try:
                plugin.pre_step(model, data)
            except Exception as exc:
                self.plugins.failed(plugin, "pre_step", exc)
        mujoco.mj_step(model, data, nstep=count)
        self.iterations += count
        warnings = data.warning  # MuJoCo counts bad qpos/qvel/qacc, then resets the state
        if warnings[_QPOS].number + warnings[_QVEL].number + warnings[_QACC].number != \
                self._unstable_total:
            self._check_unstable()
        now = data.time + SLACK  # (schedule.is_due, for each plugin, without a call)
        for plugin in self.plugins.post:
            if plugin.next_update <= now:
                try:
                    plugin.post_step(model, data)
                except Exception as exc:
                    self.plugins.failed(plugin, "post_step", exc)

    def idle(self) -> None:
        """The world is paused: the plugins' paused hooks (those that publish while paused,
        as Gazebo's JointStatePublisher does)."""
        for plugin in self.plugins.idle:
            try:
                plugin.paused(self.model, self.data)
            except Exception as exc:
                self.plugins.failed(plugin, "paused", exc)

    def _check_unstable(self) -> None:
        data = self.data
        self._unstable_total = sum(data.warning[kind].number for kind in UNSTABLE)
        for kind in UNSTABLE:
            bad = data.warning[kind]
            if bad.number != self._unstable[kind]:
                self._unstable[kind] = bad.number
                self._report_blow_up(int(bad.lastinfo), kind.name.removeprefix("mjWARN_BAD"))

    def _report_blow_up(self, dof: int, what: str) -> None:
        owner = "the world"
        if 0 <= dof < self.model.nv:
            body = self.model.body(int(self.model.dof_bodyid[dof])).name
            owner = f"entity '{body.split('/')[0]}'" if "/" in body else f"body '{body}'"
        self.logger.warning(
            f"physics became unstable at t={self.data.time:.3f}s (MuJoCo: NaN or huge {what} "
            f"at degree of freedom {dof}, {owner}); MuJoCo reset the state; the sim goes on")
        self.plugins.reset()

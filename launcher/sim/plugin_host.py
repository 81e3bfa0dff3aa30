"""The plugins of a world: the world file's own and each entity's, made from their configs,
loaded, re-bound after every recompile, reset, and dropped (with a logged error) when one
raises, so that the sim goes on without it. The step loop walks the lists kept here, built
once per change and not per step."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterable, Sequence
from typing import Any

from launcher.errors import LaunchError
from launcher.sim.mjcf import PluginConfig
from launcher.sim.plugins import (
    Plugin,
    PluginError,
    PluginUnavailable,
    find_class,
    is_infrastructure,
)


class PluginHost:
    def __init__(self, sim: Any, logger: Any,
                 entity_plugins: Callable[[], Iterable[list[Plugin]]]) -> None:
        """`sim` is what plugins are given (the world); `entity_plugins` lists each entity's
        plugin list (removing a failed plugin removes it from its entity's list)."""
        self.sim, self.logger = sim, logger
        self._entity_plugins = entity_plugins
        self.world: list[Plugin] = []  # the world's own (not an entity's)
        self.all: list[Plugin] = []
        self.pre: list[Plugin] = []  # those with a pre_step
        self.post: list[Plugin] = []  # those with a post_step
        self.idle: list[Plugin] = []  # those with a paused hook

    def make(self, config: PluginConfig, entity: Any) -> Plugin | None:
        """The plugin a config names; None (logged) when it cannot run here."""
        if is_infrastructure(config):
            return None  # Gazebo's physics, user commands, …: what the sim is by itself
        try:
            cls = find_class(config)
            return cls(self.sim, entity, config)
        except PluginUnavailable as exc:
            self.logger.warning(str(exc))
        except PluginError as exc:
            self.logger.error(str(exc))
        except Exception as exc:
            self.logger.error(f"{config.where}: plugin {config.name or config.filename} failed "
                              f"to start: {type(exc).__name__}: {exc}")
        return None

    def load_world_plugins(self, configs: Sequence[PluginConfig], model: Any,
                           data: Any) -> None:
        """Make, bind and load the world's plugins; one that fails is logged and left out."""
        for config in configs:
            plugin = self.make(config, None)
            if plugin is None:
                continue
            try:
                plugin.bind(model, data)
                plugin.load()
            except Exception as exc:
                self.failed(plugin, "load", exc)
                continue
            self.world.append(plugin)
            self.changed()

    def add(self, plugin: Plugin, model: Any, data: Any) -> None:
        """A world plugin made in code (not from a world file): bound and loaded; one that
        fails raises, as the program that made it cannot go on without it."""
        plugin.bind(model, data)
        plugin.load()
        self.world.append(plugin)
        self.changed()

    def load(self, plugins: Sequence[Plugin]) -> None:
        for plugin in list(plugins):
            try:
                plugin.load()
            except Exception as exc:
                self.failed(plugin, "load", exc)

    def bind(self, model: Any, data: Any) -> None:
        """After a recompile: every plugin gets the new model and data."""
        for plugin in list(self.all):
            try:
                plugin.bind(model, data)
            except Exception as exc:
                self.failed(plugin, "bind", exc)

    def reset(self) -> None:
        for plugin in self.all:
            plugin.reset()

    def failed(self, plugin: Plugin, hook: str, exc: BaseException) -> None:
        """A plugin raised: said once, and the sim goes on without it."""
        owner = f" of entity '{plugin.entity.name}'" if plugin.entity is not None else ""
        if isinstance(exc, LaunchError):  # a located mistake in its configuration
            self.logger.error(f"{exc}; {plugin.label}{owner} is left out")
        else:
            self.logger.error(f"plugin {plugin.label}{owner} raised in {hook}: "
                              f"{type(exc).__name__}: {exc}; the sim goes on without it")
        for group in (self.world, *self._entity_plugins()):
            if plugin in group:
                group.remove(plugin)
        self.changed()
        with contextlib.suppress(Exception):  # already failing: its close may fail too
            plugin.close()

    def changed(self) -> None:
        """Refresh the lists the step loop walks."""
        found = list(self.world)
        for plugins in self._entity_plugins():
            found += plugins
        self.all = found
        self.pre = [p for p in found if type(p).pre_step is not Plugin.pre_step]
        # only these bound the batches: a plugin without a post_step (one that spawns a
        # model at load) would otherwise make every batch a single step
        self.post = [p for p in found if type(p).post_step is not Plugin.post_step]
        self.idle = [p for p in found if type(p).paused is not Plugin.paused]

"""The registry: decorators mark actions and substitutions; the registry collects and checks.

Built-in names are listed in `BUILTINS` (name -> module), so a launch file only imports the
modules of the tags and substitutions it uses (start-up time is benchmarked); a unit test
checks that this index matches the decorators. Extensions come through the same door: modules
named by the `launcher.extensions` entry-point group, looked at only when a name is unknown.
Loading a module collects every marked class in it and rejects a name defined twice. ROS 2's
launch extensions (the `launch.frontend.launch_extension` group) come in the same way: their
`@expose_action` / `@expose_substitution` (launcher.compat's launch.frontend) call `add`.
"""

from __future__ import annotations

import functools
import importlib
import warnings
from collections.abc import Iterable
from types import ModuleType
from typing import Any

from launcher.description.substitution import Substitution

# launcher's own extensions, then ROS 2 launch's (whose modules add themselves when imported)
EXTENSION_GROUPS = ("launcher.extensions", "launch.frontend.launch_extension")
_ACTIONS = "launcher.description.actions."
_SUBS = "launcher.description.substitutions."
BUILTINS: dict[str, dict[str, str]] = {
    "action": {
        **dict.fromkeys(("arg", "let", "reset"), _ACTIONS + "arguments"),
        "executable": _ACTIONS + "executable",
        "include": _ACTIONS + "include",
        "group": _ACTIONS + "group",
        "timer": _ACTIONS + "timer",
        "rostest": _ACTIONS + "rostest",
        **dict.fromkeys(("set_env", "unset_env", "append_env", "reset_env"),
                        _ACTIONS + "environment"),
        **dict.fromkeys(("log", "log_info", "log_warning", "log_error", "log_debug"),
                        _ACTIONS + "log"),
        "shutdown": _ACTIONS + "shutdown",
        **dict.fromkeys(("for", "for_each"), _ACTIONS + "loops"),
        "node": _ACTIONS + "node",
        "lifecycle_node": _ACTIONS + "lifecycle",
        **dict.fromkeys(("node_container", "load_composable_node"), _ACTIONS + "composition"),
        **dict.fromkeys(("push_ros_namespace", "push-ros-namespace", "set_parameter",
                         "set_parameters_from_file", "set_remap", "set_use_sim_time"),
                        _ACTIONS + "ros"),
        **dict.fromkeys(("machine", "roslaunch_machine"), _ACTIONS + "machine"),
    },
    "substitution": {
        **dict.fromkeys(("var", "for-var", "index", "anon"), _SUBS + "configuration"),
        **dict.fromkeys(("env", "roslaunch_env"), _SUBS + "environment"),
        **dict.fromkeys(("eval", "roslaunch_eval"), _SUBS + "expression"),
        **dict.fromkeys(("dirname", "filename", "file-content", "find-exec", "log_dir"),
                        _SUBS + "files"),
        "command": _SUBS + "command",
        **dict.fromkeys(("not", "and", "or", "any", "all", "equals", "not-equals", "if"),
                        _SUBS + "logic"),
        **dict.fromkeys(("find-pkg-share", "find-pkg-prefix", "exec-in-pkg", "param"),
                        _SUBS + "packages"),
    },
}


EXTENSION = "extension"  # a declared field's metadata key: launcher's own field, not ROS 2's


def action(*tags: str, extension: bool = False):
    """Mark a class as the action for the frontend tags `tags`; the registry collects it.
    `extension`: launcher's own, beyond ROS 2's launch (a file uses it once it says so)."""

    def mark(cls: type) -> type:
        cls.tags = tags
        cls.extension = extension
        return cls

    return mark


class Registry:
    def __init__(self, index: dict[str, dict[str, str]] | None = None) -> None:
        self.index = BUILTINS if index is None else index
        self.actions: dict[str, type] = {}
        self.substitutions: dict[str, type[Substitution]] = {}
        self._loaded: set[str] = set()
        self._extensions_loaded = False

    # --- collecting -------------------------------------------------------------------------
    def load(self, modules: Iterable[str | ModuleType]) -> None:
        for module in modules:
            mod = importlib.import_module(module) if isinstance(module, str) else module
            if mod.__name__ in self._loaded:
                continue
            self._loaded.add(mod.__name__)
            for obj in vars(mod).values():
                if not isinstance(obj, type) or obj.__module__ != mod.__name__:
                    continue
                for tag in vars(obj).get("tags", ()):
                    self._add(self.actions, tag, obj, "action")
                if issubclass(obj, Substitution):
                    for name in vars(obj).get("names", ()):
                        self._add(self.substitutions, name, obj, "substitution")

    @staticmethod
    def _add(table: dict[str, type], name: str, obj: type, what: str) -> None:
        if name in table and table[name] is not obj:
            raise RuntimeError(f"{what} '{name}' is defined twice: by {table[name].__module__} "
                               f"and {obj.__module__}")
        table[name] = obj

    def add(self, kind: str, name: str, maker: object) -> None:
        """Add one action ("action") or substitution at run time: what launch.frontend's
        expose decorators make of a user's class; a name launcher has already is refused."""
        table = self.actions if kind == "action" else self.substitutions
        known = table.get(name, self.index[kind].get(name))
        if known is not None and known is not maker:
            raise RuntimeError(f"{kind} '{name}' is defined twice: by {known!r} and {maker!r}")
        table[name] = maker  # type: ignore[assignment]

    def load_all(self) -> None:
        self.load(sorted({m for names in self.index.values() for m in names.values()}))
        self.load_extensions()

    def load_extensions(self) -> bool:
        """Load the extension groups' entry points once; True if anything was loaded."""
        if self._extensions_loaded:
            return False
        self._extensions_loaded = True
        from importlib.metadata import entry_points  # only for unknown names: start-up time

        found = [ep for group in EXTENSION_GROUPS for ep in entry_points(group=group)]
        self.load(module for ep in found if (module := _load_extension(ep)) is not None)
        return bool(found)

    # --- looking up -------------------------------------------------------------------------
    def _find(self, kind: str, table: dict[str, type], name: str) -> type | None:
        if name not in table and name in self.index[kind]:
            self.load([self.index[kind][name]])
        if name not in table:
            self.load_extensions()
        return table.get(name)

    def find_action(self, tag: str) -> type | None:
        return self._find("action", self.actions, tag)

    def find_substitution(self, name: str) -> type[Substitution] | None:
        return self._find("substitution", self.substitutions, name)

    def known(self, kind: str) -> set[str]:
        """Every name of that kind (for "did you mean"), without importing anything."""
        table = self.actions if kind == "action" else self.substitutions
        return set(self.index[kind]) | set(table)


def _load_extension(point: Any) -> Any:
    """An extension's module; a ROS 2 launch extension that fails to import is warned about
    and passed over, as launch does (launcher's own fail loudly)."""
    try:
        return point.load()
    except Exception as exc:
        if point.group == EXTENSION_GROUPS[0]:
            raise
        warnings.warn(f"Failed to load the launch extension {point.name}: {exc}", stacklevel=2)
        return None


@functools.cache
def default_registry() -> Registry:
    """The process's registry (made on first use)."""
    return Registry()

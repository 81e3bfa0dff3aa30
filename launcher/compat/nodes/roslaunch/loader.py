"""roslaunch.loader: the loader's base (Loader), its scope (LoaderContext) and value typing
(convert_value). launcher's own reading of a launch file is its ROS 1 frontend: XmlLoader
(roslaunch.xmlloader) hands files to it; these are for code that builds configs by hand."""

from __future__ import annotations

import os
import subprocess
from copy import deepcopy
from typing import Any

from launcher.errors import LaunchError
from roslaunch.core import PHASE_SETUP, Param, RLException, RosbinExecutable  # noqa: F401

PRIV_NAME = "~"
rosparam = None  # (roslaunch's optional rosparam module: launcher reads YAML itself)


class LoadException(RLException):
    """A launch that cannot be loaded."""


def convert_value(value: str, type_: str) -> Any:
    """`value` (text) as `type_` says: str/string, int, double, bool/boolean, yaml, or auto
    (a number, a bool, else the text); ValueError when it is not one."""
    from launcher.description.parameters import roslaunch_value

    kind = type_.lower()
    if kind not in ("auto", "str", "string", "int", "double", "bool", "boolean", "yaml"):
        raise ValueError(f"Unknown type '{type_}'")
    try:
        return roslaunch_value(value, kind, "")
    except LaunchError as exc:
        raise ValueError(exc.message) from None


def _global(ns: str) -> str:
    space = ns if ns.startswith("/") else f"/{ns}"
    return space if space.endswith("/") else f"{space}/"


class LoaderContext:
    """A scope of the loader: its namespace, file, `~params`, remaps, env and arguments."""

    def __init__(self, ns: str, filename: str, parent: LoaderContext | None = None,
                 params: list[Param] | None = None, env_args: list[Any] | None = None,
                 resolve_dict: dict[str, Any] | None = None,
                 include_resolve_dict: dict[str, Any] | None = None,
                 arg_names: list[str] | None = None) -> None:
        self.parent, self.filename = parent, filename
        self.ns = _global(ns or "/")
        self._remaps: list[tuple[str, str]] = []
        self.params = params or []
        self.env_args = env_args or []
        self.resolve_dict = resolve_dict or {}
        self.arg_names = arg_names or []
        self.include_resolve_dict = include_resolve_dict or None
        self.pass_all_args = False

    def add_param(self, p: Param) -> None:
        """Add a ~param for the nodes declared after it here (replacing one of that key)."""
        self.params = [m for m in self.params if m.key != p.key] + [p]

    def add_remap(self, remap: tuple[str, str]) -> None:
        """Add a remap (replacing one of the same `from`)."""
        source, target = (str(x).rstrip("/") or "/" for x in remap)
        if not source or not target:
            raise RLException("remap from/to attributes cannot be empty")
        self._remaps = [r for r in self._remaps if r[0] != source] + [(source, target)]

    def add_arg(self, name: str, default: Any = None, value: Any = None,
                doc: str | None = None) -> None:
        """Declare argument `name` here: `value` fixes it, `default` is used unless given."""
        if name in self.arg_names and not self.pass_all_args:
            raise LoadException(f"arg '{name}' has already been declared")
        if name not in self.arg_names:
            self.arg_names.append(name)
        resolve = self.resolve_dict if self.include_resolve_dict is None \
            else self.include_resolve_dict
        values = resolve.setdefault("arg", {})
        if value is not None:
            if name in values and not self.pass_all_args:
                raise LoadException(f"cannot override arg '{name}', which has already been set")
            values[name] = value
        elif default is not None:
            values.setdefault(name, default)
        if not value:
            resolve.setdefault("arg_doc", {})[name] = (doc, default)

    def remap_args(self) -> list[tuple[str, str]]:
        """The remaps in force here: the parent's, less those remapped again here, then
        these."""
        if self.parent is None:
            return list(self._remaps)
        mine = {r[0] for r in self._remaps}
        return [r for r in self.parent.remap_args() if r[0] not in mine] + self._remaps

    def include_child(self, ns: str | None, filename: str) -> LoaderContext:
        """The scope of an included file (its own arguments)."""
        ctx = self.child(ns)
        ctx.arg_names, ctx.filename, ctx.include_resolve_dict = [], filename, {}
        return ctx

    def child(self, ns: str | None) -> LoaderContext:
        """A scope inside this one, in sub-namespace `ns` (None: the same namespace)."""
        if not ns:
            space = self.ns
        elif ns.startswith("/") or ns == PRIV_NAME:
            space = ns
        else:
            space = self.ns + ns
        return LoaderContext(space, self.filename, parent=self, params=self.params,
                             env_args=self.env_args[:], resolve_dict=deepcopy(self.resolve_dict),
                             arg_names=self.arg_names[:],
                             include_resolve_dict=self.include_resolve_dict)


def load_sysargs_into_context(context: LoaderContext, argv: list[str]) -> None:
    """The `name:=value` words of `argv` as the context's arguments."""
    context.resolve_dict["arg"] = dict(w.split(":=", 1) for w in argv
                                       if ":=" in w and not w.startswith("__"))


def process_include_args(context: LoaderContext) -> None:
    """Check that every argument given to an include is declared, and enter its scope."""
    given = (context.include_resolve_dict or {}).get("arg", {})
    for name in context.arg_names:
        if name not in given:
            raise LoadException("include args must have declared values")
    context.args_passed = list(given)  # type: ignore[attr-defined]
    context.arg_names = []
    context.resolve_dict, context.include_resolve_dict = context.include_resolve_dict or {}, None


def post_process_include_args(context: LoaderContext) -> None:
    """Refuse arguments given to an include that the included file does not declare."""
    bad = [a for a in getattr(context, "args_passed", []) if a not in context.arg_names]
    if bad:
        raise LoadException(f"unused args [{', '.join(bad)}] for include of "
                            f"[{context.filename}]")


class Loader:
    """What the XML loader shares: parameters, env and rosparam into a ROSLaunchConfig."""

    def load_rosparam(self, context: LoaderContext, ros_config: Any, cmd: str, param: str,
                      file_: str | None, text: str | None, verbose: bool = True,
                      subst_function: Any = None) -> None:
        """`<rosparam command="load">`: the YAML of `file_` (or `text`) as parameters
        under `param` (dump and delete are run by launcher's launch, not here)."""
        import yaml

        if cmd != "load":
            return
        if file_ is not None:
            with open(file_, encoding="utf-8") as handle:
                text = handle.read()
        if subst_function is not None and text:
            text = subst_function(text)
        data = yaml.safe_load(text or "") if text else None
        base = param if param.startswith("/") else context.ns + param
        self._add_tree(ros_config, base.rstrip("/") or "/", data, verbose)

    def _add_tree(self, ros_config: Any, key: str, data: Any, verbose: bool) -> None:
        if isinstance(data, dict) and data:
            for name, value in data.items():
                self._add_tree(ros_config, f"{key.rstrip('/')}/{name}", value, verbose)
        elif data is not None:
            self.add_param(ros_config, key, data, verbose)

    def load_env(self, context: LoaderContext, ros_config: Any, name: str, value: str) -> None:
        """`<env>`: set `name` for the nodes of this scope."""
        if not name:
            raise ValueError("'name' attribute must be non-empty")
        context.env_args.append((name, value))

    def param_value(self, verbose: bool, name: str, ptype: str | None, value: str | None,
                    textfile: str | None, binfile: str | None, command: str | None) -> Any:
        """A `<param>`'s value: `value` typed, or a file's text or bytes, or a command's
        output."""
        if value is not None:
            return convert_value(value.strip(), ptype or "auto")
        if textfile is not None:
            with open(textfile, encoding="utf-8") as handle:
                return handle.read()
        if binfile is not None:
            with open(binfile, "rb") as handle:
                return handle.read()
        if command is not None:
            done = subprocess.run(command, shell=True, capture_output=True, text=True,
                                  check=False, env=os.environ)
            if done.returncode:
                raise LoadException(f"Invalid <param> tag: command [{command}] failed")
            return done.stdout
        raise ValueError("unknown parameter value for <param> " + name)

    def add_param(self, ros_config: Any, param_name: str, param_value: Any,
                  verbose: bool = True) -> None:
        """Put parameter `param_name` in the config."""
        ros_config.add_param(Param(param_name, param_value), verbose=verbose)

"""`--ros-args` as the `node` action writes them, and params files.

    ARGS… --ros-args [-r|--remap FROM:=TO] [-p|--param NAME:=VALUE] [--params-file FILE]
                     [--log-level LEVEL] [-e|--enclave E] [--] ARGS…

Params files: `{NODE_OR_WILDCARD: {ros__parameters: {...}}}`; keys `/**`, `/**/NAME`, `NAME`
and `/NS/NAME` apply to the node they match. Nested maps flatten to dotted names.
"""

from __future__ import annotations

import json
import os
from typing import Any

from launcher.errors import LaunchError, Location
from launcher.lineage import NODE_PARAMETERS
from launcher.packages import ros1_args
from launcher.records import dataclass, field
from launcher.user_files import read_text


@dataclass
class RosArgs:
    node_name: str | None = None
    namespace: str | None = None
    remaps: list[tuple[str, str]] = field(default_factory=list)
    # ("file", path) and ("value", (name, value)) in the order given: later ones win, as in rcl
    parameter_sources: list[tuple[str, Any]] = field(default_factory=list)
    log_level: str | None = None
    user_args: list[str] = field(default_factory=list)

    @property
    def parameters(self) -> dict[str, Any]:
        """The `-p` values."""
        return dict(source for kind, source in self.parameter_sources if kind == "value")


_inherited: list[str] | None = None


def _launched_parameters() -> list[str]:
    """A roslaunch node's parameters as `--ros-args` words (lineage.NODE_PARAMETERS), taken
    out of the environment once, so that no process this one starts inherits them."""
    global _inherited
    if _inherited is None:
        text = os.environ.pop(NODE_PARAMETERS, "")
        try:
            _inherited = [str(w) for w in json.loads(text)] if text else []
        except ValueError:
            _inherited = []
    return _inherited


def parse(argv: list[str]) -> RosArgs:
    """Split argv into the program's own arguments and its ROS arguments: ROS 2's after
    `--ros-args`, and ROS 1's as roslaunch gives them (`FROM:=TO`, `__name:=`, `__ns:=`,
    `_param:=value`; `__log:=` and the master's are taken and unused)."""
    out = RosArgs()
    inside = False
    i = 0
    inherited = _launched_parameters()
    if inherited:
        argv = [*argv, "--ros-args", *inherited]
    while i < len(argv):
        word = argv[i]
        if word == "--ros-args":
            inside = True
        elif inside and word == "--":
            inside = False
        elif not inside and ros1_args.is_ros1(word):
            for flag, value in zip(*[iter(ros1_args.as_ros2(word))] * 2, strict=True):
                _option(out, flag, value)
        elif not inside:
            out.user_args.append(word)
        elif word in ("-r", "--remap", "-p", "--param", "--params-file", "--log-level",
                      "-e", "--enclave"):
            if i + 1 >= len(argv):
                raise LaunchError(f"--ros-args: '{word}' needs a value")
            _option(out, word, argv[i + 1])
            i += 1
        else:
            raise LaunchError(f"--ros-args: unknown argument '{word}'")
        i += 1
    return out


def _option(out: RosArgs, word: str, value: str) -> None:
    if word in ("--params-file",):
        out.parameter_sources.append(("file", value))
    elif word == "--log-level":
        out.log_level = value.split(":")[-1].upper()
    elif word in ("-e", "--enclave"):
        pass
    else:
        if ":=" not in value:
            raise LaunchError(f"--ros-args: '{word} {value}': expected NAME:=VALUE")
        name, _, text = value.partition(":=")
        if word in ("-p", "--param"):
            out.parameter_sources.append(("value", (name, _typed(text))))
        elif name == "__node":
            out.node_name = text
        elif name == "__ns":
            out.namespace = text
        else:
            out.remaps.append((name, text))


def typed(text: str) -> Any:
    """A value as `-p name:=VALUE` reads it (YAML scalars and lists)."""
    return _typed(text)


def _typed(text: str) -> Any:
    if "\n" in text.strip():  # a document (a robot description a launch gave): text, lines kept
        return text
    import yaml  # only for -p values and params files: node start-up time

    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    return text if value is None or isinstance(value, dict) else value


def node_parameters(parsed: RosArgs, node: str, namespace: str) -> dict[str, Any]:
    """The node's parameters from its command line: params files and `-p` values in order."""
    out: dict[str, Any] = {}
    for kind, source in parsed.parameter_sources:
        if kind == "file":
            out.update(load_params_file(source, node, namespace))
        else:
            out[source[0]] = source[1]
    return out


def load_params_file(path: str, node: str, namespace: str) -> dict[str, Any]:
    """The parameters for /NAMESPACE/NODE in a params file; errors name file:line."""
    import yaml  # only for -p values and params files: node start-up time

    try:
        text = read_text(path)
    except OSError as exc:
        raise LaunchError(f"cannot read params file: {exc.strerror}", Location(path)) from None
    try:
        document = yaml.safe_load(text) or {}
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        where = Location(path, mark.line + 1, mark.column + 1) if mark else Location(path)
        raise LaunchError(f"params file is not valid YAML: {exc.problem}", where) from None
    if not isinstance(document, dict):
        raise LaunchError("params file: expected a map of node names", Location(path, 1))
    full = f"{namespace.rstrip('/')}/{node}"
    out: dict[str, Any] = {}
    for key, body in document.items():
        if _matches(str(key), node, full) and isinstance(body, dict):
            flatten(body.get("ros__parameters", {}) or {}, "", out)
    return out


def _matches(key: str, node: str, full: str) -> bool:
    return key in ("/**", "**", node, full, f"/**/{node}") or key.lstrip("/") == full.lstrip("/")


def flatten(values: dict[str, Any], prefix: str, out: dict[str, Any]) -> None:
    for name, value in values.items():
        if isinstance(value, dict):
            flatten(value, f"{prefix}{name}.", out)
        else:
            out[f"{prefix}{name}"] = value

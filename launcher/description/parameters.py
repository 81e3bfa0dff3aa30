"""ROS parameters for nodes: typing values, the run-wide settings, and params files.

Run-wide settings (`push_ros_namespace`, `set_parameter`, `set_parameters_from_file`,
`set_remap`) live in the launch configurations under reserved keys, so `group` scopes them as
it scopes arguments (as in ROS 2). Values are typed like ROS 2 types them, with one rule
ROS 2 lacks: text that spans lines (a robot description, any XML) is always a string and is
never parsed as YAML.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from launcher.errors import ExecutionError, Location
from launcher.private import private_folder, write_private
from launcher.runtime.context import LaunchContext
from launcher.user_files import read_text

NAMESPACE = "<ros_namespace>"
GLOBAL_PARAMETERS = "<global_parameters>"  # a tuple of (name, value)
GLOBAL_PARAMETER_FILES = "<global_parameter_files>"  # a tuple of paths
REMAPS = "<remaps>"  # a tuple of (from, to)
TYPES = ("str", "int", "float", "bool", "yaml")


def typed(text: str, kind: str | None = None) -> Any:
    """The parameter value of `text`: as `kind` says, else inferred from a one-line literal."""
    if kind == "str":
        return text
    if kind in ("int", "float"):
        try:
            return int(text) if kind == "int" else float(text)
        except ValueError:
            raise ExecutionError(f"param: '{text}' is not a valid {kind}") from None
    if kind == "bool":
        low = text.strip().lower()
        if low not in ("true", "false"):
            raise ExecutionError(f"param: '{text}' is not true or false")
        return low == "true"
    if "\n" in text.strip() and kind != "yaml":
        return text  # robot descriptions and other documents stay text
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    if isinstance(value, bool | int | float | str):
        return value
    if isinstance(value, list) and all(isinstance(v, bool | int | float | str) for v in value):
        return value
    return text if value is not None else text


def _add(context: LaunchContext, key: str, items: tuple) -> None:
    context.configurations[key] = (*context.configurations.get(key, ()), *items)  # type: ignore


def global_parameters(context: LaunchContext) -> tuple[tuple[str, Any], ...]:
    return context.configurations.get(GLOBAL_PARAMETERS, ())  # type: ignore[return-value]


def add_global_parameter(context: LaunchContext, name: str, value: Any) -> None:
    _add(context, GLOBAL_PARAMETERS, ((name, value),))


def add_global_parameter_file(context: LaunchContext, path: str) -> None:
    _add(context, GLOBAL_PARAMETER_FILES, (path,))


def global_parameter_files(context: LaunchContext) -> tuple[str, ...]:
    return context.configurations.get(GLOBAL_PARAMETER_FILES, ())  # type: ignore[return-value]


def add_remap(context: LaunchContext, source: str, target: str) -> None:
    _add(context, REMAPS, ((source, target),))


def remaps(context: LaunchContext) -> tuple[tuple[str, str], ...]:
    return context.configurations.get(REMAPS, ())  # type: ignore[return-value]


def namespace(context: LaunchContext) -> str:
    return context.configurations.get(NAMESPACE, "")


def push_namespace(context: LaunchContext, value: str) -> None:
    if value.startswith("/"):
        context.configurations[NAMESPACE] = value.rstrip("/")
    else:
        context.configurations[NAMESPACE] = join_namespace(namespace(context), value)


def join_namespace(outer: str, inner: str) -> str:
    if inner.startswith("/"):
        return inner.rstrip("/") or "/"
    parts = [p for p in (outer.strip("/"), inner.strip("/")) if p]
    return "/" + "/".join(parts) if parts else ""


def check_params_file(path: Path, where: Location | None) -> None:
    """A params file must exist and be valid YAML (errors name its line)."""
    try:
        text = read_text(path)
    except FileNotFoundError:
        raise ExecutionError(f"parameters file '{path}' does not exist", where) from None
    except OSError as exc:
        raise ExecutionError(f"cannot read parameters file '{path}': {exc.strerror}", where) \
            from None
    try:
        yaml.safe_load(text)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        at = Location(str(path), mark.line + 1, mark.column + 1) if mark else Location(str(path))
        raise ExecutionError(f"parameters file is not valid YAML: {exc.problem}", at) from None


def write_params_file(folder: Path, stem: str, parameters: dict[str, Any]) -> Path:
    """A params file, 0600 in a 0700 folder: it may hold the robot description."""
    private_folder(folder)
    path = folder / f"{stem}.yaml"
    count = 1
    while path.exists():
        count += 1
        path = folder / f"{stem}_{count}.yaml"
    document = {"/**": {"ros__parameters": parameters}}
    write_private(path, yaml.safe_dump(document, default_flow_style=False, sort_keys=False,
                                       allow_unicode=True, width=float("inf")))
    return path

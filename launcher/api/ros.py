"""launch_ros's Python API beyond its actions: parameter descriptions, the names' utilities,
lifecycle matchers, ROS-time timers, and the launch's own ROS node (`get_ros_node`)."""

from __future__ import annotations

import os
import threading
from collections.abc import Callable, Iterable, Mapping
from typing import Any

from launcher.description.action import Action
from launcher.description.actions.lifecycle import ChangeState
from launcher.description.actions.timer import TimerAction
from launcher.description.substitution import perform_text, to_text
from launcher.errors import ExecutionError
from launcher.lifecycle import NAMED
from launcher.runtime.context import LaunchContext


# --- parameters ---------------------------------------------------------------------------
class ParameterValue:
    """A value with its type, as launch_ros has it: `ParameterValue(Command(…), value_type=str)`."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value, self.value_type = value, value_type

    def type_name(self) -> str | None:
        """`type:` as launch files write it: str, int, …, list_of_int, …"""
        names = {str: "str", int: "int", float: "float", bool: "bool"}
        if self.value_type is None:
            return None
        if self.value_type in names:
            return names[self.value_type]
        args = getattr(self.value_type, "__args__", ())
        if getattr(self.value_type, "__origin__", None) is list and args and args[0] in names:
            return f"list_of_{names[args[0]]}"
        raise TypeError(f"ParameterValue: value_type {self.value_type!r} is not one of str, "
                        "int, float, bool, List[str|int|float|bool]")

    def evaluate(self, context: LaunchContext) -> Any:
        """The value, substitutions done (text; typed by the node as its parameters are)."""
        value = self.value
        if isinstance(value, list | tuple) and not all(isinstance(v, str) for v in value):
            return [perform_text(context, to_text(v)) for v in value]
        return perform_text(context, to_text(value)) if not isinstance(
            value, bool | int | float) else value


class ParameterFile:
    """A parameters file, as launch_ros has it: `ParameterFile(path, allow_substs=False)`;
    with `allow_substs` the substitutions written in the file are performed."""

    def __init__(self, param_file: Any, *, allow_substs: Any = False) -> None:
        self.param_file, self.allow_substs = param_file, allow_substs

    def evaluate(self, context: LaunchContext) -> str:
        return perform_text(context, to_text(self.param_file))


class Parameter:
    """launch_ros.descriptions.Parameter: one parameter, `Parameter('rate', 10)`, for a
    node's `parameters=[…]`."""

    def __init__(self, name: Any, value: Any, *, value_type: Any = None) -> None:
        self.name = name
        self.value = value if value_type is None else ParameterValue(value,
                                                                     value_type=value_type)

    def as_dict(self) -> dict[Any, Any]:
        return {self.name: self.value}


ParameterDescription = Parameter
ParameterValueDescription = ParameterValue


# --- names --------------------------------------------------------------------------------
def is_namespace_absolute(ns: str) -> bool:
    return ns.startswith("/")


def is_root_namespace(ns: str) -> bool:
    return ns == "/"


def make_namespace_absolute(ns: str) -> str:
    return ns if is_namespace_absolute(ns) else f"/{ns}"


def prefix_namespace(base_ns: str | None, ns: str | None) -> str | None:
    """`ns` under `base_ns`, as launch_ros pushes namespaces (an absolute `ns` stays)."""
    if base_ns is None or base_ns == "":
        return ns
    if ns is None or ns == "":
        return base_ns
    if is_namespace_absolute(ns):
        return ns
    return ("" if is_root_namespace(base_ns) else base_ns) + "/" + ns


def normalize_remap_rule(remap_rule: Any) -> tuple[Any, Any]:
    """A remapping pair, each side as substitutions."""
    source, target = remap_rule
    return tuple(to_text(source)), tuple(to_text(target))


def normalize_remap_rules(remap_rules: Iterable[Any]) -> list[tuple[Any, Any]]:
    return [normalize_remap_rule(rule) for rule in remap_rules]


def normalize_parameter_dict(parameters: Mapping[Any, Any], *,
                             _prefix: str | None = None) -> dict[tuple[Any, ...], Any]:
    """Nested parameter maps flattened to dotted names (`{'a': {'b': 1}}` → a.b)."""
    flat: dict[tuple[Any, ...], Any] = {}
    for name, value in parameters.items():
        full = to_text(name) if _prefix is None else (*to_text(_prefix), *to_text("."),
                                                      *to_text(name))
        if isinstance(value, Mapping):
            flat.update(normalize_parameter_dict(value, _prefix=full))
        else:
            flat[tuple(full)] = value
    return flat


def normalize_parameters(parameters: Iterable[Any]) -> list[Any]:
    """A node's `parameters=[…]`: files as ParameterFile, maps flattened."""
    out: list[Any] = []
    for item in parameters:
        if isinstance(item, ParameterFile):
            out.append(item)
        elif isinstance(item, Parameter):
            out.append(normalize_parameter_dict(item.as_dict()))
        elif isinstance(item, Mapping):
            out.append(normalize_parameter_dict(item))
        else:
            out.append(ParameterFile(item))
    return out


def evaluate_parameter_dict(context: LaunchContext,
                            parameters: Mapping[Any, Any]) -> dict[str, Any]:
    """A flattened map's names and values, substitutions done."""
    done = {}
    for name, value in parameters.items():
        key = perform_text(context, tuple(name))
        if isinstance(value, ParameterValue):
            done[key] = value.evaluate(context)
        elif isinstance(value, bool | int | float):
            done[key] = value
        elif isinstance(value, list | tuple) and all(isinstance(v, bool | int | float | str)
                                                     for v in value):
            done[key] = list(value)
        else:
            done[key] = perform_text(context, to_text(value))
    return done


def evaluate_parameters(context: LaunchContext, parameters: Iterable[Any]) -> list[Any]:
    """Normalized parameters evaluated: files as their paths, maps as names to values."""
    return [item.evaluate(context) if isinstance(item, ParameterFile)
            else evaluate_parameter_dict(context, item) for item in parameters]


def to_parameters_list(context: LaunchContext, node_name: str, namespace: str,
                       evaluated_parameters: Iterable[Any]) -> list[Any]:
    """Evaluated parameters as (name, value) pairs (a file's as they apply to the node)."""
    pairs: list[Any] = []
    for item in evaluated_parameters:
        if isinstance(item, str):
            pairs.extend(_file_parameters(item, node_name, namespace).items())
        else:
            pairs.extend(item.items())
    return pairs


def _file_parameters(path: str, node_name: str, namespace: str) -> dict[str, Any]:
    """A params file's parameters that apply to the node (its name, full or not, and /**)."""
    import yaml

    with open(path, encoding="utf-8") as file:
        data = yaml.safe_load(file) or {}
    full = f"{namespace.rstrip('/')}/{node_name}"
    found: dict[str, Any] = {}
    for key in ("/**", node_name, full, full.lstrip("/")):
        section = data.get(key) if isinstance(data, dict) else None
        if isinstance(section, dict) and isinstance(section.get("ros__parameters"), dict):
            found.update(_flat(section["ros__parameters"]))
    return found


def _flat(values: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    out: dict[str, Any] = {}
    for name, value in values.items():
        full = f"{prefix}{name}"
        if isinstance(value, Mapping):
            out.update(_flat(value, f"{full}."))
        else:
            out[full] = value
    return out


_node_names: dict[str, int] = {}
_names_lock = threading.Lock()


def add_node_name(context: LaunchContext, node_name: str) -> None:
    """Count a node of this full name (launch_ros warns on duplicates)."""
    with _names_lock:
        _node_names[node_name] = _node_names.get(node_name, 0) + 1


def get_node_name_count(context: LaunchContext, node_name: str) -> int:
    with _names_lock:
        return _node_names.get(node_name, 0)


# --- lifecycle --------------------------------------------------------------------------------
def matches_node_name(node_name: str) -> Callable[[Any], bool]:
    """launch_ros.events.matches_node_name: the lifecycle node action of that full name."""
    return lambda action: action.node_name == node_name  # (launch_ros's: once it has run)


def match_node_name_goal(node_name: str, goal_state: str) -> Callable[[Any], bool]:
    return lambda event: getattr(event, "node", None) == node_name and \
        event.goal_state == goal_state


def match_node_name_start_goal(node_name: str, start_state: str,
                               goal_state: str) -> Callable[[Any], bool]:
    return lambda event: match_node_name_goal(node_name, goal_state)(event) and \
        event.start_state == start_state


class LifecycleTransition(Action):
    """launch_ros.actions.LifecycleTransition: ask the named lifecycle nodes for these
    transitions (lifecycle_msgs' ids), one after another."""

    def __init__(self, *, lifecycle_node_names: Iterable[Any], transition_ids: Iterable[Any],
                 **kwargs: Any) -> None:
        self.condition, self.where = kwargs.get("condition"), None
        self.names = [to_text(name) for name in lifecycle_node_names]
        self.transition_ids = [NAMED.get(str(t), t) if isinstance(t, str) else int(t)
                               for t in transition_ids]

    def execute(self, context: LaunchContext) -> None:
        if context.service is None:
            return
        for name in self.names:
            node = make_namespace_absolute(perform_text(context, name))
            context.service.change_states(node, list(self.transition_ids), self.where)


# --- timers, the log folder ---------------------------------------------------------------
class RosTimer(TimerAction):
    """launch_ros.actions.RosTimer: a TimerAction on the launch's ROS clock: the wall clock,
    which it is unless the launch sets use_sim_time (then refused: the launch's own clock
    does not follow /clock yet)."""

    def __init__(self, *, period: Any, actions: Iterable[Any], **kwargs: Any) -> None:
        super().__init__(period=period, actions=list(actions), **kwargs)

    def execute(self, context: LaunchContext) -> Any:
        if str(context.configurations.get("use_sim_time", "false")).lower() == "true":
            raise ExecutionError("RosTimer on sim time (use_sim_time) is not supported: "
                                 "the launch's clock is the wall clock; use TimerAction",
                                 self.where)
        return super().execute(context)


ROSTimer = RosTimer


class SetROSLogDir(Action):
    """launch_ros.actions.SetROSLogDir: the nodes after it write their logs to this folder
    (ROS_LOG_DIR; a relative one is taken under the current one)."""

    def __init__(self, new_log_dir: Any, **kwargs: Any) -> None:
        self.condition, self.where = kwargs.get("condition"), None
        self.new_log_dir = to_text(new_log_dir)

    def execute(self, context: LaunchContext) -> None:
        folder = perform_text(context, self.new_log_dir)
        current = context.environment.get("ROS_LOG_DIR")
        if current and not os.path.isabs(folder):
            folder = os.path.join(current, folder)
        context.environment["ROS_LOG_DIR"] = folder


__all__ = [
    "ChangeState", "LifecycleTransition", "Parameter", "ParameterDescription", "ParameterFile",
    "ParameterValue", "ParameterValueDescription", "ROSTimer", "RosTimer", "SetROSLogDir",
    "add_node_name", "evaluate_parameter_dict", "evaluate_parameters", "get_node_name_count",
    "is_namespace_absolute", "is_root_namespace", "make_namespace_absolute",
    "match_node_name_goal", "match_node_name_start_goal", "matches_node_name",
    "normalize_parameter_dict", "normalize_parameters", "normalize_remap_rule",
    "normalize_remap_rules", "prefix_namespace", "to_parameters_list",
]

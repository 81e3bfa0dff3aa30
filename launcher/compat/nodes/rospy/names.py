"""rospy.names: ROS 1 graph names (rosgraph.names' rules), the command line's remappings and
the node's own name. Once init_node has run, names resolve as launcher's node resolves them
(its remaps, ROS 1's `from:=to` and ROS 2's `--ros-args -r` alike)."""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from typing import Any

from rospy.exceptions import ROSException, ROSInitException
from rospy.impl.validators import ParameterInvalid

SEP = "/"
GLOBALNS = "/"
PRIV_NAME = "~"
REMAP = ":="
ANYTYPE = "*"
TOPIC_ANYTYPE = ANYTYPE  # a subscriber that takes any type
SERVICE_ANYTYPE = ANYTYPE  # a service client without a fixed type


def isstring(s: Any) -> bool:
    """Whether `s` is a str."""
    return isinstance(s, str)


def is_global(name: str) -> bool:
    return bool(name) and name[0] == SEP


def is_private(name: str) -> bool:
    return bool(name) and name[0] == PRIV_NAME


def namespace(name: str) -> str:
    """The namespace of `name`, with a trailing slash ('/wg/node1' -> '/wg/')."""
    if name is None:
        raise ValueError("name")
    if not isstring(name):
        raise TypeError("name")
    if not name:
        return SEP
    name = name[:-1] if name[-1] == SEP else name
    return name[:name.rfind(SEP) + 1] or SEP


def ns_join(ns: str, name: str) -> str:
    """`name` in namespace `ns` (a ~private or /global name is returned as it is)."""
    if is_private(name) or is_global(name):
        return name
    if ns == PRIV_NAME:
        return PRIV_NAME + name
    if not ns:
        return name
    return ns + name if ns[-1] == SEP else ns + SEP + name


def make_global_ns(name: str) -> str:
    """`name` as a global namespace: 'foo' -> '/foo/'."""
    if is_private(name):
        raise ValueError(f"cannot turn [{name}] into a global name")
    name = name if is_global(name) else SEP + name
    return name if name[-1] == SEP else name + SEP


def get_ros_namespace(env: Any = None, argv: list[str] | None = None) -> str:
    """The program's namespace: `__ns:=` on the command line, else ROS_NAMESPACE, else '/'."""
    for arg in sys.argv if argv is None else argv:
        if arg.startswith("__ns:="):
            return make_global_ns(arg[len("__ns:="):])
    return make_global_ns((os.environ if env is None else env).get("ROS_NAMESPACE", GLOBALNS))


def canonicalize_name(name: str) -> str:
    """`name` without doubled or trailing slashes: '/foo//bar/' -> '/foo/bar'."""
    if not name or name == SEP:
        return name
    parts = "/".join(x for x in name.split(SEP) if x)
    return "/" + parts if name[0] == SEP else parts


def _resolve(name: str, caller_id: str, remappings: dict[str, str] | None = None) -> str:
    """rosgraph.names.resolve_name: `name` made global relative to node `caller_id`."""
    if not name:
        return namespace(caller_id)
    name = canonicalize_name(str(name))
    if name[0] == SEP:
        resolved = name
    elif is_private(name):
        resolved = canonicalize_name(caller_id + SEP + name[1:])
    else:
        resolved = namespace(caller_id) + name
    return remappings[resolved] if remappings and resolved in remappings else resolved


def load_mappings(argv: list[str]) -> dict[str, str]:
    """{from: to} of the `from:=to` remappings in `argv` (not `_param:=value`)."""
    mappings = {}
    for arg in argv:
        source, found, target = arg.partition(REMAP)
        source, target = source.strip(), target.strip()
        if not found or not source or not target or source.startswith("-"):
            continue
        if len(source) > 1 and source[0] == "_" and source[1] != "_":
            continue  # a private parameter
        mappings[source] = target
    return mappings


_mappings = load_mappings(sys.argv)
_resolved_mappings: dict[str, str] = {}
_caller_namespace = get_ros_namespace()
_caller_id = _caller_namespace + "unnamed"  # until init_node
_node_resolve: Callable[[str], str] | None = None  # the node's own, once it exists


def reload_mappings(argv: list[str]) -> None:
    """Read the remapping table again from `argv`."""
    global _mappings
    _mappings = load_mappings(argv)


def initialize_mappings(node_name: str) -> None:
    """Resolve the remapping table for node `node_name`."""
    global _resolved_mappings
    _resolved_mappings = {m if m.startswith("__") else _resolve(m, node_name):
                          v if m.startswith("__") else _resolve(v, node_name)
                          for m, v in _mappings.items()}


def get_mappings() -> dict[str, str]:
    """The command line's remappings, unresolved."""
    return _mappings


def get_resolved_mappings() -> dict[str, str]:
    """The command line's remappings, resolved for the node."""
    return _resolved_mappings


def resolve_name_without_node_name(name: str) -> str:
    """`name` resolved before init_node: ValueError for a ~name."""
    if is_private(name):
        raise ValueError("~name topics cannot be created before init_node() has been called")
    fake_caller_id = ns_join(get_namespace(), "node")
    fake_resolved = _resolve(name, fake_caller_id)
    for source, target in _mappings.items():
        if _resolve(source, fake_caller_id) == fake_resolved:
            return _resolve(target, fake_caller_id)
    return fake_resolved


def resolve_name(name: str, caller_id: str | None = None) -> str:
    """`name` in global, canonical form: relative names in the node's namespace, ~names
    under the node, remappings applied. An empty name is the namespace."""
    if not caller_id and name and _node_resolve is not None:
        return _node_resolve(name)
    return _resolve(name, caller_id or get_name(), _resolved_mappings)


def remap_name(name: str, caller_id: str | None = None, resolved: bool = True) -> str:
    """`name` remapped (and then resolved) when the command line remaps it, else as given."""
    if name in _mappings:
        return _resolve(_mappings[name], caller_id or get_caller_id())
    return name


def scoped_name(caller_id: str, name: str) -> str:
    """`name` relative to the namespace of `caller_id`: ('/foo/x', '/foo/bar/n') -> 'bar/n'."""
    if not is_global(caller_id):
        raise ROSException("caller_id must be global")
    return canonicalize_name(name)[len(namespace(caller_id)):]


def _checked(param_name: str, param_value: Any) -> Any:
    if not param_value or not isstring(param_value):
        raise ParameterInvalid(f"ERROR: parameter [{param_name}] must be a non-empty string")
    if ":" in param_value or " " in param_value:
        raise ParameterInvalid(f"ERROR: parameter [{param_name}] contains illegal chars")
    return param_value


def valid_name_validator_resolved(param_name: str, param_value: Any, caller_id: str) -> str:
    """`param_value` checked as a name and resolved for `caller_id`."""
    return _resolve(_checked(param_name, param_value), caller_id)


def valid_name_validator_unresolved(param_name: str, param_value: Any, caller_id: str) -> str:
    """`param_value` checked as a name."""
    return _checked(param_name, param_value)


def valid_name(param_name: str, resolve: bool = True) -> Callable[[Any, str], str]:
    """A validator of non-empty names (resolved unless `resolve` is false)."""
    def validator(param_value: Any, caller_id: str) -> str:
        if resolve:
            return valid_name_validator_resolved(param_name, param_value, caller_id)
        return valid_name_validator_unresolved(param_name, param_value, caller_id)
    return validator


def global_name(param_name: str) -> Callable[[Any, str], str]:
    """A validator of global names."""
    def validator(param_value: Any, caller_id: str) -> str:
        if not param_value or not isstring(param_value):
            raise ParameterInvalid(f"ERROR: parameter [{param_name}] must be a non-empty "
                                   "string")
        if not is_global(param_value):
            raise ParameterInvalid(f"ERROR: parameter [{param_name}] must be a globally "
                                   "referenced name")
        return param_value
    return validator


def get_namespace() -> str:
    """The node's namespace, ending in '/'."""
    return _caller_namespace


def get_name() -> str:
    """The node's fully qualified name ('/unnamed' before init_node)."""
    return _caller_id


get_caller_id = get_name


def set_caller_id(caller_id: str, resolve: Callable[[str], str] | None = None) -> None:
    """init_node's part: the node's name, and how the node resolves names."""
    global _caller_id, _caller_namespace, _node_resolve
    _caller_id, _caller_namespace, _node_resolve = caller_id, namespace(caller_id), resolve


__all__ = ["ANYTYPE", "GLOBALNS", "PRIV_NAME", "REMAP", "SEP", "SERVICE_ANYTYPE",
           "TOPIC_ANYTYPE", "ParameterInvalid", "ROSException", "ROSInitException",
           "canonicalize_name", "get_caller_id", "get_mappings", "get_name", "get_namespace",
           "get_resolved_mappings", "get_ros_namespace", "global_name", "initialize_mappings",
           "is_global", "is_private", "isstring", "load_mappings", "make_global_ns",
           "namespace", "ns_join", "reload_mappings", "remap_name", "resolve_name",
           "resolve_name_without_node_name", "scoped_name", "valid_name",
           "valid_name_validator_resolved", "valid_name_validator_unresolved"]

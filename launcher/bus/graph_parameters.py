"""The graph's parameter server, as ROS 1's master keeps one: a node, `/_parameter_server`
(hidden, as ROS 2 hides infrastructure: `node list -a` shows it), that the graph's router
hosts (so it lives as long as the graph does, and `launcher router` is roscore), whose
parameters are everyone's: any name may be set, got or deleted through its parameter
services. Here too is its client (rospy's `get_param('/x')`, `launcher rosparam`,
the loader a ROS 1 launch runs for its parameters).

Names: ROS 1's `/robot1/robot_description` is the server's parameter
`robot1.robot_description` (ROS 2 nests parameters with dots; ROS 1 names hold no dots), so
`launcher param get /_parameter_server robot1.robot_description` and `launcher rosparam get
/robot1/robot_description` read the same value. A dict is kept as its leaves, and getting a
name above them gives the dict back, as ROS 1's server does.
"""

from __future__ import annotations

import threading
import time
import uuid
from collections.abc import Callable, Mapping
from typing import Any, NamedTuple

from launcher.bus import parameters as params
from launcher.bus.messages import build
from launcher.errors import LaunchError

NAME = "_parameter_server"  # hidden (a leading _), as ROS 2 hides infrastructure
NODE = f"/{NAME}"
RECHECK = 1.0  # s: how long "no server" is believed before the graph is asked again


class Missing(LaunchError):
    """A name nothing is set at or below (said in ROS 1's words)."""


def key(ros1_name: str) -> str:
    """The server's parameter for a ROS 1 name (`/a/b` → `a.b`)."""
    return ".".join(part for part in ros1_name.split("/") if part)


def ros1_name(parameter: str) -> str:
    return "/" + parameter.replace(".", "/")


MIXED = "!ros1-list "  # a list of mixed types, kept as this tag and its YAML


def leaves(ros1: str, value: Any) -> dict[str, Any]:
    """A value as the server keeps it: a dict as its leaves, each a parameter value (a list
    of mixed types, which a ROS 2 parameter cannot hold but ROS 1's XML-RPC server does, as
    its YAML behind a tag: its clients read it back as the list)."""
    if isinstance(value, Mapping):
        found: dict[str, Any] = {}
        for inner, item in value.items():
            found.update(leaves(f"{ros1.rstrip('/')}/{inner}", item))
        return found
    if isinstance(value, list | tuple):
        kinds = {type(item) for item in value}
        if kinds == {int, float}:
            value = [float(item) for item in value]
        elif len(kinds) > 1 or kinds & {list, tuple, dict, type(None)}:
            import yaml

            value = MIXED + yaml.safe_dump(list(value), default_flow_style=True,
                                           width=1 << 30).strip()
        else:
            value = list(value)
    return {key(ros1): value}


def _read(value: Any) -> Any:
    """A value as the server's clients read it (a mixed list as the list)."""
    if isinstance(value, str) and value.startswith(MIXED):
        import yaml

        return yaml.safe_load(value[len(MIXED):])
    return value


def dump_text(value: Any) -> str:
    """A value (a tree: a dict) as rosparam dump writes it: YAML, without its end marker."""
    import yaml

    text = yaml.safe_dump(value, default_flow_style=None, allow_unicode=True, sort_keys=True)
    return text[:-5] if text.endswith("\n...\n") else text.rstrip("\n")


ROS1_DISTRO, ROS1_VERSION = "noetic", "1.16.0"  # the ROS 1 that launcher's stands for


def master_parameters(run_id: str) -> dict[str, str]:
    """What a ROS 1 master holds from its start (roscore.xml's, and roslaunch's run id):
    /run_id, /rosdistro and /rosversion (the last two end in a newline there)."""
    return {"/run_id": run_id, "/rosdistro": f"{ROS1_DISTRO}\n",
            "/rosversion": f"{ROS1_VERSION}\n"}


class Hosted(NamedTuple):
    stop: Callable[[], None]  # the server goes
    reset: Callable[[], None]  # it holds what a fresh master holds, and nothing else


def host(session: Any) -> Hosted:
    """Serve the parameter server on `session` (the router's), its callbacks on a thread of
    their own, holding what a fresh ROS 1 master holds."""
    from launcher.bus.node import Node

    node = Node(NAME, argv=[], session=session)
    lock = threading.Lock()

    def reset() -> None:
        with lock:
            for name in list(node.parameters):
                node.params.request(name, None)
            for name, value in master_parameters(str(uuid.uuid1())).items():
                node.params.set(key(name), value)

    reset()
    thread = threading.Thread(target=node.spin, name="parameter_server", daemon=True)
    thread.start()

    def stop() -> None:
        node.shutdown()
        thread.join(1.0)
        node.destroy_node()

    return Hosted(stop, reset)


def _related(one: str, other: str) -> bool:
    """Whether one of the two names is the other's, or is below it."""
    return one == other or one.startswith(other + ".") or other.startswith(one + ".")


class GraphParameters:
    """A client of the graph's parameter server, for one node."""

    def __init__(self, node: Any, timeout: float = 5.0) -> None:
        self.node, self.timeout = node, timeout
        self._clients: dict[str, Any] = {}
        self._known: tuple[bool, float] | None = None  # (there, when asked)

    def _client(self, kind: str, suffix: str) -> Any:
        if suffix not in self._clients:
            self._clients[suffix] = self.node.create_client(kind, f"{NODE}/{suffix}")
        return self._clients[suffix]

    def available(self, wait: float = 1.0) -> bool:
        """Whether a server is on the graph (asked of the router, for up to `wait` seconds;
        the answer is believed for RECHECK seconds, so asking often costs a node little)."""
        if self._known is not None and time.monotonic() - self._known[1] < RECHECK:
            return self._known[0]
        found = self._client(params.GET, "get_parameters").wait_for_service(wait)
        self._known = (found, time.monotonic())
        return found

    def _call(self, kind: str, suffix: str, request: dict[str, Any]) -> Any:
        client = self._client(kind, suffix)
        return client.call(build(client.request_type, request), self.timeout)

    def names(self, prefix: str = "/") -> list[str]:
        below = key(prefix)
        found = self._below(below)
        if below:
            found += self._present([below])
        return sorted(ros1_name(name) for name in set(found))

    def _below(self, name: str) -> list[str]:
        """The server's parameters under `name` (all of them under the root, '')."""
        return list(self._call(params.LIST, "list_parameters",
                               {"prefixes": [name + "."] if name else []}).result.names)

    def _present(self, names: list[str]) -> list[str]:
        response = self._call(params.GET, "get_parameters", {"names": names})
        return [n for n, v in zip(names, response.values, strict=True)
                if v.type != params.NOT_SET]

    def get(self, ros1: str) -> Any:
        """The value, or the dict of everything below the name; Missing when neither."""
        name = key(ros1)
        if name:
            response = self._call(params.GET, "get_parameters", {"names": [name]})
            if response.values[0].type != params.NOT_SET:
                return _read(params.from_message(response.values[0]))
        below = self._below(name)
        if not below:
            raise Missing(f"Parameter [{ros1}] is not set")
        values = self._call(params.GET, "get_parameters", {"names": list(below)}).values
        return params.nested((full[len(name) + 1 if name else 0:],
                              _read(params.from_message(value)))
                             for full, value in zip(below, values, strict=True))

    def set(self, ros1: str, value: Any) -> None:
        if not key(ros1) and not isinstance(value, Mapping):
            raise LaunchError("/ holds every parameter: it can be set to a map of names, not "
                              "to one value")
        if isinstance(value, Mapping):
            self.delete(ros1, missing_ok=True)  # ROS 1: a dict replaces what was there
        self._set(leaves(ros1, value))

    def set_many(self, values: Mapping[str, Any]) -> None:
        """Parameters by ROS 1 name, in one request, in their order, as ROS 1's master sets
        them one after the other: a value replaces what was below its name (`/a` set after
        `/a/b`), and a name below a value replaces that value (`/a/b` set after `/a`)."""
        found: dict[str, Any] = {}
        for name, value in values.items():
            for leaf, item in leaves(name, value).items():
                for other in [k for k in found if _related(k, leaf)]:
                    del found[other]
                found[leaf] = item
        self._clear_around(found)
        self._set(found)

    def _clear_around(self, found: dict[str, Any]) -> None:
        """What the server holds above or below the names about to be set."""
        above = {name.rsplit(".", i)[0] for name in found for i in range(1, name.count(".") + 1)}
        doomed = self._present(sorted(above - set(found))) if above else []
        if found:
            below = self._call(params.LIST, "list_parameters",
                               {"prefixes": [n + "." for n in sorted(found)]}).result.names
            doomed += [n for n in below if n not in found]
        if doomed:
            self._call(params.SET, "set_parameters", {"parameters": [
                {"name": n, "value": params.to_message(None)} for n in set(doomed)]})

    def _set(self, values: dict[str, Any]) -> None:
        request = {"parameters": [{"name": n, "value": params.to_message(v)}
                                  for n, v in values.items()]}
        response = self._call(params.SET, "set_parameters", request)
        for name, result in zip(values, response.results, strict=True):
            if not result.successful:
                raise LaunchError(f"the parameter server refused [{ros1_name(name)}]: "
                                  f"{result.reason}")

    def delete(self, ros1: str, missing_ok: bool = False) -> None:
        """The name and everything below it."""
        name = key(ros1)
        doomed = [*(self._present([name]) if name else []), *self._below(name)]
        if not doomed:
            if missing_ok:
                return
            raise Missing(f"Parameter [{ros1}] is not set")
        self._call(params.SET, "set_parameters", {"parameters": [
            {"name": n, "value": params.to_message(None)} for n in doomed]})

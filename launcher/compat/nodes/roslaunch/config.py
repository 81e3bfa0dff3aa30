"""roslaunch.config: ROSLaunchConfig, what loading launch files makes (nodes, tests, params,
machines), and load_config_default, which loads them. Each file is read by launcher's ROS 1
frontend (roslaunch.xmlloader); the config also keeps what it read as launcher's launch
descriptions (`sources`), which roslaunch.launch's runner runs."""

from __future__ import annotations

import os
from typing import Any

from roslaunch.core import (
    DEFAULT_MASTER_URI,
    Machine,
    Master,
    Node,
    Param,
    RLException,
    Test,
    is_machine_local,
    local_machine,
    printerrlog,
    printlog,
)

DEFAULT_MASTER_PORT = 11311


def namespaces_of(name: str) -> list[str]:
    """The namespaces that hold `name`, outermost first ('/a/b/c' → ['/', '/a/', '/a/b/'])."""
    if name is None:
        raise ValueError("name")
    if name in ("", "/"):
        return ["/"]
    parts = [p for p in name.split("/") if p][:-1]
    return ["/", *("/" + "/".join(parts[:i + 1]) + "/" for i in range(len(parts)))]


def calculate_env_loader(env: dict[str, str] | None = None) -> str:
    """roslaunch's env-loader script for remote machines: launcher starts nothing through one
    (other hosts go through its SSH supervisor), so it names ROS_ENV_LOADER or nothing."""
    environment = os.environ if env is None else env
    loader = environment.get("ROS_ENV_LOADER")
    if loader is None:
        raise RLException("launcher has no env-loader script; set ROS_ENV_LOADER to name one")
    return loader


def get_roscore_filename() -> str:
    """roscore.xml's path: launcher has none (its graph needs no master to start)."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "roscore.xml")


def load_roscore(loader: Any, config: ROSLaunchConfig, verbose: bool = True) -> None:
    """Load roscore's launch into `config`: launcher's graph has no core processes to add,
    and its /rosdistro and /rosversion are the graph's own."""


class ROSLaunchConfig:
    """What a launch holds once loaded: its nodes, tests, parameters, machines and files."""

    def __init__(self) -> None:
        self.params: dict[str, Param] = {}
        self.nodes: list[Node] = []
        self.nodes_core: list[Node] = []
        self.tests: list[Test] = []
        self.machines: dict[str, Machine] = {"": local_machine()}
        self.clear_params: list[str] = []
        self.executables: list[Any] = []
        self.roslaunch_files: list[str] = []
        self.master = Master(uri=DEFAULT_MASTER_URI)
        self.config_errors: list[str] = []
        # launcher's own: (description, arguments) of each file, as the runner runs them
        self.sources: list[tuple[Any, dict[str, str]]] = []
        self._assign_machines_complete = False

    def add_roslaunch_file(self, f: str) -> None:
        """Note launch file `f` as read."""
        self.roslaunch_files.append(f)

    def add_config_error(self, msg: str) -> None:
        """Note an error found while loading."""
        self.config_errors.append(msg)

    def set_master(self, m: Master) -> None:
        """Use master `m`."""
        self.master = m

    def has_remote_nodes(self) -> bool:
        """Whether a node runs on another host."""
        self.assign_machines()
        return any(not is_machine_local(n.machine) for n in self.nodes + self.tests
                   if n.machine is not None)

    def assign_machines(self) -> None:
        """Give each node its Machine (this host when it names none)."""
        if self._assign_machines_complete:
            return
        for node in self.nodes_core + self.nodes + self.tests:
            if node.machine_name and node.machine_name not in self.machines:
                raise RLException(f"ERROR: unknown machine [{node.machine_name}]")
            node.machine = self.machines[node.machine_name or ""]
        self._assign_machines_complete = True

    def summary(self, local: bool = False) -> str:
        """roslaunch's SUMMARY: parameters, machines and nodes by namespace."""
        out = "\nSUMMARY\n========"
        if self.clear_params:
            out += "\n\nCLEAR PARAMETERS\n" + "\n".join(sorted(f" * {p}"
                                                           for p in self.clear_params))
        if self.params:
            out += "\n\nPARAMETERS\n" + "\n".join(sorted(
                f" * {k}: {_short(v.value)}" for k, v in self.params.items()))
        if not local:
            out += "\n\nMACHINES\n" + "\n".join(sorted(f" * {k}" for k in self.machines if k))
        out += "\n\nNODES\n"
        spaces: dict[str, list[Node]] = {}
        for node in self.nodes:
            spaces.setdefault(node.namespace, []).append(node)
        for space in sorted(spaces):
            out += f"  {space}\n" + "".join(f"    {n.name} ({n.package}/{n.type})\n"
                                            for n in spaces[space])
        return out

    def add_executable(self, exe: Any) -> None:
        """Add an executable to run."""
        if not exe:
            raise ValueError("exe is None")
        self.executables.append(exe)

    def add_clear_param(self, param: str) -> None:
        """Clear parameter namespace `param` before setting the launch's."""
        self.clear_params.append(param)

    def add_param(self, p: Param, filename: str | None = None, verbose: bool = True) -> None:
        """Set parameter `p` (a later one of the same key wins)."""
        if p.key in self.params and self.params[p.key] != p and filename is not None:
            printerrlog(f"WARN: overriding parameter [{p.key}]")
        self.params[p.key] = p
        if verbose:
            printlog(f"Added parameter [{p.key}]")

    def add_machine(self, m: Machine, verbose: bool = True) -> bool:
        """Add a machine; False when one of that name with the same settings is there."""
        if m.name in self.machines:
            if not m.config_equals(self.machines[m.name]):
                raise RLException(f"Machine [{m.name}] already added and does not match")
            return False
        self.machines[m.name] = m
        return True

    def add_test(self, test: Test, verbose: bool = True) -> None:
        """Add a rostest test."""
        self.tests.append(test)

    def add_node(self, node: Node, core: bool = False, verbose: bool = True) -> None:
        """Add a node (`core`: roscore's)."""
        if node.name and any(n.name == node.name and n.namespace == node.namespace
                             for n in self.nodes + self.nodes_core):
            raise RLException(f"roslaunch file contains multiple nodes named "
                              f"[{node.namespace}{node.name}].")
        (self.nodes_core if core else self.nodes).append(node)


def _short(value: Any) -> str:
    text = str(value)
    if len(text) > 20:
        text = text[:17] + "..."
    return text if text.isprintable() else "<...>"


def load_config_default(roslaunch_files: list[Any], port: int | None,
                        roslaunch_strs: list[str] | None = None, loader: Any = None,
                        verbose: bool = False, assign_machines: bool = True,
                        ignore_unset_args: bool = False) -> ROSLaunchConfig:
    """Load `roslaunch_files` (each a path, or (path, ['arg:=value', …])) and
    `roslaunch_strs` (launch XML) into a new ROSLaunchConfig."""
    from roslaunch.loader import LoadException
    from roslaunch.xmlloader import XmlLoader, XmlParseException

    config = ROSLaunchConfig()
    if port:
        config.master.uri = f"http://localhost:{port}/"
    loader = loader or XmlLoader()
    loader.ignore_unset_args = ignore_unset_args
    load_roscore(loader, config, verbose=verbose)
    try:
        for entry in roslaunch_files:
            path, argv = file_and_args(entry)
            loader.load(path, config, argv=argv, verbose=verbose)
        for text in roslaunch_strs or []:
            loader.load_string(text, config, verbose=verbose)
    except (XmlParseException, LoadException) as exc:
        raise RLException(str(exc)) from None
    if assign_machines:
        config.assign_machines()
    return config


def file_and_args(entry: Any) -> tuple[str, list[str] | None]:
    """A launch file entry as roslaunch takes it: 'file', (file, [args]) or [file, arg…]."""
    if isinstance(entry, str | os.PathLike):
        return os.fspath(entry), None
    path, *rest = entry
    if len(rest) == 1 and isinstance(rest[0], list | tuple):
        rest = list(rest[0])
    return os.fspath(path), [str(word) for word in rest]

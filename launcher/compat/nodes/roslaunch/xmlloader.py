"""roslaunch.xmlloader: XmlLoader, which loads a launch file into a ROSLaunchConfig. The file
is read by launcher's ROS 1 frontend and visited as a run visits it, with nothing started
(runtime/dry_run.py, as `roslaunch --nodes` does): the config's nodes, tests and parameters
are what the run would start and set, substitutions, includes and arguments resolved."""

from __future__ import annotations

import json
import os
import sys
import tempfile
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError
from launcher.runtime.dry_run import DryRun
from roslaunch.core import Machine, Node, Param, RLException, Test  # noqa: F401
from roslaunch.loader import Loader
from roslaunch.substitution_args import (  # noqa: F401 (roslaunch.xmlloader has them)
    ArgException,
    SubstitutionException,
    resolve_args,
)

NS = "ns"
CLEAR_PARAMS = "clear_params"


class XmlParseException(RLException):
    """A launch file that cannot be read."""


def ifunless_test(obj: Any, tag: Any, context: Any) -> bool:
    """Whether an element's if=/unless= lets it be loaded (with roslaunch's context)."""
    if_value, unless_value = tag.getAttribute("if"), tag.getAttribute("unless")
    if if_value and unless_value:
        raise XmlParseException("cannot set both 'if' and 'unless' on the same tag")
    word = if_value or unless_value
    if not word:
        return True
    value = resolve_args(word, context.resolve_dict).strip().lower()
    if value not in ("1", "0", "true", "false"):
        raise XmlParseException(f"{'if' if if_value else 'unless'} must be true or false, "
                                f"got '{value}'")
    return (value in ("1", "true")) == bool(if_value)


def ifunless(f: Any) -> Any:
    """Decorate a loader method `f(self, tag, context, …)` to skip elements if=/unless= turn
    off."""
    def call(*args: Any, **kwds: Any) -> Any:
        if ifunless_test(args[0], args[1], args[2]):
            return f(*args, **kwds)
        return None
    return call


class XmlLoader(Loader):
    """Loads roslaunch XML files into a ROSLaunchConfig, through launcher's frontend."""

    ARG_ATTRS = ("name", "value", "default", "doc")
    ENV_ATTRS = ("name", "value")
    GROUP_ATTRS = (NS, CLEAR_PARAMS)
    INCLUDE_ATTRS = ("file", NS, CLEAR_PARAMS, "pass_all_args")
    MACHINE_ATTRS = ("name", "address", "env-loader", "ssh-port", "user", "password",
                     "default", "timeout")
    NODE_ATTRS = ("pkg", "type", "machine", "name", "args", "output", "respawn",
                  "respawn_delay", "cwd", NS, CLEAR_PARAMS, "launch-prefix", "required")
    PARAM_ATTRS = ("name", "value", "type", "value", "textfile", "binfile", "command")
    REMAP_ATTRS = ("from", "to")
    ROSPARAM_OPT_ATTRS = ("command", NS, "file", "param", "subst_value")
    TEST_ATTRS = ("pkg", "type", "machine", "name", "args", "cwd", NS, "launch-prefix",
                  "test-name", "time-limit", "retry")

    def __init__(self, resolve_anon: bool = True, args_only: bool = False) -> None:
        self.resolve_anon, self.args_only = resolve_anon, args_only
        self.root_context: Any = None
        self.ignore_unset_args = False
        self._strings: list[tempfile.TemporaryDirectory] = []  # load_string's files

    def load(self, filename: str, ros_config: Any, core: bool = False,
             argv: list[str] | None = None, verbose: bool = True) -> None:
        """Load launch file `filename` into `ros_config`, its arguments the name:=value
        words of `argv` (sys.argv when None)."""
        words = sys.argv if argv is None else argv
        arguments = dict(w.split(":=", 1) for w in words if ":=" in w and not w.startswith("__"))
        try:
            read_into(ros_config, Path(filename), arguments)
        except LaunchError as exc:
            raise XmlParseException(str(exc)) from None
        ros_config.add_roslaunch_file(filename)

    def load_string(self, xml_text: str, ros_config: Any, core: bool = False,
                    verbose: bool = True) -> None:
        """Load launch XML `xml_text` into `ros_config`."""
        folder = tempfile.TemporaryDirectory(prefix="roslaunch-string-")
        self._strings.append(folder)  # (its file is read again when the launch runs)
        path = Path(folder.name) / "string.launch"
        path.write_text(xml_text, encoding="utf-8")
        try:
            read_into(ros_config, path, {})
        except LaunchError as exc:
            raise XmlParseException(str(exc)) from None

    def resolve_args(self, args: str, context: Any) -> str:
        """`args` with the context's substitutions resolved."""
        return resolve_args(args, context.resolve_dict, self.resolve_anon)

    def opt_attrs(self, tag: Any, context: Any, attrs: tuple[str, ...]) -> list[Any]:
        """The optional attributes `attrs` of element `tag`, resolved (None when absent)."""
        return [self.resolve_args(tag.getAttribute(a), context) if tag.hasAttribute(a)
                else None for a in attrs]

    def reqd_attrs(self, tag: Any, context: Any, attrs: tuple[str, ...]) -> list[Any]:
        """The required attributes `attrs` of element `tag`, resolved."""
        missing = [a for a in attrs if not tag.hasAttribute(a)]
        if missing:
            raise XmlParseException(f"<{tag.tagName}> is missing required attribute(s): "
                                    f"{', '.join(missing)}")
        return self.opt_attrs(tag, context, attrs)


# --- reading through launcher's frontend ------------------------------------------------------
class _Recorder(DryRun):
    """A dry run that notes each node as roslaunch's Node, read in the scope it starts in."""

    def __init__(self, context_of: Any) -> None:
        super().__init__()
        self.context_of = context_of
        self.nodes: list[Node] = []

    def start_process(self, spec: Any, started: Any = None) -> None:
        super().start_process(spec, started)
        node = node_of(spec, self.context_of())
        if node is not None:
            self.nodes.append(node)


def read_into(ros_config: Any, path: Path, arguments: dict[str, str]) -> None:
    """Read launch file `path` with `arguments` into `ros_config`: its nodes, tests and
    parameters, and the description that a run of the config runs."""
    from launcher.cli.launch_command import children_environment
    from launcher.cli.workspace import load_index
    from launcher.frontend.builder import parse_file_text
    from launcher.frontend.loader import load_file
    from launcher.runtime.context import LaunchContext

    description = load_file(path)
    index = load_index()
    holder: list[LaunchContext] = []
    dry = _Recorder(lambda: holder[0])
    with tempfile.TemporaryDirectory(prefix="launcher-roslaunch-") as folder:
        context = LaunchContext(children_environment(index, False), arguments, service=dry,
                                log_dir=Path(folder), load_description=dry.loader(load_file),
                                packages=index, parse_text=parse_file_text)
        holder.append(context)
        context.rostests = []  # type: ignore[attr-defined]
        dry.visit([description], context)
        for found in context.rostests:  # type: ignore[attr-defined]
            context.enter(found.snapshot)
            dry.visit([found.node], context)
            context.leave()
            node = dry.nodes.pop()
            ros_config.add_test(Test(found.name, node.package, node.type, node.name,
                                     node.namespace, args=node.args,
                                     remap_args=node.remap_args, env_args=node.env_args,
                                     time_limit=found.time_limit, retry=found.retry,
                                     filename=node.filename))
        for key, value in server_parameters(dry.specs).items():
            ros_config.add_param(Param(key, value), verbose=False)
    for node in dry.nodes:
        ros_config.add_node(node)
    ros_config.sources.append((description, arguments))


def server_parameters(specs: list[Any]) -> dict[str, Any]:
    """What the launch's helper (launcher.nodes.load_parameters) sets on the graph's server:
    its file, the last word of its command line."""
    found: dict[str, Any] = {}
    for spec in specs:
        if "launcher.nodes.load_parameters" in spec.argv:
            found.update(json.loads(Path(spec.argv[-1]).read_text()).get("set", {}))
    return dict(sorted(found.items()))


def node_of(spec: Any, context: Any) -> Node | None:
    """roslaunch's Node for a process the launch starts (None for one that is no ROS 1 node:
    a helper, a ROS 2 node)."""
    from launcher.description.substitution import perform_text

    origin = spec.origin
    words = {w.partition(":=")[0]: w.partition(":=")[2] for w in spec.argv if ":=" in w}
    if "__name" not in words or getattr(origin, "package", None) is None:
        return None
    package, node_type = (perform_text(context, t) for t in (origin.package, origin.executable))
    start = next((i for i, w in enumerate(spec.argv) if os.path.basename(w) == node_type), 0)
    rest = spec.argv[start + 1:]
    base = context.initial_environment
    return Node(package, node_type, words["__name"], spec.env.get("ROS_NAMESPACE", "/"),
                args=" ".join(w for w in rest if ":=" not in w),
                respawn=spec.respawn, respawn_delay=spec.respawn_delay,
                remap_args=[tuple(w.split(":=", 1)) for w in rest
                            if ":=" in w and not w.startswith("__")],
                env_args=[(k, v) for k, v in sorted(spec.env.items())
                          if base.get(k) != v and not k.startswith("LAUNCHER_")
                          and k != "ROS_NAMESPACE"],
                output="screen" if "screen" in spec.stdout_to else "log",
                required=bool(getattr(origin, "on_exit", None)),
                filename=str(context.files.current or "<unknown>"))


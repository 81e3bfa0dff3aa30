"""roslaunch's views of a launch, printed instead of running it: `--nodes`, `--args NODE`,
`--find-node NODE`, `--files` and `--dump-params`.

As roslaunch does, the whole launch is loaded as a run loads it (arguments, includes,
substitutions, `command=` parameters), here through a dry run (runtime/dry_run.py) that
starts nothing; the outputs follow roslaunch 1.16's (roslaunch/__init__.py, node_args.py,
param_dump.py, rlutil.print_file_list).
"""

from __future__ import annotations

import json
import shlex
import tempfile
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, did_you_mean

VIEWS = ("nodes", "node_args", "find_node", "files", "dump_params")


class Loaded:
    """A launch file loaded by a dry run: its nodes (full name → process spec and where it is
    declared), the files it read, and the parameters it sets on the graph's server."""

    def __init__(self, description: Any, configurations: dict[str, str], index: Any) -> None:
        from launcher.cli.launch_command import children_environment
        from launcher.frontend.builder import parse_file_text
        from launcher.frontend.loader import load_file
        from launcher.runtime.context import LaunchContext
        from launcher.runtime.dry_run import DryRun

        dry = DryRun()
        with tempfile.TemporaryDirectory(prefix="launcher-roslaunch-") as folder:
            self.environment = children_environment(index, False)
            context = LaunchContext(dict(self.environment), configurations,
                                    service=dry, log_dir=Path(folder),
                                    load_description=dry.loader(load_file), packages=index,
                                    parse_text=parse_file_text)
            dry.files += _files(description)
            dry.visit([description], context)
            self.parameters = _server_parameters(dry.specs)
        self.files = list(dict.fromkeys(dry.files))
        self.where = dict(context.node_names)
        self.nodes: dict[str, Any] = {}
        for spec in dry.specs:
            name = _node_name(spec)
            if name is not None:
                self.nodes.setdefault(name, spec)

    def node(self, name: str) -> str:
        """The full name of the node `name` (relative names are global, as roslaunch's
        script_resolve_name makes them), or roslaunch's error."""
        full = name if name.startswith("/") else f"/{name}"
        if full not in self.nodes:
            known = list(self.nodes)
            raise LaunchError(f"Cannot find node named [{full}]{did_you_mean(full, known)}. "
                              "Node names are:\n * " + "\n * ".join(known or ["(none)"]))
        return full


def show(args: Any, description: Any, configurations: dict[str, str], index: Any) -> int:
    loaded = Loaded(description, configurations, index)
    if args.nodes:
        print("\n".join(loaded.nodes))
    elif args.node_args:
        spec = loaded.nodes[loaded.node(args.node_args)]
        print(" ".join(_command_line(spec, loaded.environment)))
    elif args.find_node:
        print(loaded.where[loaded.node(args.find_node)].file)
    elif args.files:
        print("\n".join(str(f) for f in loaded.files))
    else:
        import yaml

        print(yaml.safe_dump(loaded.parameters, default_flow_style=False), end="")
    return 0


def _files(description: Any) -> list[Path]:
    """The files given on the command line (a description, or the group of each)."""
    if description.file is not None:
        return [Path(description.file).resolve()]
    return [Path(group.actions[0].file).resolve() for group in description.actions]


def _node_name(spec: Any) -> str | None:
    """A node's full name from its command line (roslaunch's __name:= with ROS_NAMESPACE,
    or ROS 2's -r __node:= and __ns:=); None for a process that is no named node."""
    words = [w for w in spec.argv if w.startswith(("__name:=", "__ns:=", "__node:="))]
    if not any(w.startswith(("__name:=", "__node:=")) for w in words):
        return None
    name, space = "", spec.env.get("ROS_NAMESPACE", "")
    for word in words:
        key, _, value = word.partition(":=")
        if key == "__ns":
            space = value
        else:
            name = value
    return f"{space.rstrip('/')}/{name}"


def _command_line(spec: Any, environment: dict[str, str]) -> list[str]:
    """roslaunch --args: what the launch sets in the node's environment beyond what every
    process of it gets, as VAR=value words, then its command line (launcher's own hand-overs,
    LAUNCHER_*, left out: they name this view's passing files)."""
    changed = [f"{key}={shlex.quote(value)}" for key, value in sorted(spec.env.items())
               if not key.startswith("LAUNCHER_") and environment.get(key) != value]
    return [*changed, *(shlex.quote(word) for word in spec.argv)]


def _server_parameters(specs: list[Any]) -> dict[str, Any]:
    """What the launch's helper would set on the graph's server (its file, argv's last word),
    as roslaunch's config.params has them, roscore.xml's /rosdistro and /rosversion among
    them (not /run_id, which a run makes)."""
    from launcher.bus.graph_parameters import master_parameters

    found: dict[str, Any] = master_parameters("")
    for spec in specs:
        if "launcher.nodes.load_parameters" in spec.argv:
            document = json.loads(Path(spec.argv[-1]).read_text())
            found.update(document.get("set", {}))
    found.pop("/run_id", None)
    return dict(sorted(found.items()))

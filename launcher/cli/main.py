"""`launcher COMMAND …`: parse argv, run the command, print one clean message on failure.

Only the module of the command being run is imported (start-up time is benchmarked); the
others are listed for `--help` from this table.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from typing import NamedTuple

from launcher import __version__
from launcher.arguments import Parser
from launcher.cli.ros1 import TOOLS as ROS1_TOOLS
from launcher.errors import reported

COMMANDS = {
    "launch": ("launcher.cli.launch_command", "run a launch file"),
    "pkg": ("launcher.cli.pkg_command", "packages: list, find, create"),
    "env": ("launcher.cli.env_command", "print the environment the workspace's hooks make"),
    "topic": ("launcher.cli.topic_command",
              "topics: list, echo, pub, hz, bw, delay, info, type, find"),
    "bag": ("launcher.cli.bag_command", "record and play rosbag2 bags: record, play, info, "
                                        "list"),
    "service": ("launcher.cli.service_command", "services: list, call, type, find, info"),
    "node": ("launcher.cli.node_command", "nodes: list, info"),
    "action": ("launcher.cli.action_command", "actions: list, info, type, send_goal"),
    "lifecycle": ("launcher.cli.lifecycle_command", "lifecycle nodes: nodes, list, get, set"),
    "control": ("launcher.cli.control_command", "ros2_control's controller manager: "
                "list_controllers, load_controller, switch_controllers, …"),
    "logger": ("launcher.cli.logger_command", "a node's logger levels: get, set"),
    "graph": ("launcher.cli.graph_command", "draw the graph's nodes and topics (as rqt_graph)"),
    "plot": ("launcher.cli.plot_command", "draw fields of messages over time (as rqt_plot)"),
    "rviz2-layout": ("launcher.cli.rviz_command", "convert an rviz config into a Foxglove "
                                                  "layout"),
    "param": ("launcher.cli.param_command",
              "parameters of a running node: list, get, set, describe, delete, dump, load"),
    "rosparam": ("launcher.cli.rosparam_command",
                 "ROS 1's rosparam: the graph's parameter server (list, get, set, delete, "
                 "dump, load)"),
    "interface": ("launcher.cli.interface_command",
                  "message and service types: list, show, proto, package, packages"),
    "run": ("launcher.cli.run_command", "run an executable of a package (as ros2 run / rosrun)"),
    "router": ("launcher.cli.router_command", "run a standing router of the graph"),
    "sim": ("launcher.cli.sim_command", "run the MuJoCo world server"),
    "gz": ("launcher.cli.gz_command", "Gazebo's commands (sim, topic, service, model)"),
    "doctor": ("launcher.cli.doctor_command", "check the install and the workspace; say what "
                                              "to fix"),
}


class Tool(NamedTuple):
    """A word that is a tool of its own: its module's `main(argv, prog)` takes the words after
    it as they are. `debug`: where --debug asks for tracebacks (any word, none: the tool's own
    flags, lead: the two words after it); `strip`: --debug is taken out of its words."""
    module: str
    name: str = ""  # the reporter's name for its errors
    debug: str = "any"
    strip: bool = False


# ROS 2's `ros2` and colcon (compat/bin), ROS 1's tools (cli/ros1), and launcher's commands
# whose words after them are another program's (gz sim's flags, -h included; run's executable)
TOOLS = {
    "ros2": Tool("launcher.cli.ros2_command"),
    "colcon": Tool("launcher.cli.colcon_command"),
    **{name: Tool(module, strip=True) for name, module in ROS1_TOOLS.items()},
    "sim": Tool("launcher.cli.sim_command", "sim", debug="none"),
    "run": Tool("launcher.cli.run_command", "run", debug="lead"),
    "gz": Tool("launcher.cli.gz_command", strip=True),
}


def build_parser(selected: str | None, prog: str = "launcher") -> tuple[
        argparse.ArgumentParser, argparse._SubParsersAction]:
    """The parser, and its subcommands (only the selected one's module is imported)."""
    parser = Parser(  # (its subcommands' parsers are Parsers too)
        prog=prog, description="ROS 2-style launch files for simulated robots.")
    parser.add_argument("--version", action="version", version=f"launcher {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, (module, helptext) in COMMANDS.items():
        if name == selected:
            importlib.import_module(module).add_parser(commands)
        else:
            commands.add_parser(name, help=helptext)
    return parser, commands


def main(argv: list[str] | None = None, prog: str = "launcher") -> int:
    if "_ARGCOMPLETE" in os.environ:  # the shell asks for completions (hooks/setup.sh)
        from launcher.cli.completion import complete

        return complete(build_parser, COMMANDS)
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] in TOOLS:
        return run_tool(argv[0], argv[1:])
    return reported(lambda: _parse_and_run(argv, prog), "", "--debug" in argv)


def run_tool(word: str, words: list[str]) -> int:
    """The tool `word` on the words after it (see TOOLS), its errors through the reporter."""
    tool = TOOLS[word]
    debug = {"any": "--debug" in words, "none": False, "lead": "--debug" in words[:2]}[tool.debug]
    given = [w for w in words if w != "--debug"] if tool.strip else words
    module = importlib.import_module(tool.module)
    return reported(lambda: module.main(given, word), tool.name, debug)


def _parse_and_run(argv: list[str], prog: str = "launcher") -> int | None:
    selected = next((word for word in argv if not word.startswith("-")), None)
    parser, commands = build_parser(selected if selected in COMMANDS else None, prog)
    if selected == "launch" and argv[0] == "launch":
        # `name:=value` may come before or after options (`--duration 10 drive:=false`)
        args = commands.choices["launch"].parse_intermixed_args(argv[1:])
    else:
        args = parser.parse_args_strictly(argv)
    return args.run(args)

if __name__ == "__main__":
    sys.exit(main())

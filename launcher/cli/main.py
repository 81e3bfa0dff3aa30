"""`launcher COMMAND …`: parse argv, run the command, print one clean message on failure.

Only the module of the command being run is imported (start-up time is benchmarked); the
others are listed for `--help` from this table.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys

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
    if argv[:1] == ["ros2"]:  # ROS 2's `ros2` (compat/bin): its verbs are launcher's commands
        from launcher.cli.ros2_command import translate

        debug = "--debug" in argv
        return reported(lambda: _ros2(translate(argv[1:])), "", debug)
    if argv[:1] == ["colcon"]:  # colcon (compat/bin): the real one, from the build tools
        from launcher.cli.colcon_command import main as colcon

        return reported(lambda: colcon(argv[1:]), "", "--debug" in argv)
    if argv[:1] and argv[0] in ROS1_TOOLS:  # ROS 1's rostopic, roslaunch, … (compat/bin)
        tool = importlib.import_module(ROS1_TOOLS[argv[0]])
        debug = "--debug" in argv
        rest = [a for a in argv[1:] if a != "--debug"]
        return reported(lambda: tool.main(rest, argv[0]), "", debug)
    if argv[:1] == ["sim"]:  # every flag after it is the sim's own (gz sim's), -h included
        from launcher.cli.sim_command import run_sim

        return reported(lambda: run_sim(argv[1:]), "sim")
    if argv[:1] == ["run"]:  # every word after PACKAGE EXECUTABLE is the executable's own
        from launcher.cli.run_command import run_run

        return reported(lambda: run_run(argv[1:]), "run", "--debug" in argv[1:3])
    if argv[:1] == ["gz"]:  # Gazebo's own flags, -h included
        from launcher.cli.gz_command import run_gz

        return reported(lambda: run_gz([a for a in argv[1:] if a != "--debug"]), "",
                        "--debug" in argv)
    return reported(lambda: _parse_and_run(argv, prog), "", "--debug" in argv)


def _ros2(argv: list[str] | None) -> int:
    return 0 if argv is None else main(argv, "ros2")


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

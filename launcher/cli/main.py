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
from launcher.cli.commands import LAUNCHER, ROS1
from launcher.cli.ros1 import TOOLS as ROS1_TOOLS
from launcher.cli.verbs import add_entries, run_group
from launcher.errors import reported

COMMANDS = LAUNCHER  # (the table: cli/commands.py)


class Tool(NamedTuple):
    """A word that is a tool of its own: its module's `main(argv, prog)` (or, with no module,
    the verbs of ROS1[word]) takes the words after it as they are. `debug`: where --debug asks
    for tracebacks (any word, none: the tool's own flags, lead: the two words after it);
    `strip`: --debug is taken out of its words."""
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
    **{name: Tool("", strip=True) for name in ROS1},
    "sim": Tool("launcher.cli.sim_command", "sim", debug="none"),
    "run": Tool("launcher.cli.run_command", "run", debug="lead"),
    "gz": Tool("launcher.cli.gz_command", strip=True),
}


def build_parser(words: list[str] | None, prog: str = "launcher") -> tuple[
        argparse.ArgumentParser, argparse._SubParsersAction]:
    """The parser, and its commands: only the verb `words` choose has its module imported
    (every one with EVERY)."""
    parser = Parser(  # (its subcommands' parsers are Parsers too)
        prog=prog, description="ROS 2-style launch files for simulated robots.")
    parser.add_argument("--version", action="version", version=f"launcher {__version__}")
    commands = add_entries(parser, COMMANDS, words, dest="command", metavar="COMMAND")
    return parser, commands


def main(argv: list[str] | None = None, prog: str = "launcher") -> int:
    if "_ARGCOMPLETE" in os.environ:  # the shell asks for completions (hooks/setup.sh)
        from launcher.cli.completion import complete

        return complete(build_parser)
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] in TOOLS:
        return run_tool(argv[0], argv[1:])
    return reported(lambda: _parse_and_run(argv, prog), "", "--debug" in argv)


def run_tool(word: str, words: list[str]) -> int:
    """The tool `word` on the words after it (see TOOLS), its errors through the reporter."""
    tool = TOOLS[word]
    debug = {"any": "--debug" in words, "none": False, "lead": "--debug" in words[:2]}[tool.debug]
    given = [w for w in words if w != "--debug"] if tool.strip else words
    if not tool.module:
        return reported(lambda: run_group(ROS1[word], given, word), tool.name, debug)
    module = importlib.import_module(tool.module)
    return reported(lambda: module.main(given, word), tool.name, debug)


def _parse_and_run(argv: list[str], prog: str = "launcher") -> int | None:
    parser, commands = build_parser(argv, prog)
    if argv[:1] == ["launch"]:
        # `name:=value` may come before or after options (`--duration 10 drive:=false`)
        args = commands.choices["launch"].parse_intermixed_args(argv[1:])
    else:
        args = parser.parse_args_strictly(argv)
    return args.run(args)

if __name__ == "__main__":
    sys.exit(main())

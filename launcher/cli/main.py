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
from launcher.cli.commands import LAUNCHER, TOOLS
from launcher.cli.verbs import add_entries, run_group
from launcher.errors import reported

COMMANDS = LAUNCHER  # (the table: cli/commands.py)


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
    """The tool `word` on the words after it (cli/commands.py's TOOLS), its errors through
    the reporter."""
    tool = TOOLS[word]
    debug = {"any": "--debug" in words, "none": False, "lead": "--debug" in words[:2]}[tool.debug]
    given = [w for w in words if w != "--debug"] if tool.strip else words
    if tool.group is not None:
        group = tool.group
        return reported(lambda: run_group(group, given, word), tool.name, debug)
    module = importlib.import_module(tool.module)
    return reported(lambda: module.main(given, word), tool.name, debug)


def _parse_and_run(argv: list[str], prog: str = "launcher") -> int | None:
    parser, commands = build_parser(argv, prog)
    if argv[:1] in (["launch"], ["batch"]):
        # `name:=value` may come before or after options (`--duration 10 drive:=false`)
        args = commands.choices[argv[0]].parse_intermixed_args(argv[1:])
    else:
        args = parser.parse_args_strictly(argv)
    return args.run(args)

if __name__ == "__main__":
    sys.exit(main())

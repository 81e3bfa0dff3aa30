"""Every option of every command says what it does, and a number says its unit."""

import argparse

import pytest

from launcher.cli import positive_number
from launcher.cli.commands import ROS1
from launcher.cli.main import COMMANDS, build_parser
from launcher.cli.verbs import EVERY, group_parser

UNITS = ("SECONDS", "seconds", " s)", " s ", "HZ", "Hz", "FACTOR", "times", "per second",
         "BYTES", "bytes", "PORT", "metres", "m/s", "messages", "N")


def options(parser: argparse.ArgumentParser, path: list[str]):
    """Every option and argument (the docs' CLI reference shows each with its help)."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from options(sub, [*path, name])
        elif action.dest != "help" and action.nargs != argparse.REMAINDER:
            yield " ".join(path), action


def parser_of(command: str) -> argparse.ArgumentParser:
    if command in ROS1:
        return group_parser(ROS1[command], command, EVERY)
    return build_parser(EVERY)[1].choices[command]


@pytest.mark.parametrize("command", sorted(COMMANDS) + sorted(ROS1))
def test_every_option_has_help_and_numbers_their_unit(command):
    for where, action in options(parser_of(command), [command]):
        name = "/".join(action.option_strings) or action.dest
        assert action.help, f"{where} {name} has no help text"
        if action.type in (float, positive_number):
            said = f"{action.help} {action.metavar or ''}"
            assert any(unit in said for unit in UNITS), f"{where} {name}: no unit in {said!r}"

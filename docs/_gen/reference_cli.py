"""The command-line reference: every `launcher` command walked from its argparse parser."""

from __future__ import annotations

import argparse
from collections.abc import Iterator

from md_tables import code, table

from launcher.cli.commands import ROS1
from launcher.cli.main import COMMANDS, build_parser
from launcher.cli.verbs import EVERY, group_parser

TITLE = "# Command line\n\nGenerated from the commands' own parsers at each build.\n"


def parsers() -> Iterator[tuple[str, argparse.ArgumentParser]]:
    """Each command's parser (`sim` and `gz` pass their words on to the sim's own parsers),
    then ROS 1's tools that have verbs."""
    import importlib

    from launcher.nodes import sim, snapshot

    _, commands = build_parser(EVERY)
    for name in COMMANDS:
        if name == "sim":
            yield "launcher sim", sim.build_parser()
            yield "launcher sim snapshot", snapshot.build_parser()
        elif name == "gz":
            for verb in ("topic", "service", "model"):  # (the package re-exports functions)
                parser = importlib.import_module(f"launcher.nodes.gz.{verb}").build_parser()
                yield f"launcher {parser.prog}", parser
        else:
            yield f"launcher {name}", commands.choices[name]
    for name, group in ROS1.items():
        yield name, group_parser(group, name, EVERY)


def page() -> str:
    parts = [TITLE]
    for title, parser in parsers():
        parts.append(_command(title, parser, 2))
    return "\n".join(parts)


def _command(title: str, parser: argparse.ArgumentParser, level: int) -> str:
    out = [f"{'#' * level} {title}\n"]
    if parser.description:
        out.append(parser.description.strip() + "\n")
    usage = parser.format_usage().removeprefix("usage: ").strip()
    out.append(f"```\n{' '.join(usage.split())}\n```\n")
    rows = [_row(action) for action in parser._actions
            if not isinstance(action, argparse._SubParsersAction)
            and action.help != argparse.SUPPRESS and action.dest != "help"]
    if rows:
        out.append(table(("argument", "meaning", "default"), rows))
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            helps = {a.dest: a.help for a in action._choices_actions}
            for name, sub in action.choices.items():
                if sub.description is None and helps.get(name):
                    sub.description = helps[name]
                out.append(_command(f"{title} {name}", sub, min(level + 1, 4)))
    return "\n".join(out)


def _row(action: argparse.Action) -> tuple[str, str, str]:
    if action.option_strings:
        value = "" if action.nargs == 0 else f" {_metavar(action)}"
        name = ", ".join(f"{flag}{value}" for flag in action.option_strings)
    else:
        name = _metavar(action)
    default = action.default
    shown = "" if default in (None, False, [], "", argparse.SUPPRESS) or action.nargs == 0 \
        else code(default)
    return code(name), action.help or "", shown


def _metavar(action: argparse.Action) -> str:
    if action.metavar is not None:
        return action.metavar if isinstance(action.metavar, str) else " ".join(action.metavar)
    if action.choices is not None:
        return "{" + ",".join(map(str, action.choices)) + "}"
    return action.dest.upper() if action.option_strings else action.dest

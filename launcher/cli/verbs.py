"""Commands and their verbs as ros2cli lays them out: one verb per module, each named in a
table (cli/commands.py) with its help, so that a parser lists every verb and imports only the
module of the one chosen.

A verb's module holds `add_arguments(parser)` and `run(args) -> int | None`; a group holds
verbs (or groups) under one word; a tool is a word whose words after it are another program's,
passed on as typed (cli/main.py runs it).
"""

from __future__ import annotations

import argparse
import importlib
from typing import Any, NamedTuple

from launcher.arguments import Parser


class Verb(NamedTuple):
    module: str  # holds add_arguments(parser) and run(args); the first may set a description
    help: str


class Group(NamedTuple):
    help: str
    verbs: dict[str, Verb | Group]
    description: str | None = None  # (default: the help)
    metavar: str = "VERB"  # ROS 1's tools say COMMAND
    defaults: dict[str, Any] = {}  # values every verb's args have (rossrv's kind)
    strict: bool = True  # False: words no verb knows are taken and unused (catkin_tools')


class Tool(NamedTuple):
    """A word whose words after it are another program's, passed on as typed (gz sim's flags,
    -h included; run's executable's; ros2's verbs): its module's `main(argv, prog) -> int`
    takes them, or, with no module, `group`'s chosen verb (ROS 1's rostopic, …). Where a tool
    is one of launcher's commands, its module's add_arguments(parser) describes those words
    for the help, completion and the docs; a run never parses them with it.

    `debug`: where --debug asks for tracebacks: "any" word, "none" (the tool's own flags),
    "lead" (the two words after it); `strip`: --debug is taken out of its words."""
    module: str = ""
    help: str = ""
    name: str = ""  # the reporter's name for its errors
    debug: str = "any"
    strip: bool = False
    group: Group | None = None


EVERY = None  # `words` that build every verb's arguments (the docs, the help checks)


def chosen(words: list[str] | None) -> str | None:
    """The word a parser over `words` chooses: the first that is not an option."""
    return next((word for word in words if not word.startswith("-")), None) \
        if words is not None else None


def add_entries(parser: argparse.ArgumentParser, table: dict[str, Verb | Group | Tool],
                words: list[str] | None, dest: str = "verb",
                metavar: str = "VERB") -> argparse._SubParsersAction:
    """`table`'s words under `parser`; the arguments of the one `words` chooses (of all with
    EVERY) are added, the others give their help only."""
    word = chosen(words)
    entries = parser.add_subparsers(dest=dest, metavar=metavar, required=True)
    for name, entry in table.items():
        sub = entries.add_parser(name, help=entry.help, description=getattr(
            entry, "description", None) or entry.help)
        if words is EVERY or name == word:
            rest = words[words.index(name) + 1:] if words is not EVERY else EVERY
            add_entry(sub, entry, rest)
    return entries


def add_entry(parser: argparse.ArgumentParser, entry: Verb | Group | Tool,
              words: list[str] | None) -> None:
    """One entry's arguments: a verb's own, a group's verbs, or the words a tool describes
    (a tool is run before any parse: cli/main.py)."""
    if isinstance(entry, Group):
        add_entries(parser, entry.verbs, words, metavar=entry.metavar)
        parser.set_defaults(**entry.defaults)
        return
    module = importlib.import_module(entry.module)
    module.add_arguments(parser)
    if isinstance(entry, Verb):
        parser.set_defaults(run=module.run)


def group_parser(group: Group, prog: str, words: list[str] | None) -> Parser:
    """A tool of its own whose words are `group`'s verbs (rostopic, catkin, …)."""
    parser = Parser(prog=prog, description=group.description or group.help)
    add_entry(parser, group, words)
    return parser


def run_group(group: Group, argv: list[str], prog: str) -> int:
    """`prog argv…`: the chosen verb run on its parsed arguments."""
    parser = group_parser(group, prog, argv)
    args = parser.parse_args_strictly(argv) if group.strict else parser.parse_known_args(argv)[0]
    return int(args.run(args) or 0)

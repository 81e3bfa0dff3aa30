"""The one argparse parser every entry point uses (the CLI, `launcher sim`, the router, the
built-in nodes): a command-line mistake is a UsageError (exit status 2) that the one reporter
prints, "did you mean" for a mistyped flag, and no usage block of argparse's own."""

from __future__ import annotations

import argparse
import os
import re
import sys
from collections.abc import Iterator
from typing import NoReturn

from launcher.errors import UsageError, did_you_mean


class Formatter(argparse.HelpFormatter):
    """argparse's formatter, sized without importing shutil (argparse makes one for every
    option it adds, and shutil is a good part of a launch's start-up imports)."""

    def __init__(self, prog: str, indent_increment: int = 2, max_help_position: int = 24,
                 width: int | None = None) -> None:
        if width is None:
            width = _columns() - 2
        super().__init__(prog, indent_increment, max_help_position, width)


def _columns() -> int:
    """What shutil.get_terminal_size() says: $COLUMNS, the terminal's width, or 80."""
    try:
        return int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        pass
    try:
        return os.get_terminal_size(sys.__stdout__.fileno()).columns or 80
    except (AttributeError, ValueError, OSError):
        return 80


class Parser(argparse.ArgumentParser):
    """argparse that raises one clean error, with "did you mean" for a mistyped flag (its
    subcommands' parsers are Parsers too)."""

    def __init__(self, *args: object, **kwargs: object) -> None:
        kwargs.setdefault("formatter_class", Formatter)
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]

    def error(self, message: str) -> NoReturn:
        hint = ""
        if message.startswith("unrecognized arguments: "):
            flags = [s for a in self._actions if a.help != argparse.SUPPRESS
                     for s in a.option_strings]  # (not the hidden ones)
            words = message.split(": ", 1)[1].split()
            hint = "".join(did_you_mean(w, flags) for w in words if w.startswith("-"))
        choice = re.search(r"invalid choice: '([^']*)' \(choose from (.*)\)$", message)
        if choice:
            hint = did_you_mean(choice.group(1), re.findall(r"'([^']*)'", choice.group(2)))
        raise UsageError(f"{self.prog}: {message}{hint} (see `{self.prog} -h`)")

    def parse_args_strictly(self, argv: list[str]) -> argparse.Namespace:
        """parse_args, with words no parser took said by the (sub)command that was given
        them: its name in the message and its flags in "did you mean"."""
        args, extra = self.parse_known_args(argv)
        if extra:
            _chosen(self, args).error(f"unrecognized arguments: {' '.join(extra)}")
        return args


def _chosen(parser: argparse.ArgumentParser, args: argparse.Namespace
            ) -> argparse.ArgumentParser:
    """The innermost subcommand's parser that `args` went through."""
    while True:
        commands = next((a for a in parser._actions
                         if isinstance(a, argparse._SubParsersAction)), None)
        chosen = getattr(args, commands.dest, None) if commands is not None else None
        if commands is None or chosen not in commands.choices:
            return parser
        parser = commands.choices[chosen]


def flag_words(argv: list[str], doc: str | None) -> Iterator[tuple[str, list[str]]]:
    """Gazebo's single-dash flags (`-name robot -x 1`): each word, with the words after it
    (a flag takes its values from them); `-h` prints `doc` and exits."""
    words = list(argv)
    while words:
        word = words.pop(0)
        if word in ("-h", "--help"):
            print(doc)
            raise SystemExit(0)
        yield word, words

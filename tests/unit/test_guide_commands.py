"""The docs name only commands and options the CLI has: every `launcher …` command line in a
guide, concept page or the README (in a shell block, or in `code` in the text), and every
`ros2 …` and ROS 1 tool line that launcher answers, is checked against the commands' own
parsers (those the CLI reference is generated from), so a renamed or removed option fails
here instead of misleading a user."""

from __future__ import annotations

import argparse
import re
import shlex
import sys
from pathlib import Path

import pytest

from launcher.cli import ros2_command
from launcher.cli.main import build_parser
from launcher.cli.verbs import EVERY
from tests.support.environment import REPO

sys.path.insert(0, str(REPO / "docs" / "_gen"))
import reference_cli  # noqa: E402 - the generator of the CLI reference, beside the docs

PAGES = sorted([REPO / "README.md", *(REPO / "docs").rglob("*.md")])
SHELL_BLOCKS = {"", "sh", "bash", "console", "shell", "zsh"}
ANYWHERE = {"--debug", "-h", "--help"}  # taken by every command (cli/main.py)


def command_parsers() -> dict[str, argparse.ArgumentParser]:
    """Every command and subcommand, by its words ("launcher topic echo")."""
    found: dict[str, argparse.ArgumentParser] = {}

    def add(title: str, parser: argparse.ArgumentParser) -> None:
        found.setdefault(title, parser)
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    add(f"{title} {name}", sub)

    for title, parser in reference_cli.parsers():
        add(title, parser)
        if not title.startswith("launcher "):  # ROS 1's tools: `rosparam`, `launcher rosparam`
            add(f"launcher {title}", parser)
    found["launcher gz sim"] = found["launcher sim"]  # (gz_command: the same program)
    root, _ = build_parser(EVERY)
    add("launcher", root)  # (after: `sim`, `gz` and `run` parse their words themselves)
    return found


PARSERS = command_parsers()
# the first words of the lines checked: launcher's, and the ROS names it answers to
LEADS = ("launcher", "ros2", *(t for t in PARSERS if " " not in t))


def as_launcher(words: list[str]) -> list[str] | None:
    """`ros2 VERB …` is `launcher VERB …` (cli/ros2_command.py); None for the verbs launcher
    answers without a parser of theirs (daemon) or says it lacks."""
    if words[:1] != ["ros2"]:
        return words
    verb = ros2_command.ALIASES.get(words[1], words[1]) if len(words) > 1 else ""
    return ["launcher", verb, *words[2:]] if verb in ros2_command.SAME or \
        verb in ros2_command.ALIASES.values() else None


def lines_of(page: Path) -> list[tuple[int, str]]:
    """(line number, command line) for each `launcher …` command on the page."""
    found: list[tuple[int, str]] = []
    fence: str | None = None
    pending, start = "", 0
    for number, line in enumerate(page.read_text().splitlines(), 1):
        marker = re.match(r"\s*```(\S*)", line)
        if marker:
            fence = None if fence is not None else marker.group(1)
            continue
        if fence is None:
            found += [(number, span) for span in re.findall(r"`([^`]+)`", line)
                      if span.split(" ", 1)[0] in LEADS and " " in span]
        elif fence in SHELL_BLOCKS:
            pending, start = (pending + " " + line.strip(), start) if pending \
                else (line.strip(), number)
            if pending.endswith("\\"):
                pending = pending[:-1]
                continue
            # two columns of commands side by side, each with its own comment
            for part in re.split(r"\s{3,}", pending.removeprefix("$ ")):
                if part.split(" ", 1)[0] in LEADS and " " in part:
                    found.append((start, part))
            pending = ""
    return found


def commands_in(text: str) -> list[list[str]]:
    """The words of a command line, one list per alternative (`rosparam get|set` is two);
    pipes, redirections and comments cut, `[optional]` brackets and `(notes)` dropped."""
    text = re.sub(r"\([^)]*\)", " ", text)
    text = re.split(r"\s(?:\||>|&&|;)\s", text)[0]
    try:
        words = shlex.split(text.replace("[", " ").replace("]", " "), comments=True)
    except ValueError:  # an unfinished quote: a snippet of a longer line
        words = text.replace("[", " ").replace("]", " ").split()
    commands = [words]
    for index, word in enumerate(words[:3]):
        if "|" in word and not word.startswith("-") and "/" not in word:
            commands = [[*words[:index], choice, *words[index + 1:]]
                        for choice in word.split("|")]
            break
    return commands


def placeholder(word: str) -> bool:
    return word.isupper() or "…" in word or "..." in word


def problems(words: list[str]) -> list[str]:
    """What the CLI lacks of the command `words` (empty when it has everything)."""
    launcher_words = as_launcher(words)
    if launcher_words is None:
        return []
    words = launcher_words
    for end in range(len(words), 0, -1):
        title = " ".join(words[:end])
        if title in PARSERS:
            parser, rest = PARSERS[title], words[end:]
            break
    else:
        return [f"no command `{' '.join(words[:2])}`"]
    subcommands = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    first = next((w for w in rest if not w.startswith("-")), None)
    if subcommands and first is not None and placeholder(first):
        return []  # (`launcher topic … --sim`: the options of any of its commands)
    if subcommands and first is not None and not placeholder(first) and \
            rest.index(first) == 0 and first not in subcommands[0].choices:
        return [f"`{title}` has no command '{first}' (it has: "
                f"{', '.join(subcommands[0].choices)})"]
    remainder = any(a.nargs == argparse.REMAINDER for a in parser._actions)
    missing = []
    for word in rest:
        if word in ("--", "--ros-args") or (remainder and not word.startswith("-")):
            break
        if not word.startswith("-") or re.match(r"-[\d.]", word) or word == "-":
            continue
        option = word.split("=", 1)[0]
        if option not in parser._option_string_actions and option not in ANYWHERE:
            missing.append(f"`{title}` has no option {option}")
    return missing


def documented() -> list[tuple[str, str]]:
    return [(f"{page.relative_to(REPO)}:{number}", text)
            for page in PAGES for number, text in lines_of(page)]


@pytest.mark.parametrize("where, text", documented(), ids=lambda value: value)
def test_a_documented_command_is_one_the_cli_has(where, text):
    found = [problem for words in commands_in(text) for problem in problems(words)]
    assert not found, f"{where}: {text}: " + "; ".join(found)


@pytest.mark.parametrize("text, expected", [
    ("launcher topic echo /odom --no-such-option", "has no option --no-such-option"),
    ("launcher topik list", "has no command 'topik'"),
    ("launcher rosparam list|fetch /ns", "has no command 'fetch'"),
    ("launcher sim snapshot -o a.png --wide 3", "has no option --wide"),
    ("ros2 topic echo /odom --nope", "`launcher topic echo` has no option --nope"),
    ("rostopic echo -n 1 --nope /odom", "`rostopic echo` has no option --nope"),
])
def test_the_check_finds_what_the_cli_lacks(text, expected):
    found = [problem for words in commands_in(text) for problem in problems(words)]
    assert any(expected in problem for problem in found), found


def test_the_check_reads_commands_from_shell_blocks_and_text(tmp_path):
    page = tmp_path / "page.md"
    page.write_text("Run `launcher topic list -t` first.\n\n```sh\n"
                    "launcher node list      launcher node info /driver   # two\n"
                    "launcher topic pub /x std_msgs/msg/String \\\n  '{data: a}' --once\n"
                    "```\n\n```python\nlauncher = 1\n```\n")
    assert lines_of(page) == [(1, "launcher topic list -t"), (4, "launcher node list"),
                              (4, "launcher node info /driver"),
                              (5, "launcher topic pub /x std_msgs/msg/String  '{data: a}' "
                                  "--once")]

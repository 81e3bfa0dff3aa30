"""One table names every command and verb (cli/commands.py); each verb is a module of its
own, and a parser imports only the chosen verb's."""

import importlib
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from launcher.cli.commands import LAUNCHER, ROS1, TOOLS
from launcher.cli.verbs import Group, Tool, group_parser, run_group

CLI = Path(__file__).resolve().parents[2] / "launcher" / "cli"


def every_verb(table: dict, path: str):
    for name, entry in table.items():
        if isinstance(entry, Group):
            yield from every_verb(entry.verbs, f"{path} {name}")
        else:
            yield f"{path} {name}", entry


VERBS = [*every_verb(LAUNCHER, "launcher"), *every_verb(ROS1, "")]


@pytest.mark.parametrize(("words", "verb"), VERBS, ids=[w.strip() for w, _ in VERBS])
def test_every_verb_in_the_table_is_a_module_with_its_arguments_and_its_run(words, verb):
    """A verb's module runs its parsed arguments; a tool's (sim, run, gz) takes its words as
    typed, and describes them."""
    module = importlib.import_module(verb.module)
    run = module.main if isinstance(verb, Tool) else module.run
    assert callable(module.add_arguments) and callable(run), words


@pytest.mark.parametrize("word", sorted(TOOLS))
def test_every_tool_is_a_module_that_takes_its_words_or_a_group(word):
    tool = TOOLS[word]
    assert bool(tool.module) != (tool.group is not None), word  # one or the other
    assert tool.group is not None or callable(importlib.import_module(tool.module).main), word


def test_every_verb_module_is_named_by_the_table():
    named = {verb.module for _, verb in VERBS}
    found = set()
    for path in CLI.rglob("*.py"):
        if re.search(r"^def add_arguments\(", path.read_text(), re.M):
            found.add(".".join(path.relative_to(CLI.parents[1]).with_suffix("").parts))
    assert found - named == set()


def test_only_the_verb_builder_makes_subcommands():
    makers = [path.name for path in CLI.rglob("*.py") if "add_subparsers" in path.read_text()]
    assert makers == ["verbs.py"]


def imported_verbs(words: list[str]) -> list[str]:
    """The verb modules a parser for `words` imports (in a fresh interpreter)."""
    code = ("import json, sys; from launcher.cli.main import build_parser; "
            f"build_parser({words!r}); "
            "print(json.dumps(sorted(m for m in sys.modules if m.count('.') >= 3 and "
            "m.startswith('launcher.cli.'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, cwd=CLI.parents[1])
    return json.loads(out.stdout)


def test_a_parser_imports_only_the_chosen_verbs_module():
    assert imported_verbs(["topic", "echo", "/chatter"]) == ["launcher.cli.topic.echo",
                                                             "launcher.cli.topic.lookup"]


def test_a_command_without_its_verb_imports_no_verb():
    assert imported_verbs(["topic", "--help"]) == []


def test_a_tools_group_gives_its_verbs_the_tools_defaults():
    args = group_parser(ROS1["rossrv"], "rossrv", ["list"]).parse_args(["list"])
    assert args.kind == "srv"


def test_a_lenient_group_takes_words_no_verb_knows(tmp_path):
    run_group(ROS1["catkin"], ["init", "-w", str(tmp_path), "--no-notify"], "catkin")
    assert (tmp_path / ".catkin_tools").is_dir()


def test_ros2_runs_the_verbs_the_table_has():
    from launcher.cli.ros2_command import SAME, VERBS

    assert {verb for verb in VERBS if verb in LAUNCHER} == SAME and "topic" in SAME


@pytest.mark.parametrize("words", [
    ["topic", "echo", "/chatter", "--full-length", "--sim", "--qos-profile", "sensor_data"],
    ["control", "switch_controllers", "--strict", "--activate-asap", "-c", "/cm"],
    ["interface", "list", "--only-msgs"],
], ids=["topic echo", "control switch_controllers", "interface list"])
def test_options_beside_a_verbs_exclusive_group_combine_with_it(words):
    from launcher.cli.main import build_parser

    parser, _ = build_parser(words)
    assert parser.parse_args(words).run is not None


def test_rostopic_pubs_latch_option_combines_with_its_rate():
    args = group_parser(ROS1["rostopic"], "rostopic", ["pub"]).parse_args(
        ["pub", "-r", "10", "-l", "/c", "std_msgs/String", "hi"])
    assert args.latch and args.rate == 10.0

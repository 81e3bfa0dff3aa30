"""What of a run is compared, written the same way whichever tool made it.

A run's folder, its ROS home and log folder, the probe's workspace, generated parameter-file
paths, anonymous names and run ids differ from run to run and tool to tool; they become
placeholders. Everything else the probe saw (argv, the environment a launch sets, the working
folder, parameters) is kept as it was.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import yaml

from tests.fidelity.runner import WORKSPACE, Outcome

# $(anon n), roslaunch's and launch's: n_<host>_<pid>_<random>
_ANON = re.compile(r"\b([A-Za-z][A-Za-z0-9]*?)_(?:[A-Za-z0-9]+_)*\d{5,}\b")
_LOG_ARG = re.compile(r"^__log:=(.*/)?([^/]*?)(?:-\d+)?\.log$")
_SERVER_VALUES = {"/run_id": "<run_id>", "/rosversion": "<rosversion>",
                  "/rosdistro": "<rosdistro>"}
KEPT_ENV = ("ROS_NAMESPACE",)
SHELL_ONLY_ENV = ("PROBE_OUT", "PROBE_ROS1")


class Paths:
    """The run-specific folders of one run, and the placeholders they become."""

    def __init__(self, folder: Path) -> None:
        self.places = [(str(folder / "home"), "<home>"), (str(folder / "log"), "<log>"),
                       (str(folder), "<case>"), (str(WORKSPACE), "<workspace>")]

    def text(self, value: str) -> str:
        for place, name in self.places:
            value = value.replace(place, name)
        return _ANON.sub(lambda m: f"<anon:{m.group(1)}>", value)

    def tree(self, value: Any) -> Any:
        if isinstance(value, str):
            return self.text(value)
        if isinstance(value, list):
            return [self.tree(item) for item in value]
        if isinstance(value, dict):
            return {self.text(key): self.tree(item) for key, item in value.items()}
        return value


def outcome(run: Outcome, folder: Path, flavour: str) -> dict[str, Any]:
    """The exit, the probe's starts (as a set: processes start in any order) and, for a
    Python case, its notes in the order the launch made them."""
    paths = Paths(folder)
    starts = [_start(record, paths, flavour) for record in run.records if "note" not in record]
    unique = sorted({json.dumps(start, sort_keys=True) for start in starts})
    result = {
        "exit": "ok" if run.exit in (0, "interrupted") else run.exit,
        "starts": [json.loads(text) for text in unique],
        "restarted": sorted({start["name"] for start in starts
                             if sum(other == start for other in starts) > 1}),
    }
    notes = [paths.tree(record["note"]) for record in run.records if "note" in record]
    if notes:
        result["notes"] = notes
    return result


def _start(record: dict[str, Any], paths: Paths, flavour: str) -> dict[str, Any]:
    argv, files = _argv(record["argv"], record.get("parameter_files", {}), paths)
    env = {key: paths.text(value) for key, value in record["env"].items()
           if (key.startswith("PROBE_") and key not in SHELL_ONLY_ENV) or key in KEPT_ENV}
    start: dict[str, Any] = {"name": paths.text(_name(record["argv"], flavour)), "argv": argv,
                             "env": env, "cwd": paths.text(record["cwd"])}
    if files:
        start["parameter_files"] = files
    if "parameters" in record:
        start["parameters"] = _server(paths.tree(record["parameters"]))
    return start


def _argv(argv: list[str], contents: dict[str, str], paths: Paths) -> tuple[list, list]:
    out, files = [], []
    for index, word in enumerate(argv):
        if index and argv[index - 1] == "--params-file" and word in contents:
            out.append(f"<params:{len(files)}>")
            try:
                files.append(paths.tree(yaml.safe_load(contents[word])))
            except yaml.YAMLError:
                files.append(paths.text(contents[word]))
            continue
        match = _LOG_ARG.match(word)
        out.append(f"__log:=<log>/{paths.text(match.group(2))}.log" if match
                   else paths.text(word))
    return out, files


def _name(argv: list[str], flavour: str) -> str:
    for index, word in enumerate(argv):
        if flavour == "ros1" and word.startswith("__name:="):
            return word.split(":=", 1)[1]
        if flavour == "ros2" and word.startswith("__node:=") and argv[index - 1] == "-r":
            return word.split(":=", 1)[1]
    return "<unnamed>"


def _server(tree: Any) -> Any:
    """The master's tree with roslaunch's own run-specific values named, not compared, and
    without /roslaunch/uris (the address of roslaunch's own XML-RPC server, which launcher,
    having none, leaves out: a listed choice)."""
    if not isinstance(tree, dict):
        return tree
    flat = {key: value for key, value in tree.items() if key != "roslaunch"}
    for key, placeholder in _SERVER_VALUES.items():
        if key.strip("/") in flat:
            flat[key.strip("/")] = placeholder
    return flat

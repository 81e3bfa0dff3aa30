"""Where launcher differs from the real tool on purpose: each case, what launcher does
instead, and why. The docs page of deliberate differences is made from this table
(docs/_gen), so the list a user reads is the list the test holds launcher to.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Choice:
    reason: str  # one or two sentences, for the docs
    change: Callable[[dict[str, Any]], None]  # turns the recorded outcome into launcher's

    def apply(self, recorded: dict[str, Any]) -> dict[str, Any]:
        chosen = copy.deepcopy(recorded)
        self.change(chosen)
        return chosen


def exits(code: Any) -> Callable[[dict[str, Any]], None]:
    def change(outcome: dict[str, Any]) -> None:
        outcome["exit"] = code
    return change


def starts_nothing(code: int = 1) -> Callable[[dict[str, Any]], None]:
    def change(outcome: dict[str, Any]) -> None:
        outcome.update(exit=code, starts=[], restarted=[])
    return change


# Reasons shared by several cases
CRASH_REPORTED = ("ROS 2's launch crashes on this input with a Python traceback (its own "
                  "bug); launcher reports a located error and starts nothing.")

NOT_STARTED_FAILS = ("roslaunch logs that it cannot launch the node, runs on with nothing "
                     "of it, and exits 0 when stopped; launcher reports the missing package "
                     "or executable at its place in the file, and the launch's exit status "
                     "is 1, so a script or a test sees it.")

def becomes(outcome: dict[str, Any]) -> Callable[[dict[str, Any]], None]:
    """The outcome launcher has instead (where the real tool fails and launcher does not)."""
    def change(recorded: dict[str, Any]) -> None:
        recorded.clear()
        recorded.update(copy.deepcopy(outcome))
    return change


def _probe(argv: list[str]) -> dict[str, Any]:
    return {"argv": argv, "cwd": "<case>", "env": {}, "name": "n"}


CHOICES: dict[str, Choice] = {
    "ros1/subst/unclosed": Choice(
        "roslaunch keeps an unclosed `$(arg a` as text and passes the typo on to the node; "
        "launcher refuses it at its place in the file, and starts nothing.",
        starts_nothing()),
    "ros1/group/ns-bad-name": Choice(
        "roslaunch passes a namespace holding a space on to its nodes, where ROS names "
        "cannot hold one; launcher refuses the invalid name at its place, and starts "
        "nothing.", starts_nothing()),
    "ros1/node/type-missing": Choice(NOT_STARTED_FAILS, exits(1)),
    "ros1/node/package-missing": Choice(NOT_STARTED_FAILS, exits(1)),
    "ros1/node/exits-nonzero": Choice(
        "roslaunch logs that a node died and exits 0 when stopped; launcher's exit status "
        "is 1 when a node exits with an error it did not cause (as ROS 2's launch has it), "
        "so a script or a test sees the failure.", exits(1)),
    "ros2/xml/param/from-missing-file": Choice(
        "launch_ros hands a parameters file that does not exist to the node, which fails when "
        "rcl cannot open it; launcher reports the missing file at its place in the launch "
        "file, and starts nothing.", starts_nothing()),
    "ros2/xml/node/no-pkg": Choice(
        "A node without pkg runs its executable from PATH in both; when it is not there, "
        "ROS 2's launch prints a Python traceback and runs on with nothing started, "
        "launcher says it cannot start the command, at the node's place, and exits 1.",
        exits(1)),
    "ros2/xml/param/set-use-sim-time": Choice(
        "launch_ros 0.28 exposes `<set_use_sim_time>` to XML and YAML, but its parser fails "
        "on every value (\"Type '1' and value … do not agree\", its own bug); launcher reads "
        "the value as the tag documents it, as launch_ros's Python action does.",
        becomes({"exit": "ok", "restarted": [], "starts": [_probe(
            ["--ros-args", "-r", "__node:=n", "-p", "use_sim_time:=true"])]})),
    "ros2/yaml/node/respawn-bool": Choice(
        "launch's YAML frontend refuses `respawn: true` (a YAML boolean) and takes only the "
        "text 'true'; launcher takes both, as YAML users write booleans.",
        becomes({"exit": "ok", "restarted": ["n"], "starts": [_probe(
            ["--ros-args", "-r", "__node:=n"])]})),
}

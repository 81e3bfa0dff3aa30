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
}

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

CHOICES: dict[str, Choice] = {}

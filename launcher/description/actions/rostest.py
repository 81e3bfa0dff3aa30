"""`rostest`: a ROS 1 `<test>` (the frontend makes one of each): a node that rostest runs once
the launch's own nodes have started, and that roslaunch leaves out, as ROS 1 does. Visited, it
hands itself to the run's collector of tests (`context.rostests`, which rostest sets), in the
scope it was met in."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

from launcher.description.action import Action
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import perform_text
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext, Snapshot


class CollectedTest(NamedTuple):
    """A test met by the launch, to run later in the scope it was met in."""
    name: str
    time_limit: float
    retry: int
    node: Action
    snapshot: Snapshot


@action("rostest")
@dataclass(kw_only=True, eq=False)
class RosTest(Action):
    test_name: Any = attr(Kind.TEXT, name="test-name", required=True,
                          doc="The test's name in the results.")
    time_limit: Any = attr(Kind.FLOAT, 60.0, name="time-limit", minimum=0,
                           doc="Seconds the test may run before it fails.")
    retry: Any = attr(Kind.INT, 0, minimum=0, doc="Times a failed test is run again.")
    actions: list[Action] = attr(Kind.CHILDREN, doc="The test's node.")

    def execute(self, context: LaunchContext) -> Sequence[Action] | None:
        collected = getattr(context, "rostests", None)
        if collected is not None:  # (roslaunch: none, and the test is left out)
            collected.append(CollectedTest(
                perform_text(context, self.test_name),
                resolve(context, self.time_limit, Kind.FLOAT, "time-limit"),
                resolve(context, self.retry, Kind.INT, "retry"), self.actions[0],
                context.snapshot()))
        return None

    def sub_actions(self) -> Sequence[Action]:
        return self.actions

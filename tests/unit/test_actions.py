"""The parts of rclpy.action that need no bus: the status array written directly as CDR is
the one the type store writes."""

from __future__ import annotations

import subprocess
import sys

from launcher.bus.types import registry
from launcher.compat import finder

finder.install()

from action_msgs.msg import GoalInfo, GoalStatus, GoalStatusArray  # noqa: E402
from builtin_interfaces.msg import Time  # noqa: E402
from unique_identifier_msgs.msg import UUID  # noqa: E402

from launcher.bus.actions import status_array_cdr, statuses  # noqa: E402
from launcher.machines import InvalidTransition  # noqa: E402


def test_the_status_array_written_directly_is_the_type_stores():
    entries = [(bytes(range(16)), 5, 7, 2), (bytes(range(16, 32)), 6, 8, 4),
               (bytes(range(32, 48)), 2**31 - 1, 999_999_999, 6)]
    message = GoalStatusArray(status_list=[
        GoalStatus(goal_info=GoalInfo(goal_id=UUID(uuid=list(u)), stamp=Time(sec=s, nanosec=n)),
                   status=st) for u, s, n, st in entries])
    expected = bytes(registry().serialize(message, "action_msgs/msg/GoalStatusArray"))
    assert status_array_cdr(entries) == expected
    assert status_array_cdr([]) == bytes(registry().serialize(
        GoalStatusArray(), "action_msgs/msg/GoalStatusArray"))


def test_the_client_reads_goal_statuses_from_the_bytes():
    entries = [(bytes(range(16)), 5, 7, 2), (bytes(range(16, 32)), 6, 8, 4)]
    assert statuses(status_array_cdr(entries)) == [(bytes(range(16)), 2),
                                                   (bytes(range(16, 32)), 4)]


def test_the_standard_action_types_are_there_with_their_fields():
    from action_tutorials_interfaces.action import Fibonacci
    from control_msgs.action import FollowJointTrajectory, GripperCommand
    from nav2_msgs.action import NavigateToPose

    goal = FollowJointTrajectory.Goal()
    goal.trajectory.joint_names = ["shoulder", "elbow"]
    data = registry().serialize(goal, "control_msgs/action/FollowJointTrajectory_Goal")
    back = registry().deserialize(data, "control_msgs/action/FollowJointTrajectory_Goal")
    assert list(back.trajectory.joint_names) == ["shoulder", "elbow"]
    assert FollowJointTrajectory.Result.GOAL_TOLERANCE_VIOLATED == -5
    assert GripperCommand.Goal().command.max_effort == 0.0
    assert "stalled" in GripperCommand.Result.get_fields_and_field_types()
    pose = NavigateToPose.Goal()
    pose.pose.header.frame_id = "map"
    assert NavigateToPose.Impl.SendGoalService.Request(goal=pose).goal.pose.header.frame_id \
        == "map"
    assert "partial_sequence" in Fibonacci.Feedback.get_fields_and_field_types()


class _Reply:
    def __init__(self):
        self.sent = []

    def send(self, response):
        self.sent.append(response)


def _goal(number, sec):
    from types import SimpleNamespace

    from launcher.bus import actions

    return actions.Goal(SimpleNamespace(uuid=[number] * 16), SimpleNamespace(sec=sec, nanosec=0))


def _table():
    from launcher.bus import actions

    said = []
    return actions.GoalTable(said.append), said


def test_a_goal_moves_only_as_rcl_action_lets_it():
    from launcher.bus import actions

    table, said = _table()
    goal = _goal(1, 1)
    table.add(goal)
    table.move(goal, actions.GoalEvent.EXECUTE)
    assert actions.statuses(said[-1]) == [(bytes([1] * 16), actions.EXECUTING)]
    try:
        table.move(goal, actions.GoalEvent.CANCELED)
    except InvalidTransition as exc:
        assert "from state EXECUTING with event CANCELED" in str(exc)
    else:
        raise AssertionError("EXECUTING -> CANCELED was allowed")


def test_a_result_request_waits_for_the_goals_end_and_an_unknown_one_is_answered_at_once():
    from launcher.bus import actions

    table, _ = _table()
    goal = _goal(1, 1)
    table.add(goal)
    waiting, unknown = _Reply(), _Reply()
    assert table.result_request(goal.key, waiting, lambda: "unknown")
    assert not table.result_request(bytes([9] * 16), unknown, lambda: "unknown")
    assert waiting.sent == [] and unknown.sent == ["unknown"]
    table.move(goal, actions.GoalEvent.EXECUTE)
    table.move(goal, actions.GoalEvent.SUCCEED)
    table.finish(goal, "result")
    assert waiting.sent == ["result"]


def test_a_cancel_request_names_goals_as_rcl_action_reads_it():
    from launcher.bus import actions

    table, _ = _table()
    early, late = _goal(1, 1), _goal(2, 5)
    for goal in (early, late):
        table.add(goal)
    everything = bytes(16)
    assert table.cancel_candidates(everything, 0) == (actions.ERROR_NONE, [early, late])
    assert table.cancel_candidates(everything, 2 * 10**9) == (actions.ERROR_NONE, [early])
    assert table.cancel_candidates(late.key, 0) == (actions.ERROR_NONE, [late])
    assert table.cancel_candidates(bytes([7] * 16), 0) == (actions.ERROR_UNKNOWN_GOAL_ID, [])
    table.move(early, actions.GoalEvent.EXECUTE)
    table.move(early, actions.GoalEvent.ABORT)
    assert table.cancel_candidates(early.key, 0) == (actions.ERROR_GOAL_TERMINATED, [])


def test_an_ended_goal_is_forgotten_once_its_result_has_been_kept_long_enough():
    from launcher.bus import actions

    table, said = _table()
    table.keep = 0.0
    goal = _goal(1, 1)
    table.add(goal)
    table.move(goal, actions.GoalEvent.EXECUTE)
    table.move(goal, actions.GoalEvent.SUCCEED)
    table.expire()
    assert goal.key not in table and actions.statuses(said[-1]) == []


ACTIONLIB_TABLE = """
from launcher.compat import finder
finder.install()
from actionlib import status as S
from launcher.machines import InvalidTransition
assert S.MACHINE.move(S.PENDING, S.Event.CANCEL) == S.RECALLED
assert S.MACHINE.move(S.ACTIVE, S.Event.CANCEL_REQUEST) == S.PREEMPTING
assert S.MACHINE.move(S.PREEMPTING, S.Event.SUCCEED) == S.SUCCEEDED
try:
    S.MACHINE.move(S.SUCCEEDED, S.Event.ABORT)
except InvalidTransition as exc:
    print(exc)
"""


def test_actionlibs_goals_move_by_the_same_kind_of_table():
    # (in a process of its own: importing rospy, as actionlib does, makes the message classes
    # take ints for floats, as ROS 1 does, for the rest of the process)
    done = subprocess.run([sys.executable, "-c", ACTIONLIB_TABLE], capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "from state SUCCEEDED with event ABORT" in done.stdout, done.stdout

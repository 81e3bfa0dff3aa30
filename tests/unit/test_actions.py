"""The parts of rclpy.action that need no bus: the status array written directly as CDR is
the one the type store writes."""

from __future__ import annotations

from launcher.bus.types import registry
from launcher.compat import finder

finder.install()

from action_msgs.msg import GoalInfo, GoalStatus, GoalStatusArray  # noqa: E402
from builtin_interfaces.msg import Time  # noqa: E402
from rclpy.action.server import status_array_cdr  # noqa: E402
from unique_identifier_msgs.msg import UUID  # noqa: E402


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
    from rclpy.action.client import _statuses

    entries = [(bytes(range(16)), 5, 7, 2), (bytes(range(16, 32)), 6, 8, 4)]
    assert _statuses(status_array_cdr(entries)) == [(bytes(range(16)), 2),
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

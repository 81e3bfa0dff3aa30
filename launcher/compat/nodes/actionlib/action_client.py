"""actionlib.action_client: the client side's states (CommState, TerminalState) and their
names. launcher's actionlib gives SimpleActionClient (simple_action_client.py), not yet the
goal-handle API (ActionClient, ClientGoalHandle)."""

from __future__ import annotations

from actionlib.exceptions import ActionException  # noqa: F401 (action_client has it)
from actionlib.status import ABORTED, LOST, PREEMPTED, RECALLED, REJECTED, SUCCEEDED

g_goal_id = 1  # (actionlib's counter, kept for code that reads it)
NO_TRANSITION = -1  # CommStateMachine's answers: no move, or a move that cannot be
INVALID_TRANSITION = -2


def get_name_of_constant(C: type, n: int) -> str:  # noqa: N803 (actionlib's names)
    """The name of `C`'s constant whose value is `n` (`NO_SUCH_STATE_<n>` if none)."""
    for name, value in vars(C).items():
        if isinstance(value, int) and value == n:
            return name
    return f"NO_SUCH_STATE_{n}"


class CommState:
    """Where a goal's exchange with the server stands, as the client follows it."""

    WAITING_FOR_GOAL_ACK = 0
    PENDING = 1
    ACTIVE = 2
    WAITING_FOR_RESULT = 3
    WAITING_FOR_CANCEL_ACK = 4
    RECALLING = 5
    PREEMPTING = 6
    DONE = 7
    LOST = 8
    to_string = classmethod(get_name_of_constant)


class TerminalState:
    """How a goal ended (actionlib_msgs/GoalStatus's values)."""

    RECALLED = RECALLED
    REJECTED = REJECTED
    PREEMPTED = PREEMPTED
    ABORTED = ABORTED
    SUCCEEDED = SUCCEEDED
    LOST = LOST
    to_string = classmethod(get_name_of_constant)

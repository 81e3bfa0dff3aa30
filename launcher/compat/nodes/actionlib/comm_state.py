"""The client side's states of a goal (CommState), how goals end (TerminalState), and the table
that moves a CommState by the status the server reports (actionlib's, as data).
actionlib.action_client gives these names."""

from __future__ import annotations

from actionlib import status as S

NO_TRANSITION = -1  # the table's answers: no move, or a move that cannot be
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

    RECALLED = S.RECALLED
    REJECTED = S.REJECTED
    PREEMPTED = S.PREEMPTED
    ABORTED = S.ABORTED
    SUCCEEDED = S.SUCCEEDED
    LOST = S.LOST
    to_string = classmethod(get_name_of_constant)


C = CommState
_SUCCEEDED_OR_ABORTED_BY = {S.SUCCEEDED: (C.WAITING_FOR_RESULT,),
                            S.ABORTED: (C.WAITING_FOR_RESULT,)}
_ENDED_WHILE_CANCELING = {S.PREEMPTED: (C.PREEMPTING, C.WAITING_FOR_RESULT),
                          S.SUCCEEDED: (C.PREEMPTING, C.WAITING_FOR_RESULT),
                          S.ABORTED: (C.PREEMPTING, C.WAITING_FOR_RESULT),
                          S.PREEMPTING: (C.PREEMPTING,)}
_FROM_UNACCEPTED = {S.ACTIVE: (C.ACTIVE,),
                    S.PREEMPTED: (C.ACTIVE, C.PREEMPTING, C.WAITING_FOR_RESULT),
                    S.SUCCEEDED: (C.ACTIVE, C.WAITING_FOR_RESULT),
                    S.ABORTED: (C.ACTIVE, C.WAITING_FOR_RESULT),
                    S.PREEMPTING: (C.ACTIVE, C.PREEMPTING)}
_ENDED = {status: () for status in (S.REJECTED, S.RECALLED, S.PREEMPTED, S.SUCCEEDED,
                                    S.ABORTED)}
# {comm state: {goal status reported: the comm states passed through, in order}}; () is no
# move; a status a row lacks is a move that cannot be (an error, the state kept)
TRANSITIONS: dict[int, dict[int, tuple[int, ...]]] = {
    C.WAITING_FOR_GOAL_ACK: {**_FROM_UNACCEPTED, S.PENDING: (C.PENDING,),
                             S.REJECTED: (C.PENDING, C.WAITING_FOR_RESULT),
                             S.RECALLING: (C.PENDING, C.RECALLING),
                             S.RECALLED: (C.PENDING, C.WAITING_FOR_RESULT)},
    C.PENDING: {**_FROM_UNACCEPTED, S.PENDING: (), S.REJECTED: (C.WAITING_FOR_RESULT,),
                S.RECALLING: (C.RECALLING,), S.RECALLED: (C.RECALLING, C.WAITING_FOR_RESULT)},
    C.ACTIVE: {S.ACTIVE: (), S.PREEMPTED: (C.PREEMPTING, C.WAITING_FOR_RESULT),
               S.PREEMPTING: (C.PREEMPTING,), **_SUCCEEDED_OR_ABORTED_BY},
    C.WAITING_FOR_RESULT: {S.ACTIVE: (), **_ENDED},
    C.WAITING_FOR_CANCEL_ACK: {**_ENDED_WHILE_CANCELING, S.PENDING: (), S.ACTIVE: (),
                               S.REJECTED: (C.WAITING_FOR_RESULT,),
                               S.RECALLING: (C.RECALLING,),
                               S.RECALLED: (C.RECALLING, C.WAITING_FOR_RESULT)},
    C.RECALLING: {**_ENDED_WHILE_CANCELING, S.RECALLING: (),
                  S.REJECTED: (C.WAITING_FOR_RESULT,), S.RECALLED: (C.WAITING_FOR_RESULT,)},
    C.PREEMPTING: {S.PREEMPTING: (), S.PREEMPTED: (C.WAITING_FOR_RESULT,),
                   **_SUCCEEDED_OR_ABORTED_BY},
    C.DONE: dict(_ENDED),
}

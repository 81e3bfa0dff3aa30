"""ROS 2 actions as rcl_action keeps them, written once: the names and types of an action's
three services and two topics, the goal states and the moves between them, and the table of
goals a server keeps (each result kept RESULT_KEEP seconds after its goal ends, cancel requests
resolved as rcl_action resolves them, the status array published at each change).

The one action server (bus/action_server.py: the controllers', the sim's and, under its own
classes, rclpy's), rclpy's ActionClient and `launcher action` use it; ROS 1's actionlib keeps
its own states through the same kind of table (compat/nodes/actionlib/status.py)."""

from __future__ import annotations

import enum
import struct
import threading
import time
from typing import Any

from launcher.bus.wire import stamp_nanoseconds
from launcher.machines import StateMachine

# --- names (rcl_action's: `<action>/_action/<part>`, typed `<action type>_<Part>`) ------------
SEND_GOAL, CANCEL_GOAL, GET_RESULT = "send_goal", "cancel_goal", "get_result"
FEEDBACK, STATUS = "feedback", "status"
CANCEL_TYPE = "action_msgs/srv/CancelGoal"
STATUS_TYPE = "action_msgs/msg/GoalStatusArray"
GOAL_INFO_TYPE = "action_msgs/msg/GoalInfo"


def endpoint(action_name: str, part: str) -> str:
    return f"{action_name}/_action/{part}"


def send_goal_type(action_type: str) -> str:
    return f"{action_type}_SendGoal"


def get_result_type(action_type: str) -> str:
    return f"{action_type}_GetResult"


def feedback_type(action_type: str) -> str:
    return f"{action_type}_FeedbackMessage"


# --- goal states (action_msgs/msg/GoalStatus) and rcl_action's moves between them -------------
UNKNOWN, ACCEPTED, EXECUTING, CANCELING, SUCCEEDED, CANCELED, ABORTED = range(7)
STATE_NAMES = {UNKNOWN: "UNKNOWN", ACCEPTED: "ACCEPTED", EXECUTING: "EXECUTING",
               CANCELING: "CANCELING", SUCCEEDED: "SUCCEEDED", CANCELED: "CANCELED",
               ABORTED: "ABORTED"}
TERMINAL = (SUCCEEDED, CANCELED, ABORTED)
RESULT_KEEP = 900.0  # s a result is kept after its goal ends (rcl_action's default)

GoalEvent = enum.Enum("GoalEvent", "EXECUTE CANCEL_GOAL SUCCEED ABORT CANCELED")
TRANSITIONS = {
    (ACCEPTED, GoalEvent.EXECUTE): EXECUTING,
    (ACCEPTED, GoalEvent.CANCEL_GOAL): CANCELING,
    (EXECUTING, GoalEvent.CANCEL_GOAL): CANCELING,
    (EXECUTING, GoalEvent.SUCCEED): SUCCEEDED,
    (EXECUTING, GoalEvent.ABORT): ABORTED,
    (CANCELING, GoalEvent.SUCCEED): SUCCEEDED,
    (CANCELING, GoalEvent.ABORT): ABORTED,
    (CANCELING, GoalEvent.CANCELED): CANCELED,
}
GOAL_STATES = StateMachine(TRANSITIONS, STATE_NAMES)  # rcl_action's (machines.py)

# action_msgs/srv/CancelGoal's return codes
ERROR_NONE, ERROR_REJECTED, ERROR_UNKNOWN_GOAL_ID, ERROR_GOAL_TERMINATED = range(4)


def uuid_key(goal_id: Any) -> bytes:
    """A goal id (unique_identifier_msgs/UUID) as a dict key."""
    return bytes(goal_id.uuid)


def uuid_text(goal_id: Any) -> str:
    """A goal id as rclpy prints it in its logs."""
    return str(list(bytes(goal_id.uuid)))


class Goal:
    """One goal a server keeps: its id and stamp, its state, and, once it ended, its result
    response. `handle` is its user's own object (rclpy's ServerGoalHandle, a controller's)."""

    def __init__(self, goal_id: Any, stamp: Any, state: int = ACCEPTED,
                 handle: Any = None) -> None:
        self.goal_id, self.stamp, self.state, self.handle = goal_id, stamp, state, handle
        self.key = uuid_key(goal_id)
        self.ended_at: float | None = None
        self.response: Any = None  # the GetResult response, once the goal has ended
        self._status: tuple[int, bytes] | None = None

    @property
    def active(self) -> bool:
        return self.state not in TERMINAL

    @property
    def stamp_ns(self) -> int:
        return stamp_nanoseconds(self.stamp)

    def status_cdr(self) -> bytes:
        """Its entry of the status array, made again only when its state moves."""
        made = self._status
        if made is None or made[0] != self.state:
            made = self._status = (self.state, status_entry_cdr(
                self.key, self.stamp.sec, self.stamp.nanosec, self.state))
        return made[1]


class GoalTable:
    """The goals of one action server, safe from any thread. `publish_status(cdr)` is handed
    the status array at each change."""

    def __init__(self, publish_status: Any, keep: float = RESULT_KEEP) -> None:
        self.publish_status, self.keep = publish_status, keep
        self.lock = threading.RLock()
        self._goals: dict[bytes, Goal] = {}
        self._waiting: dict[bytes, list[Any]] = {}  # result requests of goals not ended

    def __contains__(self, key: bytes) -> bool:
        with self.lock:
            return key in self._goals

    def goals(self) -> list[Goal]:
        with self.lock:
            return list(self._goals.values())

    def add(self, goal: Goal) -> None:
        """Keep a goal just accepted (announce() says it, once its request is answered)."""
        with self.lock:
            self._goals[goal.key] = goal

    def move(self, goal: Goal, event: GoalEvent) -> None:
        """The goal's state after `event`; machines.InvalidTransition (with rcl_action's
        message) if the state machine has no such move."""
        with self.lock:
            new = goal.state = GOAL_STATES.move(goal.state, event)
            if new in TERMINAL:
                goal.ended_at = time.monotonic()
        self.announce()

    def finish(self, goal: Goal, response: Any) -> None:
        """The ended goal's result response: every request that waits for it is answered."""
        with self.lock:
            goal.response = response
            waiting = self._waiting.pop(goal.key, [])
        for reply in waiting:
            reply.send(response)

    def result_request(self, key: bytes, reply: Any, unknown: Any) -> bool:
        """Answer a result request now (an ended goal's response; `unknown()` for a goal not
        kept) or when the goal ends; False when the goal is not kept."""
        self.expire()
        with self.lock:
            goal = self._goals.get(key)
            if goal is not None and goal.response is None:
                self._waiting.setdefault(key, []).append(reply)
                return True
        reply.send(unknown() if goal is None else goal.response)
        return goal is not None

    def cancel_candidates(self, key: bytes, stamp_ns: int) -> tuple[int, list[Goal]]:
        """rcl_action's reading of a cancel request: a zero id and zero stamp name every goal;
        a zero id and a stamp, those accepted at or before it; an id, that goal (an error code
        if it is unknown or ended) and, with a stamp, those at or before it too. The goals come
        back with ERROR_NONE, or none with the error code."""
        self.expire()
        goals = self.goals()
        if any(key):
            named = [g for g in goals if g.key == key]
            if not named:
                return ERROR_UNKNOWN_GOAL_ID, []
            if not named[0].active:
                return ERROR_GOAL_TERMINATED, []
            return ERROR_NONE, named + ([g for g in goals if g.stamp_ns <= stamp_ns and
                                         g not in named] if stamp_ns else [])
        if stamp_ns:
            return ERROR_NONE, [g for g in goals if g.stamp_ns <= stamp_ns]
        return ERROR_NONE, goals

    def expire(self) -> None:
        """Forget goals whose results have been kept `keep` seconds."""
        now = time.monotonic()
        with self.lock:
            gone = [k for k, g in self._goals.items()
                    if g.ended_at is not None and now - g.ended_at > self.keep]
            for key in gone:
                del self._goals[key]
        if gone:
            self.announce()

    def announce(self) -> None:
        """The status array of every goal kept (ended ones until their results expire), as
        rcl_action publishes it."""
        with self.lock:
            entries = [g.status_cdr() for g in self._goals.values()]
        self.publish_status(status_array_join(entries))


# --- the status array, written directly (a server says every goal it keeps at each change) ---
_COUNT = struct.Struct("<I")
_ENTRY_TAIL = struct.Struct("<iIb")


def status_entry_cdr(uuid: bytes, sec: int, nanosec: int, status: int) -> bytes:
    """One GoalStatus as it sits in a GoalStatusArray after the first entry (every entry
    but the first starts 1 past a multiple of 4, so its stamp is padded by 3)."""
    return uuid + b"\x00\x00\x00" + _ENTRY_TAIL.pack(sec, nanosec, status)


def status_array_join(entries: list[bytes]) -> bytes:
    """action_msgs/GoalStatusArray's CDR (little endian) from status_entry_cdr's entries
    (rcl writes it in C; made here often, and it grows with the goals kept)."""
    if not entries:
        return b"\x00\x01\x00\x00" + _COUNT.pack(0)
    first = entries[0]
    return b"".join((b"\x00\x01\x00\x00", _COUNT.pack(len(entries)), first[:16], first[19:],
                     *entries[1:]))


def status_array_cdr(entries: list[tuple[bytes, int, int, int]]) -> bytes:
    """The same from (uuid, sec, nanosec, status) entries."""
    return status_array_join([status_entry_cdr(*e) for e in entries])


def statuses(payload: bytes) -> list[tuple[bytes, int]]:
    """(goal uuid, status) of each entry of a GoalStatusArray's CDR (little or big endian):
    uuid[16], stamp (int32, uint32, aligned to 4), status int8."""
    big = payload[1] == 0
    count = int.from_bytes(payload[4:8], "big" if big else "little")
    found, at = [], 8
    for _ in range(count):
        uuid = payload[at:at + 16]
        at += 16
        at += -(at - 4) % 4
        found.append((bytes(uuid), payload[at + 8]))
        at += 9
    return found

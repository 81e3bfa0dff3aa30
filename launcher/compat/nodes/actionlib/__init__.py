"""actionlib for rospy (ROS 1), on the ROS 1 action layout: the topics `<ns>/goal`,
`<ns>/cancel`, `<ns>/status`, `<ns>/feedback` and `<ns>/result`, typed as genaction makes an
action's messages (`FibonacciActionGoal`, …, actionlib_msgs' GoalID and GoalStatusArray).
ActionServer and ActionClient follow each goal through its handle (ServerGoalHandle,
ClientGoalHandle); SimpleActionServer and SimpleActionClient are built on them as actionlib
builds them: one goal at a time, a new goal preempting the one running."""

from actionlib.action_client import (
    INVALID_TRANSITION,
    NO_TRANSITION,
    ActionClient,
    ClientGoalHandle,
    CommState,
    CommStateMachine,
    GoalManager,
    TerminalState,
    g_goal_id,
    get_name_of_constant,
)
from actionlib.action_server import (
    ActionServer,
    HandleTrackerDeleter,
    ServerGoalHandle,
    StatusTracker,
    nop_cb,
)
from actionlib.exceptions import ActionException
from actionlib.goal_id_generator import GoalIDGenerator
from actionlib.simple_action_client import SimpleActionClient, SimpleGoalState
from actionlib.simple_action_server import SimpleActionServer

__all__ = ["INVALID_TRANSITION", "NO_TRANSITION", "ActionClient", "ActionException",
           "ActionServer", "ClientGoalHandle", "CommState", "CommStateMachine",
           "GoalIDGenerator", "GoalManager", "HandleTrackerDeleter", "ServerGoalHandle",
           "SimpleActionClient", "SimpleActionServer", "SimpleGoalState", "StatusTracker",
           "TerminalState", "g_goal_id", "get_name_of_constant", "nop_cb"]

"""actionlib for rospy (ROS 1), on the ROS 1 action layout: the topics `<ns>/goal`,
`<ns>/cancel`, `<ns>/status`, `<ns>/feedback` and `<ns>/result`, typed as genaction makes an
action's messages (`FibonacciActionGoal`, …, actionlib_msgs' GoalID and GoalStatusArray).
SimpleActionServer and SimpleActionClient behave as actionlib's: one goal at a time, a new
goal preempting the one running."""

from actionlib.action_client import (
    INVALID_TRANSITION,
    NO_TRANSITION,
    CommState,
    TerminalState,
    g_goal_id,
    get_name_of_constant,
)
from actionlib.action_server import nop_cb
from actionlib.exceptions import ActionException
from actionlib.goal_id_generator import GoalIDGenerator
from actionlib.simple_action_client import SimpleActionClient, SimpleGoalState
from actionlib.simple_action_server import SimpleActionServer

__all__ = ["INVALID_TRANSITION", "NO_TRANSITION", "ActionException", "CommState",
           "GoalIDGenerator", "SimpleActionClient", "SimpleActionServer", "SimpleGoalState",
           "TerminalState", "g_goal_id", "get_name_of_constant", "nop_cb"]

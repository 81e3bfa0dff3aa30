"""actionlib for rospy (ROS 1), on the ROS 1 action layout: the topics `<ns>/goal`,
`<ns>/cancel`, `<ns>/status`, `<ns>/feedback` and `<ns>/result`, typed as genaction makes an
action's messages (`FibonacciActionGoal`, …, actionlib_msgs' GoalID and GoalStatusArray).
SimpleActionServer and SimpleActionClient behave as actionlib's: one goal at a time, a new
goal preempting the one running."""

from actionlib.simple_action_client import SimpleActionClient, SimpleGoalState
from actionlib.simple_action_server import SimpleActionServer

__all__ = ["SimpleActionClient", "SimpleActionServer", "SimpleGoalState"]
